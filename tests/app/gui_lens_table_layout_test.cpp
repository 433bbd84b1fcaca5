// The lens table's layout (issue 20): a 13-surface lens shows every row at 1400x900 in one scroll
// region, at UI scale 2 in 1600x1000 every column shows and the first-order data can be scrolled
// to, and a second radius-0 row keeps the stop controls. Drives the real viewer under Xvfb and
// checks the rectangles its dump-ui reports, and pixels where a rectangle cannot tell.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

const std::string kSource = LENSLAB_SOURCE_DIR;
// wide-22mm.dat has 13 surfaces, the most of the bundled lenses.
const std::string kThirteenSurfaces = kSource + "/lenses/wide-22mm.dat";
constexpr int kRows = 13;
const char* const kColumns[] = {"radius", "conic", "thickness", "n_d", "V_d", "aperture", "stop"};
// Dear ImGui's dark style (imgui 1.86 StyleColorsDark): CheckMark.
constexpr testing::Rgb kCheckMark{66, 150, 250};

struct Box {
  double x, y, width, height;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
};
Box box(const nlohmann::json& ui, const std::string& widget) {
  const auto& rect = ui["widgets"][widget];
  return {rect["x"].get<double>(), rect["y"].get<double>(), rect["width"].get<double>(),
          rect["height"].get<double>()};
}

class LensTableLayout : public ::testing::Test {
 protected:
  nlohmann::json dump(const std::string& environment, const std::string& size,
                      const std::string& body, const std::string& screenshot = "") {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << "load-lens " << kThirteenSurfaces << "\n"
                        << body << "wait-frames 3\n"
                        << (screenshot.empty() ? "" : "screenshot " + screenshot + "\n")
                        << "dump-ui " << (scratch / "ui.json").string() << "\nquit\n";
    const auto result =
        testing::runProcess(environment + " '" + std::string(LENSLAB_BINARY) + "' --size " + size +
                                " --script '" + path.string() + "'",
                            scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    std::ifstream file(scratch / "ui.json");
    return nlohmann::json::parse(file, nullptr, false);
  }
  std::filesystem::path scratch = testing::makeTestDirectory("lens-table-layout");
};

TEST_F(LensTableLayout, EveryRowOfAThirteenSurfaceLensShowsAt1400x900) {
  const nlohmann::json ui = dump("", "1400x900", "");
  ASSERT_TRUE(ui.is_object());
  const Box visible = box(ui, "lens-table/visible");
  const Box focus = box(ui, "first-order/focus");
  for (int row = 1; row <= kRows; ++row) {
    for (const char* column : kColumns) {
      const std::string name = "lens-table/" + std::to_string(row) + "/" + column;
      ASSERT_TRUE(ui["widgets"].contains(name)) << name;
      const Box cell = box(ui, name);
      EXPECT_GE(cell.x, visible.x) << name;
      EXPECT_LE(cell.right(), visible.right()) << name;
      EXPECT_GE(cell.y, visible.y) << name;
      EXPECT_LE(cell.bottom(), visible.bottom()) << name;
      // Above the first-order controls: not hidden under them by a table scrolled short.
      EXPECT_LT(cell.bottom(), focus.y) << name;
    }
    // Nor clipped by the table itself: each row's stop check box lies within what its cell's
    // clip rectangle shows (a table that scrolls clips the rows beyond its height).
    const std::string stop = "lens-table/" + std::to_string(row) + "/stop";
    const Box box1 = box(ui, stop), clip = box(ui, stop + "-cell");
    EXPECT_GE(box1.y, clip.y - 0.5) << stop;
    EXPECT_LE(box1.bottom(), clip.bottom() + 0.5) << stop << " is scrolled out of the table";
    EXPECT_LE(box1.right(), clip.right() + 0.5) << stop;
  }
  EXPECT_EQ(ui["state"]["lens_table_cells_cut_off"], 0);
  // The controls fit too. The first-order figures below them may scroll with the table, in the
  // panel's one scroll region, by less than a few rows (the limiting-aperture rows made them a
  // little taller than the panel).
  EXPECT_LE(focus.bottom(), visible.bottom());
  EXPECT_LT(ui["state"]["lens_panel_scroll_max_y"].get<double>(), 60.0);
}

TEST_F(LensTableLayout, AtUiScaleTwoEveryColumnShowsAndTheFirstOrderDataIsReachable) {
  const nlohmann::json ui = dump("LENSLAB_UI_SCALE=2", "1600x1000", "");
  ASSERT_TRUE(ui.is_object());
  const Box visible = box(ui, "lens-table/visible");
  for (const char* column : kColumns) {
    const std::string name = std::string("lens-table/1/") + column;
    const Box cell = box(ui, name);
    EXPECT_GE(cell.x, visible.x) << name;
    EXPECT_LE(cell.right(), visible.right()) << name << " is cut off at the panel's edge";
  }
  EXPECT_EQ(ui["state"]["lens_table_cells_cut_off"], 0);
  // The first-order controls and data follow the rows in the panel's one scroll region.
  const double scrollMax = ui["state"]["lens_panel_scroll_max_y"].get<double>();
  for (const char* widget : {"first-order/focus", "first-order/stop-diameter"}) {
    const Box control = box(ui, widget);
    EXPECT_GE(control.x, visible.x) << widget;
    EXPECT_LE(control.right(), visible.right()) << widget;
    EXPECT_LE(control.bottom(), visible.bottom() + scrollMax) << widget << " cannot be reached";
  }
  // The rows come first: the top of the table shows without scrolling.
  EXPECT_LE(box(ui, "lens-table/5/radius").bottom(), visible.bottom());
}

TEST_F(LensTableLayout, RadiusZeroOnRowTwoKeepsTheStopControls) {
  for (const std::string& environment : {std::string(""), std::string("LENSLAB_UI_SCALE=2")}) {
    SCOPED_TRACE(environment);
    const std::string size = environment.empty() ? "1400x900" : "1600x1000";
    const nlohmann::json ui =
        dump(environment, size, "set surface 2 radius 0\n", (scratch / "shot.png").string());
    ASSERT_TRUE(ui.is_object());
    // Two rows with radius 0: row 2 is flagged, the stop (row 6) stays the stop.
    ASSERT_FALSE(ui["state"]["problems"].empty());
    const Box visible = box(ui, "lens-table/visible");
    const Box stop = box(ui, "lens-table/2/stop");
    EXPECT_GE(stop.x, visible.x);
    EXPECT_LE(stop.right(), visible.right());
    EXPECT_LE(stop.bottom(), visible.bottom());
    // The check box is drawn, ticked (radius 0 is a stop): its check mark's colour is in it.
    const testing::PngImage image = testing::PngImage::load(scratch / "shot.png");
    ASSERT_TRUE(image.valid());
    EXPECT_GT(image.fractionNear(static_cast<int>(stop.x), static_cast<int>(stop.y),
                                 static_cast<int>(stop.right()), static_cast<int>(stop.bottom()),
                                 kCheckMark, 12),
              0.05);
    // The Stop mm control stays, for the row that was the stop, and can be scrolled to.
    ASSERT_TRUE(ui["widgets"].contains("first-order/stop-diameter"));
    const Box control = box(ui, "first-order/stop-diameter");
    EXPECT_LE(control.right(), visible.right());
    EXPECT_LE(control.bottom(),
              visible.bottom() + ui["state"]["lens_panel_scroll_max_y"].get<double>());
  }
}

}  // namespace
}  // namespace lenslab
