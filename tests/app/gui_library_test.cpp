// The library browser (issue 42) in the real viewer: opened on a fixture folder of lenses with
// known types, years and focal lengths (plano-convex singlets: f = R / (n - 1), as in
// library_filter_test.cpp), it lists each with its thumbnail (pixels of the cross-section's
// colours inside each card), searches and filters (the counts kept, counted by hand), and opens
// a lens as File > Open does: a real double-click on a card, and the script's `library select`;
// the lens table then holds that lens, focused for the scene as `load-lens` focuses it. Run a
// second time, the thumbnails come from the cache on disk instead of being drawn.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>

#include "support/background_process.h"
#include "support/png_image.h"
#include "support/run_process.h"
#include "support/singlet_lens_text.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

using testing::centreOf;
using testing::readJson;
using testing::waitForFile;

//   file          type           year  f (mm)  aspheric
//   a-dg.lens     double-Gauss   1953     50   no
//   b-tele.lens   telephoto      1970    200   no
//   c-phone.lens  smartphone     2019      4   yes
//   d-dg.lens     double-Gauss   1989     85   yes
//   f-old.dat     -              -       100   no
std::filesystem::path writeGuiLibraryFixture(const std::filesystem::path& scratch) {
  const auto folder = scratch / "lenses";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "a-dg.lens") << testing::planoConvexLensText(
      "title Gauss fifty\nsource US 2,532,751\ntype double-Gauss\nyear 1953\n", 25.0, "", 20.0);
  std::ofstream(folder / "b-tele.lens") << testing::planoConvexLensText(
      "title Long one\nsource US 3,000,000 (Smith)\ntype telephoto\nyear 1970\n", 100.0, "", 40.0);
  std::ofstream(folder / "c-phone.lens") << testing::planoConvexLensText(
      "title Phone camera\nsource CN 110,000,000\ntype smartphone\nyear 2019\n", 2.0, " a4 -0.001",
      2.0);
  std::ofstream(folder / "d-dg.lens") << testing::planoConvexLensText(
      "title Gauss eighty-five\nsource JP 1989-123\ntype double-Gauss\nyear 1989\n", 42.5,
      " conic -0.5 a6 1e-9", 30.0);
  std::ofstream(folder / "f-old.dat") << "# An old singlet, 100 mm\n0 1 0 10\n50 2 1.5 20\ninf "
                                         "100 1 20\n";
  return folder;
}

std::string libraryViewerCommand(const std::filesystem::path& scratch, const std::string& script) {
  // Its own cache folder: the thumbnails it writes are this test's, and a second run finds them.
  return "cd '" + scratch.string() + "' && XDG_CACHE_HOME='" + (scratch / "cache").string() +
         "' exec '" + LENSLAB_BINARY + "' --size 1400x900 --script " + script + " 2>>stderr.txt";
}

void expectLibraryViewerQuits(testing::BackgroundProcess& viewer,
                              const std::filesystem::path& scratch) {
  const auto exitCode = viewer.wait(std::chrono::seconds(120));
  ASSERT_TRUE(exitCode.has_value()) << "the viewer did not quit";
  EXPECT_EQ(*exitCode, 0) << testing::readWholeFile(scratch / "stderr.txt");
}

std::vector<std::string> libraryShownFiles(const nlohmann::json& ui) {
  std::vector<std::string> files;
  for (const auto& entry : ui["state"]["library"]["shown"]) files.push_back(entry["file"]);
  return files;
}

// Pixels of a card's thumbnail (its top-left, 6 px in, 248 x 112 at UI scale 1) near a colour.
std::size_t libraryThumbnailPixelsNear(const testing::PngImage& image, const nlohmann::json& ui,
                                       const std::string& file, testing::Rgb colour,
                                       int tolerance) {
  const auto& card = ui["widgets"]["library/card/" + file];
  const int x0 = static_cast<int>(card["x"].get<double>()) + 6;
  const int y0 = static_cast<int>(card["y"].get<double>()) + 6;
  const int x1 = std::min(image.width, x0 + 248), y1 = std::min(image.height, y0 + 112);
  std::size_t near = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) near += image.at(x, y).maxDifference(colour) <= tolerance;
  return near;
}

TEST(LibraryBrowser, ListsWithThumbnailsSearchesFiltersAndOpensLenses) {
  const auto scratch = testing::makeTestDirectory("library-browser");
  const auto folder = writeGuiLibraryFixture(scratch);
  std::ofstream(scratch / "browse.script")
      << "wait-frames 3\n"
         "library open lenses\n"
         "library wait\n"
         "wait-frames 2\n"
         "screenshot all.png\n"
         "dump-ui all.json\n"
         "wait-until-file go\n"  // the test double-clicks b-tele's card
         "wait-frames 10\n"
         "dump-ui clicked.json\n"
         "library search gauss\n"
         "dump-ui search.json\n"
         "screenshot search.png\n"
         "library search\n"
         "library filter aspheric yes\n"
         "dump-ui aspheric.json\n"
         "library filter aspheric any\n"
         "library filter efl 40 100\n"
         "dump-ui efl.json\n"
         "library filter efl any\n"
         "library filter year 1950 1975\n"
         "dump-ui year.json\n"
         "library filter clear\n"
         "library filter type double-Gauss\n"
         "dump-ui type.json\n"
         "library select d-dg\n"
         "wait-frames 3\n"
         "dump-ui opened.json\n"
         "screenshot opened.png\n"
         "quit\n";
  testing::BackgroundProcess viewer(libraryViewerCommand(scratch, "browse.script"));
  ASSERT_TRUE(waitForFile(scratch / "all.json", std::chrono::seconds(90)))
      << testing::readWholeFile(scratch / "stderr.txt");
  const nlohmann::json all = readJson(scratch / "all.json");
  const auto& library = all["state"]["library"];
  EXPECT_EQ(libraryShownFiles(all),
            (std::vector<std::string>{"a-dg.lens", "b-tele.lens", "c-phone.lens", "d-dg.lens",
                                      "f-old.dat"}))
      << library;
  EXPECT_EQ(all["state"]["tabs"]["bottom"], "library");
  // Every lens's thumbnail drawn (none cached yet) and uploaded.
  EXPECT_EQ(library["thumbnails_drawn"], 5);
  EXPECT_EQ(library["thumbnails_from_disk"], 0);
  for (const auto& entry : library["shown"]) EXPECT_TRUE(entry["thumbnail"].get<bool>()) << entry;
  // The figures computed from the prescriptions, as counted by hand.
  EXPECT_NEAR(library["shown"][1]["efl_mm"].get<double>(), 200.0, 1e-6);
  EXPECT_EQ(library["shown"][1]["type"], "telephoto");
  EXPECT_EQ(library["shown"][1]["year"], 1970);
  EXPECT_EQ(library["shown"][3]["aspheric_surfaces"], 1);  // its front: a conic and A6
  // How long it took, from the request (printed for the record).
  // The panel is drawn within two frames of the request (its wall time is theirs: a full
  // redraw by llvmpipe takes 100-250 ms on a loaded machine), and the worker reads the 5 files
  // well within 200 ms.
  std::cout << "library of 5: read in " << library["read_ms"] << " ms, panel shown "
            << library["panel_shown_ms"] << " ms after the request, listed " << library["listed_ms"]
            << " ms, thumbnails made in " << library["thumbnails_made_ms"] << " ms and shown "
            << library["thumbnails_shown_ms"] << " ms\n";
  // ImGui's tab bar selects the tab in the frame after the request and draws it in the next.
  EXPECT_LE(library["panel_shown_after_frames"].get<int>(), 2);
  EXPECT_LT(library["read_ms"].get<double>(), 200.0);

  // The thumbnails show the lens: the glass edge's light blue and the on-axis fan's green inside
  // every card's picture (the dark background alone has neither).
  const auto shot = testing::PngImage::load(scratch / "all.png");
  ASSERT_TRUE(shot.valid());
  for (const char* file : {"a-dg.lens", "b-tele.lens", "c-phone.lens", "d-dg.lens", "f-old.dat"}) {
    ASSERT_TRUE(all["widgets"].contains(std::string("library/card/") + file)) << file;
    EXPECT_GT(libraryThumbnailPixelsNear(shot, all, file, {170, 200, 240}, 40), 40u) << file;
    EXPECT_GT(libraryThumbnailPixelsNear(shot, all, file, {80, 220, 120}, 50), 20u) << file;
  }

  // A real double-click on the telephoto's card opens it.
  const auto clicked =
      testing::runProcess(testing::kFocusViewerWindow + "xdotool mousemove --window $W " +
                              centreOf(all, "library/card/b-tele.lens") +
                              " && sleep 0.3 && xdotool click --repeat 2 --delay 80 1",
                          scratch);
  ASSERT_EQ(clicked.exitCode, 0) << clicked.err;
  std::ofstream(scratch / "go") << "go";
  expectLibraryViewerQuits(viewer, scratch);

  const nlohmann::json afterClick = readJson(scratch / "clicked.json");
  EXPECT_EQ(std::filesystem::path(afterClick["state"]["lens_path"].get<std::string>()).filename(),
            "b-tele.lens")
      << afterClick["state"]["log"];
  EXPECT_EQ(afterClick["state"]["lens_name"], "Long one");
  EXPECT_EQ(afterClick["state"]["media"].size(), 3u);  // the stop and the singlet's two surfaces

  // Search and filters, against the table above.
  EXPECT_EQ(libraryShownFiles(readJson(scratch / "search.json")),
            (std::vector<std::string>{"a-dg.lens", "d-dg.lens"}));
  EXPECT_EQ(libraryShownFiles(readJson(scratch / "aspheric.json")),
            (std::vector<std::string>{"c-phone.lens", "d-dg.lens"}));
  EXPECT_EQ(libraryShownFiles(readJson(scratch / "efl.json")),
            (std::vector<std::string>{"a-dg.lens", "d-dg.lens", "f-old.dat"}));
  EXPECT_EQ(libraryShownFiles(readJson(scratch / "year.json")),
            (std::vector<std::string>{"a-dg.lens", "b-tele.lens"}));
  EXPECT_EQ(libraryShownFiles(readJson(scratch / "type.json")),
            (std::vector<std::string>{"a-dg.lens", "d-dg.lens"}));
  // A search leaves cards off the screen: only the two found are drawn.
  const nlohmann::json search = readJson(scratch / "search.json");
  EXPECT_TRUE(search["widgets"].contains("library/card/a-dg.lens"));
  EXPECT_FALSE(search["widgets"].contains("library/card/b-tele.lens"));

  // `library select` opened the 85 mm lens.
  const nlohmann::json opened = readJson(scratch / "opened.json");
  EXPECT_EQ(std::filesystem::path(opened["state"]["lens_path"].get<std::string>()).filename(),
            "d-dg.lens");
  EXPECT_EQ(opened["state"]["lens_name"], "Gauss eighty-five");
  EXPECT_EQ(opened["state"]["library"]["selected"], (folder / "d-dg.lens").string());

  // Again: the pictures come from the cache on disk, and File > Open's path (load-lens) puts the
  // same lens at the same film distance as the browser did.
  std::ofstream(scratch / "again.script") << "wait-frames 3\n"
                                             "library open lenses\n"
                                             "library wait\n"
                                             "dump-ui again.json\n"
                                             "load-lens lenses/d-dg.lens\n"
                                             "dump-ui loaded.json\n"
                                             "quit\n";
  testing::BackgroundProcess second(libraryViewerCommand(scratch, "again.script"));
  expectLibraryViewerQuits(second, scratch);
  const nlohmann::json again = readJson(scratch / "again.json");
  EXPECT_EQ(again["state"]["library"]["thumbnails_from_disk"], 5) << again["state"]["library"];
  EXPECT_EQ(again["state"]["library"]["thumbnails_drawn"], 0);
  std::cout << "again, from the cache: thumbnails made in "
            << again["state"]["library"]["thumbnails_made_ms"] << " ms, shown "
            << again["state"]["library"]["thumbnails_shown_ms"] << " ms after the request\n";
  const nlohmann::json loaded = readJson(scratch / "loaded.json");
  EXPECT_DOUBLE_EQ(loaded["state"]["film_distance_mm"].get<double>(),
                   opened["state"]["film_distance_mm"].get<double>());
}

// The bundled library, as Lens > Library > Browse library... shows it: how long it takes to list
// it and show its thumbnails (drawn, with an empty cache), for the record; the panel is there
// within the frame after the request.
TEST(LibraryBrowser, OpensOnTheBundledLibraryQuickly) {
  const auto scratch = testing::makeTestDirectory("library-bundled");
  std::ofstream(scratch / "bundled.script") << "wait-frames 3\n"
                                               "library open\n"
                                               "library wait\n"
                                               "screenshot bundled.png\n"
                                               "dump-ui bundled.json\n"
                                               "quit\n";
  testing::BackgroundProcess viewer(libraryViewerCommand(scratch, "bundled.script"));
  expectLibraryViewerQuits(viewer, scratch);
  const nlohmann::json ui = readJson(scratch / "bundled.json");
  const auto& library = ui["state"]["library"];
  EXPECT_GE(library["shown"].size(), 10u) << library;
  for (const auto& entry : library["shown"]) {
    EXPECT_EQ(entry["error"], "") << entry;
    EXPECT_TRUE(entry["thumbnail"].get<bool>()) << entry;
  }
  std::cout << "bundled library of " << library["shown"].size() << ": read in "
            << library["read_ms"] << " ms, panel shown " << library["panel_shown_ms"]
            << " ms after the request, listed " << library["listed_ms"]
            << " ms, thumbnails made in " << library["thumbnails_made_ms"] << " ms and shown "
            << library["thumbnails_shown_ms"] << " ms\n";
  // ImGui's tab bar selects the tab in the frame after the request and draws it in the next.
  EXPECT_LE(library["panel_shown_after_frames"].get<int>(), 2);
  // How long reading all 46 takes is printed above, not asserted: a wall-clock bound fails on a
  // busy machine or under a sanitizer (1,725 ms under ThreadSanitizer against 177 ms in Release,
  // 2026-11-28), and the panel shows the entries as they come. The figure is for the record.
}

}  // namespace
}  // namespace lenslab
