// Edit > Paste lens table... (issue 41): the real viewer under Xvfb shows a patent table's text as
// understood, a column's meaning changed by its combo re-reads it, and Open opens the lens.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class PasteTable : public ::testing::Test {
 protected:
  testing::ProcessResult runScript(const std::string& script) {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << script;
    return testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                   "' --size 1280x800 --script '" + path.string() + "'",
                               scratch);
  }
  nlohmann::json json(const std::string& name) {
    std::ifstream file(scratch / name);
    return nlohmann::json::parse(file, nullptr, false);
  }
  testing::PngImage image(const std::string& name) {
    return testing::PngImage::load(scratch / name);
  }
  static bool logged(const nlohmann::json& dump, const std::string& text) {
    for (const auto& entry : dump["state"]["log"])
      if (entry["text"].get<std::string>().find(text) != std::string::npos) return true;
    return false;
  }
  // Pixels that differ between two screenshots inside a widget's rectangle of a dump.
  static std::size_t differingIn(const nlohmann::json& box, const testing::PngImage& a,
                                 const testing::PngImage& b) {
    EXPECT_TRUE(box.is_object()) << box;
    std::size_t count = 0;
    const int x0 = box.value("x", 0), y0 = box.value("y", 0);
    for (int y = y0; y < y0 + box.value("height", 0) && y < a.height; ++y)
      for (int x = x0; x < x0 + box.value("width", 0) && x < a.width; ++x)
        count += a.at(x, y).maxDifference(b.at(x, y)) > 24;
    return count;
  }
  std::filesystem::path scratch = testing::makeTestDirectory("paste-table");
};

// Headings the reader does not know ("Gap", "Rad."): it takes the usual order (r before d),
// which is wrong here, so the lens cannot open (a negative gap); the script's combos fix the two
// columns, and Open opens an f/4 lens.
constexpr const char* kTable =
    "Example 1   f = 98.2   Fno = 4.0   2\xCF\x89 = 20\n"
    "No  Gap  Rad.  nd  \xCE\xBD"
    "d\n"
    "1   5    50    1.5168  64.2\n"
    "2   2    -200\n"
    "3(Stop) 3 \xE2\x88\x9E\n"
    "4   3    -80   1.6200  36.3\n"
    "5   40   -300\n";

TEST_F(PasteTable, CombosFixTheColumnsAndOpenOpensTheLens) {
  std::ofstream(scratch / "table.txt") << kTable;
  const auto result = runScript(
      "wait-frames 3\n"
      "screenshot before.png\n"
      "paste-lens-table table.txt\n"
      "wait-frames 3\n"
      "screenshot wrong.png\n"
      "dump-ui wrong.json\n"
      "paste-lens-table-column 2 d\n"
      "paste-lens-table-column 3 r\n"
      "wait-frames 3\n"
      "screenshot fixed.png\n"
      "dump-ui fixed.json\n"
      "paste-lens-table-open\n"
      "wait-frames 3\n"
      "screenshot opened.png\n"
      "dump-ui opened.json\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = image("before.png"), wrong = image("wrong.png"), fixed = image("fixed.png"),
             opened = image("opened.png");
  ASSERT_TRUE(before.valid() && wrong.valid() && fixed.valid() && opened.valid());
  const nlohmann::json w = json("wrong.json"), f = json("fixed.json"), o = json("opened.json");

  // The window is on screen over the viewer, with the text read the usual way: r before d.
  const auto window = w["widgets"]["paste-table"];
  ASSERT_TRUE(window.is_object()) << w["widgets"];
  EXPECT_GT(differingIn(window, before, wrong), 20000u);
  const auto paste = w["state"]["paste_table"];
  EXPECT_TRUE(paste["open"].get<bool>());
  // Read that way, the stop row's ∞ is a d, which is refused: four rows, and errors.
  EXPECT_EQ(paste["rows"], 4);
  EXPECT_GT(paste["errors"].get<int>(), 0);
  ASSERT_EQ(paste["columns"].size(), 5u);
  EXPECT_EQ(paste["columns"][1]["heading"], "Gap");
  EXPECT_EQ(paste["columns"][1]["meaning"], "r");
  EXPECT_FALSE(paste["can_open"].get<bool>());

  // The combos' new meanings: the rows show other numbers, and Open is enabled (drawn brighter).
  const auto fixedPaste = f["state"]["paste_table"];
  EXPECT_EQ(fixedPaste["columns"][1]["meaning"], "d");
  EXPECT_EQ(fixedPaste["columns"][2]["meaning"], "r");
  EXPECT_EQ(fixedPaste["rows"], 5);
  EXPECT_EQ(fixedPaste["errors"], 0);
  EXPECT_TRUE(fixedPaste["can_open"].get<bool>());
  EXPECT_GT(differingIn(w["widgets"]["paste-table/rows"], wrong, fixed), 200u);
  EXPECT_GT(differingIn(w["widgets"]["paste-table/open"], wrong, fixed), 10u);

  // Open: the window is gone, the lens is the table's, at the stated f-number, unsaved.
  EXPECT_FALSE(o["state"]["paste_table"]["open"].get<bool>());
  EXPECT_FALSE(o["widgets"].contains("paste-table"));
  EXPECT_TRUE(o["state"]["lens_valid"].get<bool>());
  EXPECT_EQ(o["state"]["lens_path"], "");
  EXPECT_TRUE(logged(o, "Opened lens table.txt")) << o["state"]["log"];
  EXPECT_EQ(o["state"]["first_order"]["f_number"], "f/4.00");
  EXPECT_GT(differingIn(window, wrong, opened), 20000u);
}

}  // namespace
}  // namespace lenslab
