// Reading an aperture image (aperture_shape.h): decoded by stb_image (Debian's libstb), averaged
// over its colour channels as pbrt-v4 does, and thresholded at half of white.

#include <stb_image.h>

#include <memory>
#include <system_error>

#include "optics/aperture_shape.h"

namespace lenslab::optics {

std::shared_ptr<const ApertureMask> loadApertureMask(const std::filesystem::path& path,
                                                     std::string* error) {
  auto fail = [&](std::string message) -> std::shared_ptr<const ApertureMask> {
    if (error) *error = path.string() + ": " + std::move(message);
    return nullptr;
  };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return fail("aperture image not found");
  if (std::filesystem::is_directory(path, ec)) return fail("is a directory, not an image");
  int width = 0, height = 0, channels = 0;
  // Grey and grey+alpha stay one channel of colour; RGB(A) average their three colours.
  stbi_uc* pixels = stbi_load(path.c_str(), &width, &height, &channels, 0);
  if (!pixels) {
    const char* why = stbi_failure_reason();
    return fail(std::string("cannot read the aperture image (") + (why ? why : "unknown") + ")");
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> owned(pixels, stbi_image_free);
  if (width != height)
    return fail("the aperture image must be square (it is " + std::to_string(width) + "x" +
                std::to_string(height) + ")");
  auto mask = std::make_shared<ApertureMask>();
  mask->sizePx = width;
  mask->source = path;
  mask->open.resize(static_cast<std::size_t>(width) * height);
  const int colours = channels >= 3 ? 3 : 1;
  bool anyOpen = false;
  for (std::size_t i = 0; i < mask->open.size(); ++i) {
    int sum = 0;
    for (int c = 0; c < colours; ++c) sum += pixels[i * channels + c];
    const bool open = 2 * sum >= 255 * colours;
    mask->open[i] = open ? 1 : 0;
    anyOpen = anyOpen || open;
  }
  if (!anyOpen) return fail("the aperture image is all black: no light would pass");
  mask->finish();
  return mask;
}

}  // namespace lenslab::optics
