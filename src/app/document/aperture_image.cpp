#include "app/document/aperture_image.h"

#include <filesystem>

namespace lenslab::app {

std::optional<optics::ApertureShape> loadImageAperture(const std::string& path,
                                                       std::string* error) {
  // Absolute, so that the lens file saved anywhere finds it again.
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec).lexically_normal();
  auto mask = optics::loadApertureMask(ec ? std::filesystem::path(path) : absolute, error);
  if (!mask) return std::nullopt;
  optics::ApertureShape shape;
  shape.kind = optics::ApertureShape::Kind::Image;
  shape.imageName = (ec ? std::filesystem::path(path) : absolute).string();
  shape.mask = std::move(mask);
  return shape;
}

}  // namespace lenslab::app
