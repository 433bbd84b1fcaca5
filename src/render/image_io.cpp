#include "render/image_io.h"

#include <stb_image_write.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace lenslab::render {

namespace {

// A temporary name in the target's directory, so the final rename stays on one filesystem.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += ".tmp-lenslab";
  return temporary;
}

WriteResult renameIntoPlace(const std::filesystem::path& temporary,
                            const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return {false, "cannot write " + path.string() + ": " + error.message()};
  }
  return {true, {}};
}

}  // namespace

WriteResult writePngRgba8(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgba) {
  if (width <= 0 || height <= 0 ||
      rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    return {false, "cannot write " + path.string() + ": image size does not match its pixels"};
  }
  const std::filesystem::path temporary = temporaryPathFor(path);
  errno = 0;
  if (stbi_write_png(temporary.c_str(), width, height, 4, rgba.data(), width * 4) == 0) {
    const int savedErrno = errno;
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return {false, "cannot write " + path.string() + ": " +
                       (savedErrno != 0 ? std::strerror(savedErrno) : "PNG encoder failed")};
  }
  return renameIntoPlace(temporary, path);
}

std::filesystem::path nonClobberingPath(const std::filesystem::path& directory,
                                        const std::string& stem, const std::string& extension) {
  std::filesystem::path candidate = directory / (stem + extension);
  for (int suffix = 2; std::filesystem::exists(candidate); ++suffix) {
    candidate = directory / (stem + "-" + std::to_string(suffix) + extension);
  }
  return candidate;
}

}  // namespace lenslab::render
