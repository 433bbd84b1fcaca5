// Aperture shapes in the real viewer: "set aperture" by script is an undoable edit; the
// cross-section draws the iris face-on above the stop, the film point's footprint draws the
// blades instead of the circle; a bad image is logged and the stop keeps its shape.

#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <vector>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

struct ApertureBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

ApertureBox apertureWidget(const nlohmann::json& ui, const std::string& name) {
  const auto& w = ui["widgets"][name];
  const int x = w["x"].get<int>(), y = w["y"].get<int>();
  return {x, y, x + w["width"].get<int>(), y + w["height"].get<int>()};
}

nlohmann::json readApertureJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

const testing::Rgb kStopYellow{235, 200, 80};

bool yellowNear(const testing::PngImage& shot, double x, double y) {
  const int ix = static_cast<int>(std::lround(x)), iy = static_cast<int>(std::lround(y));
  return shot.fractionNear(ix - 2, iy - 2, ix + 3, iy + 3, kStopYellow, 60) > 0.0;
}

bool logHas(const nlohmann::json& ui, const std::string& level, const std::string& text) {
  for (const auto& entry : ui["state"]["log"])
    if (entry["level"] == level && entry["text"].get<std::string>().find(text) != std::string::npos)
      return true;
  return false;
}

TEST(ApertureGui, SixBladesByScriptShowInTheCrossSectionAndTheFootprint) {
  const auto scratch = testing::makeTestDirectory("gui-aperture");
  {
    std::vector<unsigned char> wide(8 * 4, 255);
    ASSERT_NE(stbi_write_png((scratch / "wide.png").c_str(), 8, 4, 1, wide.data(), 8), 0);
  }
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  std::ofstream(scratch / "commands.script") << "load-lens " << lens << "\n"
                                             << "show-panel illumination\n"
                                                "set layout 0.3 0.35 0.5\n"  // a tall footprint
                                                "set film-point 2\n"
                                                "wait-frames 2\n"
                                                "screenshot round.png\n"
                                                "dump-ui round.json\n"
                                                "set aperture image missing.png\n"
                                                "set aperture image wide.png\n"
                                                "wait-frames 2\n"
                                                "dump-ui bad.json\n"
                                                "set aperture blades 6 rotation 0\n"
                                                "wait-frames 2\n"
                                                "screenshot hexagon.png\n"
                                                "dump-ui hexagon.json\n"
                                                "undo\n"
                                                "wait-frames 2\n"
                                                "dump-ui undone.json\n"
                                                "quit\n";
  const auto run = testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                           "' --size 1400x900 --script commands.script",
                                       scratch);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const nlohmann::json round = readApertureJson(scratch / "round.json");
  const nlohmann::json bad = readApertureJson(scratch / "bad.json");
  const nlohmann::json hexagon = readApertureJson(scratch / "hexagon.json");
  const nlohmann::json undone = readApertureJson(scratch / "undone.json");
  EXPECT_EQ(round["state"]["aperture"], "circle");
  // Bad images: logged, and the stop stays the circle.
  EXPECT_EQ(bad["state"]["aperture"], "circle");
  EXPECT_TRUE(logHas(bad, "error", "missing.png: aperture image not found")) << bad["state"]["log"];
  EXPECT_TRUE(logHas(bad, "error", "must be square (it is 8x4)")) << bad["state"]["log"];
  EXPECT_EQ(hexagon["state"]["aperture"], "blades 6 curvature 0 rotation 0");
  EXPECT_EQ(hexagon["state"]["lens_modified"], true);
  EXPECT_EQ(undone["state"]["aperture"], "circle");  // one undo step

  const auto roundShot = testing::PngImage::load(scratch / "round.png");
  const auto hexagonShot = testing::PngImage::load(scratch / "hexagon.png");
  ASSERT_TRUE(roundShot.valid() && hexagonShot.valid());
  // The cross-section: the iris drawn face-on above the stop adds the stop's yellow.
  const ApertureBox canvas = apertureWidget(hexagon, "cross-section/canvas");
  const double yellowRound =
      roundShot.fractionNear(canvas.x0, canvas.y0, canvas.x1, canvas.y1, kStopYellow, 40);
  const double yellowHexagon =
      hexagonShot.fractionNear(canvas.x0, canvas.y0, canvas.x1, canvas.y1, kStopYellow, 40);
  std::printf("stop-yellow share of the cross-section: circle %.4f, 6 blades %.4f\n", yellowRound,
              yellowHexagon);
  EXPECT_GT(yellowHexagon, yellowRound * 1.3);

  // The footprint: the iris outline in the stop's yellow, centred in its box. The circle's radius
  // in pixels is where a scan from the centre along +x first meets yellow.
  const ApertureBox footprint = apertureWidget(hexagon, "illumination/footprint");
  const double cx = 0.5 * (footprint.x0 + footprint.x1), cy = 0.5 * (footprint.y0 + footprint.y1);
  double radiusPx = 0;
  for (int r = 5; r < (footprint.x1 - footprint.x0) / 2; ++r)
    if (roundShot.fractionNear(static_cast<int>(cx) + r, static_cast<int>(cy),
                               static_cast<int>(cx) + r + 1, static_cast<int>(cy) + 1, kStopYellow,
                               60) > 0) {
      radiusPx = r;
      break;
    }
  ASSERT_GT(radiusPx, 20.0);
  // Corners at 0, 60, ... degrees (first corner on +x; the footprint shows y up): there both
  // outlines reach the radius. Half-way, at 30 + 60 k degrees, the hexagon's edge is at
  // cos 30 = 0.866 of it, the circle still at the full radius.
  for (int k = 0; k < 6; ++k) {
    const double edge = (30.0 + 60.0 * k) * std::numbers::pi / 180.0;
    const double ux = std::cos(edge), uy = -std::sin(edge);
    const double inner = radiusPx * std::cos(std::numbers::pi / 6.0);
    EXPECT_TRUE(yellowNear(hexagonShot, cx + inner * ux, cy + inner * uy)) << "edge " << k;
    EXPECT_FALSE(yellowNear(hexagonShot, cx + radiusPx * ux, cy + radiusPx * uy)) << "edge " << k;
    EXPECT_TRUE(yellowNear(roundShot, cx + radiusPx * ux, cy + radiusPx * uy)) << "edge " << k;
    EXPECT_FALSE(yellowNear(roundShot, cx + inner * ux, cy + inner * uy)) << "edge " << k;
  }
}

}  // namespace
}  // namespace lenslab
