#include "render/image_io.h"

#include <stb_image_write.h>

#include <string>
#include <system_error>

#include "common/atomic_file.h"

namespace lenslab::render {

WriteResult writePngRgba8(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgba) {
  if (width <= 0 || height <= 0 ||
      rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    return {false, "cannot write " + path.string() + ": image size does not match its pixels"};
  }
  // Encoded in memory and written by writeFileAtomically: stbi_write_png's own file writer does
  // not check fwrite, so a full disk would leave a truncated PNG that the rename then puts in
  // place of the old file.
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4) == 0) {
    return {false, "cannot write " + path.string() + ": the PNG encoder failed"};
  }
  const std::string error = writeFileAtomically(path, png);
  return {error.empty(), error};
}

std::filesystem::path nonClobberingPath(const std::filesystem::path& directory,
                                        const std::string& stem, const std::string& extension) {
  std::filesystem::path candidate = directory / (stem + extension);
  std::error_code error;  // an unreadable directory ends the search: the name is then free enough
  for (int suffix = 2; std::filesystem::exists(candidate, error); ++suffix) {
    candidate = directory / (stem + "-" + std::to_string(suffix) + extension);
  }
  return candidate;
}

}  // namespace lenslab::render
