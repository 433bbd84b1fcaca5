#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/automation/script.h"
#include "app/drawing/png_dpi.h"
#include "app/drawing/slide_layout.h"
#include "optics/film_point_bundle.h"
#include "optics/lens_loader.h"
#include "optics/ray_fan.h"

namespace lenslab::app {
namespace {

TEST(SlideLayout, ScaleBarsHaveRoundLengths) {
  EXPECT_DOUBLE_EQ(roundScaleBarLengthMm(7.3), 5.0);
  EXPECT_DOUBLE_EQ(roundScaleBarLengthMm(10.0), 10.0);
  EXPECT_DOUBLE_EQ(roundScaleBarLengthMm(19.99), 10.0);
  EXPECT_DOUBLE_EQ(roundScaleBarLengthMm(20.0), 20.0);
  EXPECT_DOUBLE_EQ(roundScaleBarLengthMm(0.34), 0.2);
  EXPECT_DOUBLE_EQ(roundScaleBarLengthMm(999.0), 500.0);
  EXPECT_EQ(roundScaleBarLengthMm(0.0), 0.0);
  EXPECT_EQ(scaleBarLabel(0.5), "0.5 mm");
  EXPECT_EQ(scaleBarLabel(20.0), "20 mm");
}

TEST(PngDpi, CrcAndPixelsPerMetre) {
  // Every PNG ends with an IEND chunk whose CRC is AE 42 60 82.
  const std::string iend = "IEND";
  EXPECT_EQ(pngCrc32({reinterpret_cast<const std::uint8_t*>(iend.data()), iend.size()}),
            0xAE426082u);
  EXPECT_EQ(pixelsPerMetre(300.0), 11811u);  // 300 / 0.0254
  EXPECT_EQ(pixelsPerMetre(72.0), 2835u);
}

TEST(ScriptParse, ExportCrossSectionArguments) {
  const ParsedScript good = parseScript(
      "export-cross-section a.png\nexport-cross-section a.svg 800x600\n"
      "export-cross-section a.png 1600x900 300 dark\nexport-cross-section a.png light 72\n",
      "t");
  EXPECT_TRUE(good.diagnostics.empty()) << good.diagnostics.formatAll();
  const auto request = parseExportArguments({"1600x900", "300", "dark"});
  ASSERT_TRUE(request);
  EXPECT_EQ(request->widthPx, 1600);
  EXPECT_EQ(request->heightPx, 900);
  EXPECT_EQ(request->dotsPerInch, 300.0);
  EXPECT_EQ(request->dark, true);
  const ParsedScript bad = parseScript(
      "export-cross-section a.jpg\nexport-cross-section a.png 16x\n"
      "export-cross-section a.png 300 72\nexport-cross-section a.png grey\n",
      "t");
  ASSERT_EQ(bad.diagnostics.all().size(), 4u) << bad.diagnostics.formatAll();
  EXPECT_EQ(bad.diagnostics.all()[1].format().rfind("t:2:28: error: '16x' is not a size", 0), 0u)
      << bad.diagnostics.all()[1].format();
}

// Text about as wide as DejaVu Sans's: 0.6 of the size per character.
SlideTextMetrics approximateMetrics() {
  SlideTextMetrics metrics;
  metrics.widthPx = [](const std::string& text, double sizePx) {
    return 0.6 * sizePx * static_cast<double>(text.size());
  };
  return metrics;
}

bool overlap(const SlideText& a, const SlideText& b) {
  return a.leftPx < b.right() && b.leftPx < a.right() && a.topPx < b.bottom() &&
         b.topPx < a.bottom();
}

TEST(SlideLayout, EveryLensIsLabelledWithTextInsideThePictureAndNoTwoTextsOverlap) {
  const std::filesystem::path lenses = std::filesystem::path(LENSLAB_SOURCE_DIR) / "lenses";
  for (const auto& entry : std::filesystem::directory_iterator(lenses)) {
    const optics::LoadedLens loaded = optics::loadLens(entry.path());
    ASSERT_TRUE(loaded.ok()) << entry.path();
    const optics::LensOutline outline = optics::computeLensOutline(loaded.file.prescription);
    CrossSectionDrawing drawing = drawLens(outline, 21.6);
    BoundsMm fit = drawing.bounds;
    fit.include({outline.frontVertexZMm + 0.25 * (fit.maxZ - fit.minZ), 0.0});
    optics::FanSpec spec;
    spec.filmHalfDiagonalMm = 21.6;
    const optics::RayFans fans = optics::computeRayFans(*loaded.system, spec);
    drawRayFans(drawing, fans, true);
    SlideCaption caption{"A lens with a long name, as its file's first comment gives it",
                         "lens.dat  ·  f/2.0302  ·  EFL 50.36 mm  ·  object at infinity",
                         {{0, "0°"}, {1, "16.7°"}, {2, "23.3°"}},
                         {},
                         std::nullopt};
    for (const auto& [width, height] : {std::pair{1920, 1080}, {1024, 768}, {800, 1200}}) {
      SlideOptions options;
      options.widthPx = width;
      options.heightPx = height;
      const SlidePicture picture =
          layoutSlide(drawing, outline, fit, caption, options, approximateMetrics());
      const std::string where = entry.path().filename().string() + " at " + std::to_string(width) +
                                "x" + std::to_string(height);
      std::size_t numbers = 0;
      for (std::size_t i = 0; i < picture.texts.size(); ++i) {
        const SlideText& text = picture.texts[i];
        numbers += text.kind == "surface-number";
        EXPECT_GE(text.leftPx, 0.0) << where << ": " << text.text;
        EXPECT_GE(text.topPx, 0.0) << where << ": " << text.text;
        EXPECT_LE(text.right(), width) << where << ": " << text.text;
        EXPECT_LE(text.bottom(), height) << where << ": " << text.text;
        for (std::size_t k = 0; k < i; ++k) {
          EXPECT_FALSE(overlap(text, picture.texts[k]))
              << where << ": '" << text.text << "' covers '" << picture.texts[k].text << "'";
        }
      }
      EXPECT_EQ(numbers, loaded.file.prescription.surfaces.size()) << where;
      EXPECT_GT(picture.scaleBarMm, 0.0) << where;
    }
  }
}

bool sameColour(Colour a, Colour b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

TEST(SlideLayout, AFilmPointsBundleIsDrawnInItsRimsColoursUnderItsSharesLegend) {
  // Issue 38: the slide drew a film point's bundle in the first field's colour with the fans'
  // legend. Each ray takes its stopping rim's colour (the passing ones the bundle's), and the
  // legend gives each share in that colour, in both themes.
  const optics::LoadedLens loaded =
      optics::loadLens(std::filesystem::path(LENSLAB_SOURCE_DIR) / "lenses/dgauss-50mm.dat");
  ASSERT_TRUE(loaded.ok());
  const optics::LensOutline outline = optics::computeLensOutline(loaded.file.prescription);
  const optics::FilmPointBundle bundle = optics::traceFilmPointBundle(*loaded.system, 18.0);
  ASSERT_GE(bundle.blocked.size(), 2u);
  CrossSectionDrawing drawing = drawLens(outline, 21.6);
  drawFilmPointBundle(drawing, bundle);
  SlideCaption caption;
  caption.title = "Double-Gauss 50 mm, 22 degree half field";
  caption.fields = {{0, "0°"}};  // ignored: the bundle replaces the fans' legend
  caption.bundle = SlideBundleLegend{
      "Film point 18.0 mm:",
      bundleLegend(bundle, loaded.file.prescription.surfaces.size(), loaded.system->stopIndex())};
  for (const SlideTheme theme : {SlideTheme::Light, SlideTheme::Dark}) {
    SlideOptions options;
    options.theme = theme;
    const SlidePalette colours = slidePalette(theme);
    const SlidePicture picture =
        layoutSlide(drawing, outline, drawing.bounds, caption, options, approximateMetrics());
    std::vector<const SlideText*> shares;
    for (const SlideText& text : picture.texts) {
      EXPECT_NE(text.kind, "legend-field") << text.text;
      EXPECT_NE(text.text, "marginal ray");
      if (text.kind == "legend-share") shares.push_back(&text);
    }
    ASSERT_EQ(shares.size(), 1 + bundle.blocked.size());
    std::size_t anyStopped = 0;
    EXPECT_EQ(shares[0]->text.rfind("reaches it ", 0), 0u);
    EXPECT_TRUE(sameColour(shares[0]->colour, colours.bundlePassing));
    for (std::size_t i = 0; i < bundle.blocked.size(); ++i) {
      const int surface = bundle.blocked[i].surface;
      EXPECT_EQ(shares[i + 1]->text.rfind("surface " + std::to_string(surface + 1), 0), 0u)
          << shares[i + 1]->text;
      const Colour colour = colours.stoppingSurfaceColour(surface);
      EXPECT_TRUE(sameColour(shares[i + 1]->colour, colour)) << shares[i + 1]->text;
      // Rays in that colour: as many as the bundle has rays stopped there.
      std::size_t stopped = 0, drawn = 0;
      for (const optics::FanRay& ray : bundle.rays)
        stopped += !ray.filmPoint && ray.path.stopSurface == surface;
      for (const SlideLine& line : picture.lines)
        drawn += line.group == "rays" && sameColour(line.colour, colour);
      EXPECT_GE(drawn, stopped) << shares[i + 1]->text;
      anyStopped += stopped;
    }
    EXPECT_GT(anyStopped, 0u);
  }
}

}  // namespace
}  // namespace lenslab::app
