#pragma once
// Writing images to disk. Every writer is atomic: it writes a temporary file beside the target
// and renames it into place, so a failed or interrupted write never leaves a partial file.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace lenslab::render {

struct WriteResult {
  bool ok = false;
  std::string error;  // what went wrong, naming the path, when !ok
};

// 8-bit RGBA, rows top to bottom, width * height * 4 bytes.
WriteResult writePngRgba8(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgba);

// Picks "stem.ext", then "stem-2.ext", "stem-3.ext", ... : the first name that does not exist
// yet in `directory`, so saving never clobbers an earlier file.
std::filesystem::path nonClobberingPath(const std::filesystem::path& directory,
                                        const std::string& stem, const std::string& extension);

}  // namespace lenslab::render
