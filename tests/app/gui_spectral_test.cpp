// Spectral rendering in the real spectralViewer (issue 23): the preview's Spectral choice and `set
// spectral`, on the default scene through the flint landscape lens (V_d 23.78). Spectral, the
// lens's colour shows: the picture's outer part, where the lateral colour grows, turns colourful
// at the chart's and posts' edges; in RGB the same scene stays grey there.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::string spectralViewer(const std::filesystem::path& scratch, const std::string& arguments) {
  return "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY + "' " + arguments;
}

nlohmann::json readSpectralJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Mean chroma (largest minus smallest channel, as shown) over the columns [x0, x1) of the rows
// [y0, y1).
double meanChroma(const testing::PngImage& shot, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  int n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x, ++n) {
      const testing::Rgb c = shot.at(x, y);
      sum += std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
    }
  }
  return n > 0 ? sum / n : 0.0;
}

TEST(SpectralPreview, TheFlintLensShowsColourOnlyWhenSpectral) {
  const auto scratch = testing::makeTestDirectory("spectral-preview");
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/flint-landscape-50mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "set spectral off\n"
                                                "wait-spp 64\n"
                                                "wait-frames 2\n"
                                                "screenshot rgb.png\n"
                                                "dump-ui rgb.json\n"
                                                "set spectral auto\n"
                                                "wait-spp 64\n"
                                                "wait-frames 2\n"
                                                "screenshot spectral.png\n"
                                                "dump-ui spectral.json\n"
                                                "quit\n";
  const auto run = testing::runProcess(
      spectralViewer(scratch, "--size 1400x900 --script commands.script"), scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json rgbUi = readSpectralJson(scratch / "rgb.json");
  const nlohmann::json spectralUi = readSpectralJson(scratch / "spectral.json");
  EXPECT_EQ(rgbUi["state"]["spectral"], "off");
  EXPECT_EQ(spectralUi["state"]["spectral"], "auto");
  ASSERT_TRUE(spectralUi["widgets"].contains("preview/spectral"));

  const auto rgb = testing::PngImage::load(scratch / "rgb.png");
  const auto spectral = testing::PngImage::load(scratch / "spectral.png");
  ASSERT_TRUE(rgb.valid() && spectral.valid());
  const auto& box = spectralUi["widgets"]["preview/image"];
  const int x0 = box["x"].get<int>(), y0 = box["y"].get<int>();
  const int w = box["width"].get<int>(), h = box["height"].get<int>();
  ASSERT_GT(w, 100);
  ASSERT_GT(h, 60);
  // The outer fifth on each side (where the fringes are), and the picture is not black.
  const double rgbOuter = meanChroma(rgb, x0, x0 + w / 5, y0, y0 + h) +
                          meanChroma(rgb, x0 + 4 * w / 5, x0 + w, y0, y0 + h);
  const double spectralOuter = meanChroma(spectral, x0, x0 + w / 5, y0, y0 + h) +
                               meanChroma(spectral, x0 + 4 * w / 5, x0 + w, y0, y0 + h);
  double brightness = 0.0;
  for (int y = y0; y < y0 + h; y += 4)
    for (int x = x0; x < x0 + w; x += 4) brightness += spectral.at(x, y).brightness();
  brightness /= (h / 4) * (w / 4);
  std::printf("outer chroma: rgb %.2f, spectral %.2f; mean brightness %.1f\n", rgbOuter,
              spectralOuter, brightness);
  EXPECT_GT(brightness, 40.0);
  EXPECT_GT(spectralOuter, rgbOuter + 4.0);
}

}  // namespace
}  // namespace lenslab
