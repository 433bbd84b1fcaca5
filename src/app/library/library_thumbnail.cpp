#include "app/library/library_thumbnail.h"

#include <stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <system_error>

#include "app/drawing/cross_section_drawing.h"
#include "app/drawing/png_dpi.h"
#include "optics/lens_outline.h"
#include "optics/ray_fan.h"

namespace lenslab::app {

SlideImage drawLibraryThumbnail(const optics::LensSystem& system, double filmHalfDiagonalMm,
                                int widthPx, int heightPx, const SlideFont& font) {
  const optics::LensOutline outline = optics::computeLensOutline(system.prescription());
  CrossSectionDrawing drawing = drawLens(outline, filmHalfDiagonalMm);
  optics::FanSpec spec;
  // Fewer rays than the panel's 13: at thumbnail size more blur into a solid fill.
  spec.raysPerFan = 7;
  spec.filmHalfDiagonalMm = filmHalfDiagonalMm;
  const optics::RayFans fans = optics::computeRayFans(system, spec);
  const BoundsMm fit = crossSectionFitBounds(drawing, outline, fans);
  // Blocked rays would be as many lines again for what the rims stop: left out at this size.
  drawRayFans(drawing, fans, /*showBlocked=*/false);
  SlideOptions options;
  options.widthPx = widthPx;
  options.heightPx = heightPx;
  options.theme = SlideTheme::Dark;
  options.title = options.surfaceNumbers = options.stopAndFilm = false;
  options.scaleBar = options.legend = false;
  const SlidePicture picture = layoutSlide(drawing, outline, fit, {}, options, font.metrics());
  return rasterizeSlide(picture, font);
}

std::filesystem::path thumbnailCacheDirectory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0')
    return std::filesystem::path(xdg) / "lenslab" / "thumbnails";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return std::filesystem::path(home) / ".cache" / "lenslab" / "thumbnails";
  return {};
}

std::filesystem::path thumbnailCachePath(const std::filesystem::path& directory,
                                         std::uint64_t contentHash, int widthPx, int heightPx) {
  char name[96];
  std::snprintf(name, sizeof name, "%016llx-%dx%d-v%d.png",
                static_cast<unsigned long long>(contentHash), widthPx, heightPx,
                kThumbnailStyleVersion);
  return directory / name;
}

std::optional<SlideImage> readCachedThumbnail(const std::filesystem::path& path, int widthPx,
                                              int heightPx) {
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
  if (!pixels || width != widthPx || height != heightPx) return std::nullopt;
  SlideImage image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(width) * height * 4);
  return image;
}

std::string writeCachedThumbnail(const std::filesystem::path& path, const SlideImage& image) {
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error) return "cannot create " + path.parent_path().string() + ": " + error.message();
  return writePngWithDpi(path, image.width, image.height, image.rgba, 96.0);
}

}  // namespace lenslab::app
