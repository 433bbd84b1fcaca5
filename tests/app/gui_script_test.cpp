// Drives the real viewer with --script under Xvfb and checks pixels of what it saved.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "optics/focus.h"
#include "optics/lens_loader.h"
#include "optics/lens_system.h"
#include "render/image_io.h"

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class ScriptedViewer : public ::testing::Test {
 protected:
  // `prefix` runs in the same shell first (ulimit, environment); `arguments` follow lenslab's.
  testing::ProcessResult runScript(const std::string& script, const std::string& prefix = "",
                                   const std::string& arguments = "") {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << script;
    return testing::runProcess(prefix + "cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                   "' --size 1280x800 --script '" + path.string() + "' " +
                                   arguments,
                               scratch);
  }
  nlohmann::json json(const std::string& name) {
    std::ifstream file(scratch / name);
    return nlohmann::json::parse(file, nullptr, false);
  }
  // The rows (1-based) the dump's lens problems are on.
  static std::vector<int> problemRows(const nlohmann::json& dump) {
    std::vector<int> rows;
    for (const auto& problem : dump["state"]["problems"]) rows.push_back(problem["surface"]);
    return rows;
  }
  // Whether the dump's log has an entry (of `level`, when given) whose text contains `text`.
  static bool logged(const nlohmann::json& dump, const std::string& text,
                     const std::string& level = "") {
    for (const auto& entry : dump["state"]["log"]) {
      const std::string said = entry["text"];
      if ((level.empty() || entry["level"] == level) && said.find(text) != std::string::npos)
        return true;
    }
    return false;
  }
  static bool loggedError(const nlohmann::json& dump, const std::string& text) {
    return logged(dump, text, "error");
  }
  // Whether a recent file of the dump's has `text` in its path.
  static bool inRecentFiles(const nlohmann::json& dump, const std::string& text) {
    for (const auto& path : dump["state"]["recent_files"]) {
      if (path.get<std::string>().find(text) != std::string::npos) return true;
    }
    return false;
  }
  testing::PngImage image(const std::string& name) {
    return testing::PngImage::load(scratch / name);
  }
  // A terrain of about a million triangles (terrain.ply in the scratch directory): a scene that
  // uses it takes a second or more to load.
  void writeTerrainPly() {
    constexpr int kSide = 708;  // vertices per side: 2 * 707^2 = 999 698 triangles
    {
      std::ofstream ply(scratch / "terrain.ply", std::ios::binary);
      ply << "ply\nformat binary_little_endian 1.0\nelement vertex " << kSide * kSide
          << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
          << 2 * (kSide - 1) * (kSide - 1)
          << "\nproperty list uchar int vertex_indices\nend_header\n";
      for (int i = 0; i < kSide; ++i) {
        for (int j = 0; j < kSide; ++j) {
          const float x = 4.0f * i / (kSide - 1) - 2.0f, z = 4.0f * j / (kSide - 1) - 2.0f;
          const float point[3] = {x, 0.1f * std::sin(6.0f * x) * std::cos(6.0f * z), z};
          ply.write(reinterpret_cast<const char*>(point), sizeof point);
        }
      }
      for (int i = 0; i + 1 < kSide; ++i) {
        for (int j = 0; j + 1 < kSide; ++j) {
          const int a = i * kSide + j, b = a + 1, c = a + kSide, d = c + 1;
          const int faces[2][3] = {{a, c, b}, {b, c, d}};
          for (const auto& face : faces) {
            const unsigned char three = 3;
            ply.write(reinterpret_cast<const char*>(&three), 1);
            ply.write(reinterpret_cast<const char*>(face), sizeof face);
          }
        }
      }
    }
  }
  // `name` in the scratch directory: the terrain above, lit by a uniform sky, seen from 1.2 m up
  // by `camera` (a Camera directive, and a Film one where wanted); writes terrain.ply too.
  void writeTerrainScene(const std::string& name, const std::string& camera) {
    writeTerrainPly();
    std::ofstream(scratch / name) << "LookAt 0 1.2 3  0 0 0  0 1 0\n"
                                  << camera
                                  << "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                                     "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
                                     "Shape \"plymesh\" \"string filename\" \"terrain.ply\"\n"
                                     "WorldEnd\n";
  }
  std::filesystem::path scratch = testing::makeTestDirectory("script");
};

TEST_F(ScriptedViewer, AnEditChangesTheCrossSectionAndUndoRestoresIt) {
  const auto result = runScript(
      "wait-frames 3\n"
      "screenshot-cross-section before.png\n"
      "set surface 1 radius 22\n"
      "set film-distance 60\n"
      "wait-frames 2\n"
      "screenshot-cross-section edited.png\n"
      "undo\n"
      "undo\n"
      "wait-frames 2\n"
      "screenshot-cross-section undone.png\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = image("before.png"), edited = image("edited.png"),
             undone = image("undone.png");
  ASSERT_TRUE(before.valid() && edited.valid() && undone.valid());
  // The lens occupies a good part of the canvas, so a changed radius and film move many pixels.
  EXPECT_GT(testing::countDifferentPixels(before, edited), 500u);
  EXPECT_EQ(testing::countDifferentPixels(before, undone), 0u);
}

// Issue 40: a conic and an A4 set by the script show in the table (the k column, and "1*" for an
// aspheric surface), the asphere editor plots the surface's departure from its sphere, and two
// undos give the table back as it was.
TEST_F(ScriptedViewer, AsphericTermsShowInTheTableAndTheAsphereEditor) {
  const auto result = runScript(
      "wait-frames 3\n"
      "screenshot before.png\n"
      "dump-ui before.json\n"
      "set surface 1 conic -0.5\n"
      "set surface 1 a4 -2e-6\n"
      "wait-frames 2\n"
      "screenshot aspheric.png\n"
      "asphere-editor 1\n"
      "wait-frames 3\n"
      "screenshot editor.png\n"
      "dump-ui editor.json\n"
      "asphere-editor close\n"
      "undo\n"
      "undo\n"
      "wait-frames 2\n"
      "screenshot undone.png\n"
      "dump-ui undone.json\n"
      "quit\n",
      // The pointer away from the editor's plot, whose hover readout would count as curve.
      "xdotool mousemove 0 790 >/dev/null 2>&1; ");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = image("before.png"), aspheric = image("aspheric.png"),
             editor = image("editor.png"), undone = image("undone.png");
  ASSERT_TRUE(before.valid() && aspheric.valid() && editor.valid() && undone.valid());
  // Pixels that differ between two screenshots inside a widget's rectangle of the dump.
  const auto differingIn = [](const nlohmann::json& box, const testing::PngImage& a,
                              const testing::PngImage& b) {
    EXPECT_TRUE(box.is_object()) << box;
    std::size_t count = 0;
    const int x0 = box.value("x", 0), y0 = box.value("y", 0);
    for (int y = y0; y < y0 + box.value("height", 0) && y < a.height; ++y) {
      for (int x = x0; x < x0 + box.value("width", 0) && x < a.width; ++x) {
        count += a.at(x, y).maxDifference(b.at(x, y)) > 24;
      }
    }
    return count;
  };
  const nlohmann::json widgets = json("before.json")["widgets"];
  const auto& conicCell = widgets["lens-table/1/conic"];
  const auto& number = widgets["lens-table/1/number"];
  // "0" became "-0.5" in the k column, "1" became "1*".
  EXPECT_GT(differingIn(conicCell, before, aspheric), 10u);
  EXPECT_GT(differingIn(number, before, aspheric), 3u);
  // Undone, both cells are as they were, pixel for pixel, and the editor is gone.
  EXPECT_EQ(differingIn(conicCell, before, undone), 0u);
  EXPECT_EQ(differingIn(number, before, undone), 0u);
  EXPECT_FALSE(json("undone.json")["widgets"].contains("asphere-editor"));

  // The editor's plot: the departure curve (drawn in its light blue) climbs across many pixel
  // rows, where a sphere's would be one flat line at zero.
  const auto plot = json("editor.json")["widgets"]["asphere-editor/plot"];
  ASSERT_TRUE(plot.is_object()) << json("editor.json")["widgets"];
  const testing::Rgb curveColour{0x4f, 0xc3, 0xf7};
  std::set<int> curveRows;
  for (int y = plot.value("y", 0); y < plot.value("y", 0) + plot.value("height", 0); ++y) {
    for (int x = plot.value("x", 0); x < plot.value("x", 0) + plot.value("width", 0); ++x) {
      if (editor.at(x, y).maxDifference(curveColour) <= 40) curveRows.insert(y);
    }
  }
  EXPECT_GT(curveRows.size(), 40u) << "the departure curve spans too few rows";
}

TEST_F(ScriptedViewer, AnEditChangesThePreviewAndUndoRestoresIt) {
  // Auto exposure off: it meters the first 16 samples per pixel, so with it the three pictures
  // (at 2 spp each) could be shown at different exposures while it settles. (The default lens
  // renders spectrally, whose colour noise moves the early metering more.)
  const auto result = runScript(
      "set auto-exposure off\n"
      "wait-spp 2\n"
      "screenshot-render before.png\n"
      "dump-ui before.json\n"
      "set stop-diameter 3.5\n"  // f/2.5 to about f/10: two stops darker
      "wait-spp 2\n"
      "screenshot-render stopped-down.png\n"
      "undo\n"
      "wait-spp 2\n"
      "screenshot-render undone.png\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto before = image("before.png"), stopped = image("stopped-down.png"),
             undone = image("undone.png");
  ASSERT_TRUE(before.valid() && stopped.valid() && undone.valid());
  // The preview renders at the size the panel shows it, pixel for pixel (at most the default
  // scene's 600x400 film), with the film's aspect ratio.
  const auto shown = json("before.json")["widgets"]["preview/image"];
  ASSERT_TRUE(shown.is_object()) << shown;
  EXPECT_LE(before.width, 600);
  EXPECT_NEAR(before.width, shown["width"].get<double>(), 1.0);
  EXPECT_NEAR(before.height, shown["height"].get<double>(), 1.0);
  EXPECT_NEAR(static_cast<double>(before.width) / before.height, 1.5, 0.01);
  const double bright = testing::meanBrightness(before);
  EXPECT_GT(bright, 40.0);  // a picture, not a black frame
  EXPECT_LT(testing::meanBrightness(stopped), 0.75 * bright);
  EXPECT_NEAR(testing::meanBrightness(undone), bright, 0.03 * bright);
}

// "Pinhole" compares the lens with an ideal one of the same focal length and the same exposure
// at the image centre: toggling it changes the picture's corners and blur, not its brightness.
// (A plain pinhole images radiance, three stops brighter than the lens at f/2.5.)
TEST_F(ScriptedViewer, ThePinholeTakesTheLensExposureInTheMiddle) {
  const auto result = runScript(
      "wait-spp 16\n"
      "screenshot-render lens.exr\n"
      "set camera pinhole\n"
      "wait-spp 16\n"
      "screenshot-render pinhole.exr\n"
      "set stop-diameter 7\n"  // half the diameter: two stops down, for both
      "wait-spp 16\n"
      "screenshot-render pinhole-stopped-down.exr\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto lens = render::readImage(scratch / "lens.exr");
  const auto pinhole = render::readImage(scratch / "pinhole.exr");
  const auto stoppedDown = render::readImage(scratch / "pinhole-stopped-down.exr");
  ASSERT_TRUE(lens.ok && pinhole.ok && stoppedDown.ok) << lens.error << pinhole.error;
  // The middle fifth of the picture (the chart's checks, in focus): its mean linear value.
  const auto middleMean = [](const render::FloatImage& picture) {
    double sum = 0.0;
    int count = 0;
    for (int y = picture.height * 2 / 5; y < picture.height * 3 / 5; ++y) {
      for (int x = picture.width * 2 / 5; x < picture.width * 3 / 5; ++x, ++count) {
        for (int c = 0; c < 3; ++c) {
          sum += picture.rgb[3 * (static_cast<std::size_t>(y) * picture.width + x) + c];
        }
      }
    }
    return sum / (3.0 * std::max(1, count));
  };
  const double lensMiddle = middleMean(lens.image);
  ASSERT_GT(lensMiddle, 0.05);
  EXPECT_NEAR(middleMean(pinhole.image), lensMiddle, 0.05 * lensMiddle);
  // Stopping the lens down by two stops takes the pinhole's exposure down to a quarter too (the
  // ideal pupil's area; the real one's edge moves a little).
  EXPECT_NEAR(middleMean(stoppedDown.image), 0.25 * middleMean(pinhole.image),
              0.02 * middleMean(pinhole.image));
}

// The cross-section and the preview paint their canvases edge to edge, so ImGui draws no window
// background under them (beginCanvasPanel): their frames, padding and the preview's black bars
// must still look like every other panel's.
TEST_F(ScriptedViewer, TheCanvasPanelsAreFramedLikeTheOthers) {
  const auto result =
      runScript("wait-spp 1\nwait-frames 2\ndump-ui ui.json\nscreenshot window.png\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto window = image("window.png");
  ASSERT_TRUE(window.valid());
  const nlohmann::json widgets = json("ui.json")["widgets"];
  const auto edge = [&](const char* name, const char* field) {
    return static_cast<int>(std::floor(widgets[name][field].get<double>()));
  };
  const int canvasX = edge("cross-section/canvas", "x"),
            canvasY = edge("cross-section/canvas", "y");
  const int canvasBottom = canvasY + edge("cross-section/canvas", "height");
  const int y = canvasY + edge("cross-section/canvas", "height") / 2;
  // The lens panel, an ordinary window, starts at x = 0: its border, then its padding.
  const testing::Rgb border = window.at(0, y), background = window.at(3, y);
  ASSERT_GT(border.maxDifference(background), 20);
  // The cross-section's window lies between the two splitters.
  const int crossLeft =
      static_cast<int>(std::floor(widgets["layout/left-splitter"]["x"].get<double>() +
                                  widgets["layout/left-splitter"]["width"].get<double>()));
  const int crossRight = edge("layout/right-splitter", "x") - 1;
  EXPECT_EQ(window.at(crossLeft, y).maxDifference(border), 0);
  EXPECT_EQ(window.at(crossLeft + 3, y).maxDifference(background), 0);
  EXPECT_EQ(window.at(crossRight, y).maxDifference(border), 0);
  EXPECT_EQ(window.at(canvasX + 10, canvasBottom + 3).maxDifference(background), 0);
  EXPECT_GT(window.at(canvasX + 10, canvasBottom - 3).maxDifference(background), 0);  // the canvas
  // The preview's window: from the right splitter to the window's right edge.
  const int previewLeft =
      static_cast<int>(std::floor(widgets["layout/right-splitter"]["x"].get<double>() +
                                  widgets["layout/right-splitter"]["width"].get<double>()));
  EXPECT_EQ(window.at(previewLeft, y).maxDifference(border), 0);
  EXPECT_EQ(window.at(previewLeft + 3, y).maxDifference(background), 0);
  EXPECT_EQ(window.at(window.width - 2, y).maxDifference(border), 0);
  // Black bars above and below the image (the film is wider than the panel's shape).
  const int imageX = edge("preview/image", "x"), imageY = edge("preview/image", "y");
  const int imageBottom = imageY + edge("preview/image", "height");
  EXPECT_EQ(window.at(imageX + 50, imageY - 3).brightness(), 0);
  EXPECT_EQ(window.at(imageX + 50, imageBottom + 3).brightness(), 0);
  EXPECT_LT(window.fractionNear(imageX, imageY, imageX + 100, imageBottom, {0, 0, 0}, 2),
            0.5);  // the picture, not a bar
}

TEST_F(ScriptedViewer, AnInvalidValueIsFlaggedAndTheLastValidLensKeepsRendering) {
  const auto result = runScript(
      "wait-spp 1\n"
      "set surface 3 thickness -30\n"  // surfaces 3 and 4 now cross
      "set surface 7 radius 0\n"       // a second stop
      "wait-frames 3\n"
      "screenshot window.png\n"
      "wait-spp 2\n"
      "screenshot-render render.png\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto window = image("window.png");
  ASSERT_TRUE(window.valid());
  // Flagged rows are tinted red in the lens table (left column, rows below the header).
  int redPixels = 0;
  for (int y = 100; y < 400; ++y) {
    for (int x = 5; x < 300; ++x) {
      const auto c = window.at(x, y);
      redPixels += c.r > c.g + 25 && c.r > c.b + 25;
    }
  }
  EXPECT_GT(redPixels, 500);
  // The preview still shows the last valid lens's picture.
  EXPECT_GT(testing::meanBrightness(image("render.png")), 40.0);
}

TEST_F(ScriptedViewer, ScriptErrorsAreReportedWithTheirLocationAndExit2) {
  const auto result = runScript("wait-frames 1\nset surface one radius 3\n");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("commands.script:2:13:"), std::string::npos) << result.err;
}

TEST_F(ScriptedViewer, AFailingCommandQuitsWith1AndSaysWhy) {
  const auto result = runScript("load-lens /no/such/lens.dat\nscreenshot never.png\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("/no/such/lens.dat"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(scratch / "never.png"));
}

// A refused edit fails the script, which says so once, at its line: the viewer used to log the
// refusal as well ("script: cannot ..."), and the log's errors go to stderr too.
TEST_F(ScriptedViewer, ARefusedScriptEditIsReportedOnce) {
  const auto result = runScript("wait-frames 1\nset surface 99 radius 1\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("commands.script:2:"), std::string::npos) << result.err;
  std::size_t reports = 0;
  for (std::size_t at = result.err.find("surface 99 does not exist"); at != std::string::npos;
       at = result.err.find("surface 99 does not exist", at + 1)) {
    ++reports;
  }
  EXPECT_EQ(reports, 1u) << result.err;
}

TEST_F(ScriptedViewer, CrossSectionExportsAsSvgWithTheRayFans) {
  const auto result = runScript("wait-frames 2\nscreenshot-cross-section lens.svg\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string svg = testing::readWholeFile(scratch / "lens.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);  // at least one glass element
  // Rays of the three fans in the panel's colours (cross_section_drawing.h), the marginal ray,
  // dashed chief rays, the film and the axis.
  const auto lines = [&](const std::string& colour) {
    std::size_t count = 0;
    for (std::size_t at = 0;
         (at = svg.find("<polyline fill=\"none\" stroke=\"rgb(" + colour + ")\"", at)) !=
         std::string::npos;
         ++at) {
      ++count;
    }
    return count;
  };
  EXPECT_GE(lines("80,220,120"), 5u);   // on axis
  EXPECT_GE(lines("250,180,60"), 5u);   // 0.7 field
  EXPECT_GE(lines("235,90,200"), 5u);   // full field
  EXPECT_EQ(lines("90,230,240"), 1u);   // marginal
  EXPECT_GE(lines("255,255,255"), 3u);  // chief rays
  EXPECT_EQ(lines("240,240,240"), 1u);  // film
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
}

TEST_F(ScriptedViewer, SvgExportFollowsTheView) {
  const auto result = runScript(
      "wait-frames 2\nscreenshot-cross-section fit.svg\n"
      "zoom-cross-section 8\nwait-frames 2\nscreenshot-cross-section zoomed.svg\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto viewBoxWidth = [&](const std::string& name) {
    const std::string svg = testing::readWholeFile(scratch / name);
    const auto at = svg.find("viewBox=\"");
    if (at == std::string::npos) return 0.0;
    std::istringstream in(svg.substr(at + 9));
    double x = 0, y = 0, width = 0;
    in >> x >> y >> width;
    return width;
  };
  const double fit = viewBoxWidth("fit.svg");
  ASSERT_GT(fit, 0);
  EXPECT_NEAR(viewBoxWidth("zoomed.svg"), fit / 8, fit * 1e-3);
}

// The memory the next test gives the viewer: 2 GB of address space. AddressSanitizer reserves
// terabytes of address space for its shadow memory, so under it (the sanitizer build defines
// LENSLAB_ADDRESS_SANITIZER) `ulimit -v` would stop every start; ASan's own limits bound the same
// 2 GB instead: a single allocation over it fails, and the process is stopped once its resident
// memory (shadow included) reaches it.
#ifdef LENSLAB_ADDRESS_SANITIZER
constexpr const char* kTwoGigabytesOfMemory =
    "export ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:max_allocation_size_mb=2000:hard_rss_limit_mb=2000\" "
    "&& ";
#else
constexpr const char* kTwoGigabytesOfMemory = "ulimit -v 2000000 && ";
#endif

TEST_F(ScriptedViewer, HugeLengthsAndExtremeZoomDoNotExhaustMemory) {
  // Dashes along a 10 km axis once took gigabytes; the viewer now runs in 2 GB of memory.
  const auto result = runScript(
      "wait-frames 3\n"
      "set film-distance 1e7\n"
      "wait-frames 3\n"
      "screenshot film.png\n"
      "zoom-cross-section 1e9\n"  // the zoom limit, 1e5 pixels per mm
      "wait-frames 3\n"
      "screenshot zoomed.png\n"
      "set surface 9 thickness 1e12\n"
      "wait-frames 3\n"
      "zoom-cross-section 1e-30\n"
      "wait-frames 2\n"
      "zoom-cross-section 1e30\n"
      "wait-frames 2\n"
      "screenshot thick.png\n"
      "screenshot-cross-section thick.svg\n"
      "quit\n",
      kTwoGigabytesOfMemory);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  for (const char* name : {"film.png", "zoomed.png", "thick.png"}) {
    const auto shot = image(name);
    ASSERT_TRUE(shot.valid()) << name;
    EXPECT_EQ(shot.width, 1280);
  }
  EXPECT_LT(std::filesystem::file_size(scratch / "thick.svg"), 1'000'000u);
}

TEST_F(ScriptedViewer, BlockedRaysAreDrawnAndCanBeHidden) {
  // The fans overfill the pupil, so the stop and the rims block some of their rays.
  const auto result = runScript(
      "wait-frames 3\nscreenshot-cross-section shown.png\n"
      "set blocked-rays hide\nwait-frames 2\nscreenshot-cross-section hidden.png\n"
      "set blocked-rays show\nwait-frames 2\nscreenshot-cross-section again.png\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto shown = image("shown.png"), hidden = image("hidden.png"), again = image("again.png");
  ASSERT_TRUE(shown.valid() && hidden.valid() && again.valid());
  EXPECT_EQ(testing::countDifferentPixels(shown, again), 0u);
  // Hiding them removes fan-coloured pixels and adds none.
  const auto fanPixels = [](const testing::PngImage& picture) {
    int count = 0;
    for (int y = 0; y < picture.height; ++y) {
      for (int x = 0; x < picture.width; ++x) {
        const auto c = picture.at(x, y);
        // Green, orange or magenta, faint or not: far from the grey background and glass.
        const int spread = std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b});
        count += spread > 40 && !(c.b > c.r && c.b > c.g);
      }
    }
    return count;
  };
  const int withBlocked = fanPixels(shown), withoutBlocked = fanPixels(hidden);
  EXPECT_GT(withoutBlocked, 500);                // the passing rays are still drawn
  EXPECT_GT(withBlocked, withoutBlocked + 300);  // and the blocked ones were
  EXPECT_GT(testing::countDifferentPixels(shown, hidden, 12), 300u);
}

TEST_F(ScriptedViewer, Radius0OnAGlassSurfaceFlagsThatRow) {
  // The double-Gauss's stop is surface 6; surface 3 is glass (n_d 1.67 after it).
  const auto result = runScript(
      "wait-frames 2\nset surface 3 radius 0\nwait-frames 2\ndump-ui radius0.json\n"
      "undo\nset surface 6 n 1.5\nwait-frames 2\ndump-ui glass-stop.json\n"
      "screenshot-cross-section glass-stop.png\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto radius0 = json("radius0.json");
  // All on the edited row: the second stop, the glass after it, and (the row is now flat) its
  // crossing the surface before it.
  const std::vector<int> rows = problemRows(radius0);
  EXPECT_GE(rows.size(), 2u);
  EXPECT_EQ(std::count(rows.begin(), rows.end(), 3), static_cast<long>(rows.size()))
      << radius0["state"]["problems"];
  EXPECT_NE(radius0["state"]["problems"][0]["message"].get<std::string>().find("second aperture"),
            std::string::npos);
  EXPECT_FALSE(radius0["state"]["lens_valid"].get<bool>());
  const auto glassStop = json("glass-stop.json");
  EXPECT_EQ(problemRows(glassStop), (std::vector<int>{6})) << glassStop["state"]["problems"];
  EXPECT_FALSE(glassStop["state"]["lens_valid"].get<bool>());
}

TEST_F(ScriptedViewer, IndexBelow1AndAHugeApertureAreFlaggedAndThePreviewStaysFinite) {
  const auto result = runScript(
      "wait-spp 1\n"
      "set surface 2 n 0.5\n"
      "set surface 8 aperture 1e9\n"
      "wait-frames 2\n"
      "dump-ui flagged.json\n"
      "screenshot-render flagged.exr\n"
      "undo\nundo\n"
      "set stop-diameter 1e4\n"  // a 10 m stop: valid, the rims limit the bundle
      "wait-spp 2\n"
      "dump-ui huge-stop.json\n"
      "screenshot-render huge-stop.exr\n"
      "quit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // Row 8 twice: the aperture exceeds its radius and the 1e5 mm plausibility limit.
  EXPECT_EQ(problemRows(json("flagged.json")), (std::vector<int>{2, 8, 8}));
  EXPECT_TRUE(problemRows(json("huge-stop.json")).empty());
  for (const char* name : {"flagged.exr", "huge-stop.exr"}) {
    const render::ReadResult read = render::readImage(scratch / name);
    ASSERT_TRUE(read.ok) << read.error;
    double sum = 0;
    for (float value : read.image.rgb) {
      ASSERT_TRUE(std::isfinite(value)) << name;
      sum += value;
    }
    EXPECT_GT(sum / read.image.rgb.size(), 0.01) << name;  // a picture, not black
  }
}

TEST_F(ScriptedViewer, ADroppedBrokenFileKeepsTheCurrentLensAndSaysWhy) {
  std::ofstream(scratch / "broken.dat") << "# a lens\n29.475 3.76 1.67 25.2\nforty 1 1 20\n";
  const auto result = runScript(
      "wait-frames 2\nscreenshot-cross-section before.png\n"
      "drop " +
      (scratch / "broken.dat").string() +
      "\n"
      "wait-frames 3\nscreenshot-cross-section after.png\ndump-ui after.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto dump = json("after.json");
  EXPECT_NE(dump["state"]["lens_path"].get<std::string>().find("dgauss-50mm.dat"),
            std::string::npos);
  EXPECT_EQ(testing::countDifferentPixels(image("before.png"), image("after.png")), 0u);
  EXPECT_TRUE(loggedError(dump, "broken.dat:3:")) << dump["state"]["log"];
  // A dropped broken file is not a recent file.
  EXPECT_FALSE(inRecentFiles(dump, "broken.dat")) << dump["state"]["recent_files"];
}

// The first frame on screen is laid out like every later one: ImGui sizes tables and scrollbars
// from the frame before, so unprepared, the first frame showed the first-order data a letter per
// line. The lens is given on the command line, so the scene's camera does not replace it, and
// kept at its file's film distance (the settings), so focusing it once the scene has loaded does
// not change the panel either.
TEST_F(ScriptedViewer, TheFirstFrameIsLaidOutLikeTheNext) {
  std::filesystem::create_directories(scratch / "config" / "lenslab");
  std::ofstream(scratch / "config" / "lenslab" / "settings.json")
      << "{\"keep_lens_film_distance\": true}\n";
  const auto result = runScript(
      "screenshot first.png\nwait-spp 1\nwait-frames 3\nscreenshot later.png\n"
      "dump-ui later.json\nquit\n",
      "export LENSLAB_SETTINGS_IN_SCRIPTS=1 XDG_CONFIG_HOME='" + (scratch / "config").string() +
          "'; ",
      "--lens '" + std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat'");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto first = image("first.png"), later = image("later.png");
  ASSERT_TRUE(first.valid() && later.valid());
  const nlohmann::json dump = json("later.json");
  const auto& splitter = dump["widgets"]["layout/left-splitter"];
  const int right = static_cast<int>(splitter["x"].get<double>());
  const int top = static_cast<int>(splitter["y"].get<double>());
  const int bottom = top + static_cast<int>(splitter["height"].get<double>());
  ASSERT_GT(right, 100);
  int different = 0;
  for (int y = top; y < bottom; ++y) {
    for (int x = 0; x < right; ++x) different += first.at(x, y).maxDifference(later.at(x, y)) > 0;
  }
  EXPECT_EQ(different, 0) << "the lens panel changed between the first frame and a later one";
}

TEST_F(ScriptedViewer, ADroppedBrokenSceneKeepsTheCurrentSceneAndSaysWhy) {
  std::ofstream(scratch / "broken.pbrt") << "WorldBegin\nShape \"sphere\" \"float radius\" [x]\n";
  const auto result = runScript("wait-spp 1\ndrop " + (scratch / "broken.pbrt").string() +
                                "\nwait-frames 3\nwait-spp 2\ndump-ui after.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto dump = json("after.json");
  // The default scene stays, and renders on (wait-spp 2 got its samples).
  EXPECT_NE(dump["state"]["scene_path"].get<std::string>().find("default.pbrt"), std::string::npos);
  EXPECT_EQ(dump["state"]["scene_loading"], "");
  EXPECT_TRUE(loggedError(dump, "broken.pbrt:2:")) << dump["state"]["log"];
  EXPECT_FALSE(inRecentFiles(dump, "broken.pbrt")) << dump["state"]["recent_files"];
}

// An empty scene parses cleanly but has nothing to render: it used to replace the current one
// with a black picture (and a 35 mm film diagonal). It is refused like a broken one.
TEST_F(ScriptedViewer, ADroppedEmptySceneKeepsTheCurrentSceneAndSaysWhy) {
  std::ofstream(scratch / "empty.pbrt") << "# nothing but a comment\n";
  std::ofstream(scratch / "dark.pbrt")
      << "WorldBegin\nShape \"sphere\" \"float radius\" [1]\nWorldEnd\n";
  const auto result = runScript("wait-spp 1\ndrop " + (scratch / "empty.pbrt").string() +
                                "\nwait-frames 3\ndrop " + (scratch / "dark.pbrt").string() +
                                "\nwait-frames 3\nwait-spp 2\ndump-ui after.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto dump = json("after.json");
  EXPECT_NE(dump["state"]["scene_path"].get<std::string>().find("default.pbrt"), std::string::npos);
  EXPECT_TRUE(loggedError(dump, "empty.pbrt: error: the scene has no shapes"))
      << dump["state"]["log"];
  EXPECT_TRUE(loggedError(dump, "dark.pbrt: error: the scene has no lights"))
      << dump["state"]["log"];
  EXPECT_FALSE(inRecentFiles(dump, "empty.pbrt")) << dump["state"]["recent_files"];
  EXPECT_FALSE(inRecentFiles(dump, "dark.pbrt")) << dump["state"]["recent_files"];
}

TEST_F(ScriptedViewer, ABrokenSceneOnTheCommandLineEndsTheSessionWithItsError) {
  std::ofstream(scratch / "broken.pbrt") << "WorldBegin\nShape \"sphere\" \"float radius\" [x]\n";
  const auto result =
      runScript("wait-spp 1\nquit\n", "", "--scene '" + (scratch / "broken.pbrt").string() + "'");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("broken.pbrt:2:"), std::string::npos) << result.err;
}

// A scene of a million triangles takes about a second to parse and build (two on a busy
// machine): it loads while the window draws, which shows it loading, and then renders it.
TEST_F(ScriptedViewer, AFrameIsDrawnWhileALargeSceneLoads) {
  writeTerrainScene("terrain.pbrt",
                    "Camera \"perspective\" \"float fov\" [45]\n"
                    "Film \"image\" \"integer xresolution\" [300] \"integer yresolution\" [200]\n");
  const auto result = runScript(
      "dump-ui first-frame.json\nwait-spp 1\ndump-ui loaded.json\n"
      "screenshot-render terrain.png\nquit\n",
      "", "--scene terrain.pbrt");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // The first frame came while the scene loaded, and said so.
  const auto first = json("first-frame.json");
  EXPECT_EQ(first["state"]["scene_loading"], "terrain.pbrt") << first["state"]["log"];
  const auto loaded = json("loaded.json");
  EXPECT_EQ(loaded["state"]["scene_path"], "terrain.pbrt");
  EXPECT_EQ(loaded["state"]["scene_loading"], "");
  // The scene, seen through the lens: the lit terrain, not a black frame.
  EXPECT_GT(testing::meanBrightness(image("terrain.png")), 20.0);
}

// A lens opened while a scene loads is the later choice: the scene, once loaded, keeps it rather
// than bringing its own (a script's load-lens right after start-up used to lose that race to the
// default scene now and then), and focuses it at the scene's focus distance, as opening it over
// the loaded scene would have.
TEST_F(ScriptedViewer, ALensOpenedWhileTheSceneLoadsIsKeptAndFocusedForTheScene) {
  const std::string lenses = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
  writeTerrainScene("terrain-lens.pbrt",
                    "Camera \"realistic\" \"string lensfile\" \"" + lenses +
                        "dgauss-50mm.dat\" \"float aperturediameter\" [10] \"float focusdistance\" "
                        "[3]\nFilm \"image\" \"integer xresolution\" [300] \"integer "
                        "yresolution\" [200]\n");
  const auto result = runScript("load-lens " + lenses +
                                    "dgauss-100mm.dat\ndump-ui opened.json\n"
                                    "wait-scene-load\nwait-frames 1\ndump-ui loaded.json\n"
                                    "undo\nwait-frames 1\ndump-ui undone.json\nquit\n",
                                "", "--scene terrain-lens.pbrt");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto opened = json("opened.json");
  ASSERT_EQ(opened["state"]["scene_loading"], "terrain-lens.pbrt")
      << "the scene loaded before the lens opened: the test did not race";
  const auto loaded = json("loaded.json");
  EXPECT_EQ(loaded["state"]["scene_path"], "terrain-lens.pbrt");
  const std::string lensPath = loaded["state"]["lens_path"];
  EXPECT_NE(lensPath.find("dgauss-100mm.dat"), std::string::npos) << lensPath;
  EXPECT_TRUE(logged(loaded, "Kept the lens opened while the scene loaded"))
      << loaded["state"]["log"];
  // Focused at the scene's "focusdistance" [3] (metres from the film), by the optics library's
  // real-ray focus of the lens file at the film distance the viewer reports.
  const optics::LoadedLens file = optics::loadLens(lenses + "dgauss-100mm.dat");
  ASSERT_TRUE(file.ok());
  const double filmMm = loaded["state"]["film_distance_mm"].get<double>();
  const optics::FocusResult object =
      optics::objectDistanceForFilmDistance(*file.system->withFilmDistance(filmMm), filmMm);
  ASSERT_TRUE(object.ok()) << object.whyNot;
  EXPECT_NEAR(*object.valueMm, 3000.0, 3.0);
  // Focusing is an undo step of its own: undone, the lens is as it opened, at its file's film
  // distance (there was no scene to focus for yet).
  const auto undone = json("undone.json");
  EXPECT_NE(undone["state"]["lens_path"].get<std::string>().find("dgauss-100mm.dat"),
            std::string::npos);
  EXPECT_DOUBLE_EQ(undone["state"]["film_distance_mm"].get<double>(),
                   file.system->filmDistanceMm());
}

// A scene that sets a film distance rather than a focus distance (the course's camera): a lens
// opened over it keeps its file's film distance, so one opened while it loads goes there too,
// not where it was focused for the scene before.
TEST_F(ScriptedViewer, ALensOpenedWhileACourseSceneLoadsGoesToItsFilesFilmDistance) {
  const std::string lenses = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
  writeTerrainScene("terrain-course.pbrt",
                    "Camera \"realistic\" \"string specfile\" \"" + lenses +
                        "dgauss-50mm.dat\" \"float filmdistance\" 36.77 \"float "
                        "aperture_diameter\" 17.1 \"float filmdiag\" 43\n");
  // The course scene dropped on the window over the default scene (whose chart, 3.6 m away, is
  // in focus), and the lens opened while it loads.
  const auto result =
      runScript("wait-scene-load\ndrop terrain-course.pbrt\nwait-frames 1\nload-lens " + lenses +
                    "dgauss-100mm.dat\ndump-ui opened.json\nwait-scene-load\nwait-frames 1\n"
                    "dump-ui loaded.json\nquit\n",
                "", "");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto opened = json("opened.json");
  ASSERT_EQ(opened["state"]["scene_loading"], "terrain-course.pbrt")
      << "the scene loaded before the lens opened: the test did not race";
  const optics::LoadedLens file = optics::loadLens(lenses + "dgauss-100mm.dat");
  ASSERT_TRUE(file.ok());
  // While the course scene loads, the lens opened focused for the default scene ...
  EXPECT_GT(opened["state"]["film_distance_mm"].get<double>(), file.system->filmDistanceMm() + 1.0);
  // ... and once it has loaded, it is at its file's film distance, and the log says why.
  const auto loaded = json("loaded.json");
  EXPECT_EQ(loaded["state"]["scene_path"], "terrain-course.pbrt");
  EXPECT_NE(loaded["state"]["lens_path"].get<std::string>().find("dgauss-100mm.dat"),
            std::string::npos);
  EXPECT_DOUBLE_EQ(loaded["state"]["film_distance_mm"].get<double>(),
                   file.system->filmDistanceMm());
  EXPECT_TRUE(logged(loaded, "the scene sets a film distance, not a focus distance"))
      << loaded["state"]["log"];
}

// ... but an edit made after opening it, while the scene still loads, is the user's: the film
// distance set then stays.
TEST_F(ScriptedViewer, ALensEditedWhileTheSceneLoadsKeepsItsEdit) {
  const std::string lenses = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
  writeTerrainScene("terrain-lens.pbrt", "Camera \"realistic\" \"string lensfile\" \"" + lenses +
                                             "dgauss-50mm.dat\" \"float focusdistance\" [3]\n");
  const auto result = runScript("load-lens " + lenses +
                                    "dgauss-100mm.dat\nset film-distance 97.5\n"
                                    "dump-ui opened.json\nwait-scene-load\nwait-frames 1\n"
                                    "dump-ui loaded.json\nquit\n",
                                "", "--scene terrain-lens.pbrt");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  ASSERT_EQ(json("opened.json")["state"]["scene_loading"], "terrain-lens.pbrt")
      << "the scene loaded before the lens opened: the test did not race";
  const auto loaded = json("loaded.json");
  EXPECT_EQ(loaded["state"]["scene_path"], "terrain-lens.pbrt");
  EXPECT_DOUBLE_EQ(loaded["state"]["film_distance_mm"].get<double>(), 97.5);
}

TEST_F(ScriptedViewer, ScriptEditsAreLogged) {
  const auto result =
      runScript("set film-distance 40\nundo\nwait-frames 1\ndump-ui log.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json dump = json("log.json");
  std::string log;
  for (const auto& entry : dump["state"]["log"]) log += entry["text"].get<std::string>() + "\n";
  EXPECT_NE(log.find("script: set film distance to 40 mm"), std::string::npos) << log;
  EXPECT_NE(log.find("script: undo"), std::string::npos) << log;
}

TEST_F(ScriptedViewer, UnwritableScreenshotPathIsAnErrorNotACrash) {
  const auto result = runScript("wait-frames 1\nscreenshot /no/such/dir/x.png\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("/no/such/dir/x.png"), std::string::npos) << result.err;
}

// Under Xvfb the GL is llvmpipe, so the viewer repaints only what changed (partial_repaint.h).
// LENSLAB_CHECK_REPAINT=1 follows every partial repaint with a full one and reports any pixel
// that differs: edits of every kind, new preview passes, the exposure, the camera, undo. And
// check-window reads the window back from the X server: it must show the drawn frame, so every
// repainted region was copied to the screen, where it belongs.
constexpr const char* kRepaintScript =
    "wait-spp 2\n"
    "check-window\n"
    "set surface 3 radius 40\n"
    "wait-spp 2\n"
    "check-window\n"
    "set film-distance 37\n"
    "wait-spp 1\n"
    "set exposure 1\n"
    "wait-frames 3\n"
    "check-window\n"
    "set camera pinhole\n"
    "wait-spp 1\n"
    "set blocked-rays hide\n"
    "undo\n"
    "undo\n"
    "wait-spp 4\n"
    "check-window\n"
    "quit\n";

TEST_F(ScriptedViewer, PartialRepaintsEqualFullRepaints) {
  const auto result =
      runScript(kRepaintScript, "export LENSLAB_CHECK_REPAINT=1; ", "--stats-json stats.json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(result.err.find("repaint check"), std::string::npos) << result.err;
  // And partial repaints did happen: most redrawn frames were new preview passes, which repaint
  // the preview panel alone.
  const nlohmann::json stats = json("stats.json");
  EXPECT_TRUE(stats["partial_repaint"].get<bool>()) << stats.dump();
  EXPECT_LT(stats["repainted_fraction_median"].get<double>(), 0.6) << stats.dump();
}

// --stats-json reports the feel figures of issue 5: two edits make two measured edits, each
// with its renderer's part no longer than the whole wait, and the opening render apart.
TEST_F(ScriptedViewer, StatsJsonMeasuresTheEditsAndTheOpeningApart) {
  // (A few frames after each pass: an edit in the frame that shows its predecessor's pass
  // would supersede that pass before it counted; ViewerStats' tests.)
  const auto result = runScript(
      "wait-spp 1\nwait-frames 3\nset film-distance 37\nwait-spp 1\nwait-frames 3\n"
      "set film-distance 37.2\nwait-spp 1\nwait-frames 3\nquit\n",
      "", "--stats-json stats.json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const nlohmann::json stats = json("stats.json");
  ASSERT_EQ(stats["edits_measured"].get<int>(), 2) << stats.dump();
  const auto waits = stats["edit_to_first_pass_ms"].get<std::vector<double>>();
  const auto renders = stats["first_pass_render_ms"].get<std::vector<double>>();
  ASSERT_EQ(waits.size(), 2u);
  ASSERT_EQ(renders.size(), 2u);
  for (std::size_t i = 0; i < waits.size(); ++i) {
    EXPECT_GT(renders[i], 0.0);
    EXPECT_LE(renders[i], waits[i]);
  }
  ASSERT_TRUE(stats["open_to_first_pass_ms"].is_number()) << stats.dump();
  EXPECT_GT(stats["open_to_first_pass_ms"].get<double>(), 0.0);
  EXPECT_GT(stats["fps_median"].get<double>(), 0.0);
}

TEST_F(ScriptedViewer, TheRepaintChecksCatchAMissedRegion) {
  // LENSLAB_CHECK_REPAINT=shrink repaints only the left half of each damaged region: the
  // comparison with a full repaint says so, and the window on screen lacks the other halves.
  const auto result = runScript(kRepaintScript, "export LENSLAB_CHECK_REPAINT=shrink; ");
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_NE(result.err.find("repaint check"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("check-window: "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("pixels of the window differ from the drawn frame"), std::string::npos)
      << result.err;
}

// Issue 20: with the iris of the double-Gauss 50 mm opened to 500 mm (its neighbours are 17-18 mm
// across) the first-order data said f/0.07 and "no real image", and the fans collapsed. The
// section now names the surface that limits the axial beam and the f-number of the beam that
// passes, the same as for the stock lens.
TEST_F(ScriptedViewer, TheIrisOpenedPastTheRimsKeepsTheStockBeamFigures) {
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  const auto result = runScript("load-lens " + lens +
                                "\nwait-frames 3\ndump-ui stock.json\n"
                                "set stop-diameter 500\nwait-frames 3\ndump-ui wide.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  for (const char* name : {"stock.json", "wide.json"}) {
    SCOPED_TRACE(name);
    const auto shown = json(name)["state"]["first_order"];
    ASSERT_TRUE(shown.is_object());
    EXPECT_EQ(shown["f_number"], "f/2.07");
    const std::string beam = shown["axial_beam"];
    EXPECT_EQ(beam.rfind("surface 3, before the iris: working f/2.03", 0), 0u) << beam;
    EXPECT_NE(shown["unvignetted"].get<std::string>().find(" deg"), std::string::npos);
  }
  EXPECT_EQ(json("wide.json")["state"]["stop_diameter_mm"], 500.0);
}

}  // namespace
}  // namespace lenslab
