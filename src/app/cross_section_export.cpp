#include "app/cross_section_export.h"

#include <cmath>
#include <cstdio>

#include "app/drawing/png_dpi.h"
#include "app/drawing/slide_raster.h"
#include "app/drawing/slide_svg.h"
#include "app/lens_caption.h"
#include "app/viewer_state.h"
#include "common/atomic_file.h"
#include "common/distance_text.h"
#include "optics/glass.h"

namespace lenslab::app {

std::string checkExportSettings(const CrossSectionExportSettings& settings) {
  const SlideOptions& slide = settings.slide;
  const auto sideOk = [](int side) { return side >= kMinExportSidePx && side <= kMaxExportSidePx; };
  if (!sideOk(slide.widthPx) || !sideOk(slide.heightPx)) {
    return "the size " + std::to_string(slide.widthPx) + "x" + std::to_string(slide.heightPx) +
           " is not between " + std::to_string(kMinExportSidePx) + " and " +
           std::to_string(kMaxExportSidePx) + " pixels a side";
  }
  if (static_cast<double>(slide.widthPx) * slide.heightPx > kMaxExportPixels) {
    return "the size " + std::to_string(slide.widthPx) + "x" + std::to_string(slide.heightPx) +
           " has more than 50 million pixels";
  }
  if (!(settings.dotsPerInch >= 1.0 && settings.dotsPerInch <= 10000.0)) {
    return "the resolution is not between 1 and 10000 DPI";
  }
  return {};
}

std::string fieldAngleText(double degrees) {
  if (std::abs(degrees) < 0.05) return "0°";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f°", degrees);
  return text;
}

SlideCaption crossSectionCaption(ViewerState& state) {
  SlideCaption caption;
  caption.title = lensName(state);
  std::string subtitle;
  const auto add = [&](const std::string& part) {
    subtitle += (subtitle.empty() ? "" : "  ·  ") + part;
  };
  if (const std::string& path = state.lens.document().path(); !path.empty()) {
    add(std::filesystem::path(path).filename().string());
  }
  if (const std::string source = lensSource(state); !source.empty()) add(source);
  if (state.lensSystem) {
    const optics::FirstOrderData& firstOrder = state.lensSystem->firstOrder();
    // As the first-order section writes it (and the plots' exports): EFL over the paraxial beam
    // that passes every clear aperture.
    add(lensFNumberText(state));
    if (!firstOrder.afocal) {
      char text[64];
      std::snprintf(text, sizeof text, "EFL %.2f mm", firstOrder.eflMm);
      add(text);
    }
  }
  const bool atInfinity = state.fanSettings.objectAtInfinity;
  add(atInfinity ? std::string("object at infinity")
                 : "object " + distanceText(state.fanSettings.objectDistanceMm) + " from the film");
  if (const optics::FilmPointBundle* bundle = filmPointBundle(state)) {
    // The bundle is drawn instead of the fans: the legend gives its shares, as the panel's.
    char text[96];
    std::snprintf(text, sizeof text, "bundle of the film point %.1f mm", bundle->imageHeightMm);
    add(text);
    caption.subtitle = subtitle;
    std::snprintf(text, sizeof text,
                  "Film point %.1f mm, of the light the iris admits:", bundle->imageHeightMm);
    caption.bundle = SlideBundleLegend{
        text,
        bundleLegend(*bundle, state.lensSystem->surfaces().size(), state.lensSystem->stopIndex())};
    return caption;
  }
  caption.subtitle = subtitle;
  for (std::size_t i = 0; i < state.rayFans.fans.size(); ++i) {
    const optics::RayFan& fan = state.rayFans.fans[i];
    std::string text;
    if (atInfinity) {
      text = fieldAngleText(fan.fieldAngleDeg);
    } else {
      char height[48];
      std::snprintf(height, sizeof height, "%.1f mm high", fan.objectHeightMm);
      text = height;
    }
    caption.fields.push_back({static_cast<int>(i), text});
  }
  if (!state.rayFans.fans.empty() && !state.rayFans.fans.front().atOtherWavelengths.empty()) {
    caption.lines = {{optics::kWavelengthFNm, "F 486 nm"},
                     {state.rayFans.wavelengthNm, "d 588 nm"},
                     {optics::kWavelengthCNm, "C 656 nm"}};
  }
  return caption;
}

std::variant<CrossSectionExportJob, std::string> prepareCrossSectionExport(
    ViewerState& state, const std::filesystem::path& path,
    const CrossSectionExportSettings& settings) {
  const std::string extension = path.extension().string();
  if (extension != ".svg" && extension != ".png") {
    return "cannot export the cross-section to " + path.string() +
           ": the file name must end in .png or .svg";
  }
  if (const std::string problem = checkExportSettings(settings); !problem.empty()) {
    return "cannot export the cross-section to " + path.string() + ": " + problem;
  }
  if (!state.lensSystemIsCurrent) {
    return "cannot export the cross-section to " + path.string() +
           ": the lens is invalid (see the lens table)";
  }
  const CrossSectionCache& shown = crossSection(state);
  return CrossSectionExportJob{path,          settings,        shown.drawing,
                               shown.outline, shown.fitBounds, crossSectionCaption(state)};
}

CrossSectionExportResult runCrossSectionExport(const CrossSectionExportJob& job) {
  const SlideFont font;
  const SlidePicture picture = layoutSlide(job.drawing, job.outline, job.fit, job.caption,
                                           job.settings.slide, font.metrics());
  const bool svg = job.path.extension() == ".svg";
  CrossSectionExportResult result;
  if (svg) {
    result.error = writeFileAtomically(job.path, slideSvg(picture, job.caption.title));
  } else {
    const SlideImage image = rasterizeSlide(picture, font);
    result.error =
        writePngWithDpi(job.path, image.width, image.height, image.rgba, job.settings.dotsPerInch);
  }
  if (!result.error.empty()) return result;
  char text[160];
  const char* theme = job.settings.slide.theme == SlideTheme::Light ? "light" : "dark";
  if (svg) {
    std::snprintf(text, sizeof text, "SVG, %d×%d px, %s theme", picture.widthPx, picture.heightPx,
                  theme);
  } else {
    std::snprintf(text, sizeof text, "PNG, %d×%d px, %g DPI, %s theme", picture.widthPx,
                  picture.heightPx, job.settings.dotsPerInch, theme);
  }
  result.summary = text;
  return result;
}

}  // namespace lenslab::app
