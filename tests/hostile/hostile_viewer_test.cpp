// Drops the bad-input catalogue (hostile_cases.h) on the real viewer, one after another in one
// session: each must be reported in the log at its place, briefly, and the viewer must keep its
// lens and scene, draw them as before and go on rendering.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "hostile/hostile_cases.h"
#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

TEST(HostileDrops, EachIsLoggedAndTheViewerKeepsItsLensAndScene) {
  const fs::path scratch = testing::makeTestDirectory("hostile-viewer");
  const fs::path cases = scratch / "cases";
  fs::create_directories(cases);
  std::vector<hostile::HostileCase> dropped;
  for (hostile::HostileCase& hostile : hostile::buildCases(cases)) {
    // The viewer has no --resolution; of the NaN/inf sweeps, the NaN cases (the same reader
    // refuses inf there, as the CLI test shows).
    if (!hostile.extraArguments.empty()) continue;
    const std::string name = hostile.file.filename().string();
    if (name.rfind("every-number", 0) == 0 && name.find("-nan.") == std::string::npos) continue;
    dropped.push_back(hostile);
  }
  std::string script =
      "set auto-exposure off\nwait-spp 2\nscreenshot-cross-section before.png\n"
      "screenshot-render before-render.png\n";
  for (const hostile::HostileCase& hostile : dropped) {
    script += "drop " + hostile.file.string() + "\nwait-frames 2\n";
    if (hostile.scene) script += "wait-scene-load\n";
  }
  script +=
      "wait-frames 2\nscreenshot-cross-section after.png\nwait-spp 4\n"
      "screenshot-render after-render.png\ndump-ui after.json\nquit\n";
  std::ofstream(scratch / "commands.script") << script;
  const auto result = testing::runProcess("cd '" + scratch.string() + "' && timeout 600 '" +
                                              LENSLAB_BINARY + "' --size 1280x800 --script '" +
                                              (scratch / "commands.script").string() + "'",
                                          scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err.substr(0, 4000);

  std::ifstream dumpFile(scratch / "after.json");
  const nlohmann::json dump = nlohmann::json::parse(dumpFile, nullptr, false);
  ASSERT_TRUE(dump.is_object());
  // The lens and the scene of the start, unchanged on screen, and the preview rendered on.
  EXPECT_NE(dump["state"]["lens_path"].get<std::string>().find("dgauss-50mm.dat"),
            std::string::npos);
  EXPECT_NE(dump["state"]["scene_path"].get<std::string>().find("default.pbrt"), std::string::npos);
  const auto before = testing::PngImage::load(scratch / "before.png");
  const auto after = testing::PngImage::load(scratch / "after.png");
  ASSERT_TRUE(before.valid() && after.valid());
  EXPECT_EQ(testing::countDifferentPixels(before, after), 0u);
  const auto render = testing::PngImage::load(scratch / "after-render.png");
  ASSERT_TRUE(render.valid());
  EXPECT_GT(testing::meanBrightness(render), 20.0);  // a picture, not black

  // Each case has its error in the log, at its place, with what is wrong, in a short entry.
  std::vector<std::string> errors;
  for (const auto& entry : dump["state"]["log"]) {
    if (entry["level"] == "error") errors.push_back(entry["text"].get<std::string>());
  }
  for (const hostile::HostileCase& hostile : dropped) {
    const std::string name = hostile.file.filename().string();
    const std::string place = hostile::placeOf(hostile);
    bool found = false;
    for (const std::string& error : errors) {
      if (error.find(place) == std::string::npos || error.find(hostile.expect) == std::string::npos)
        continue;
      found = true;
      EXPECT_LT(error.size(), 4096u) << name;
    }
    EXPECT_TRUE(found) << "no error with '" << place << "' and '" << hostile.expect << "'";
  }
  for (const auto& path : dump["state"]["recent_files"]) {
    EXPECT_EQ(path.get<std::string>().find(cases.string()), std::string::npos) << path;
  }
}

}  // namespace
}  // namespace lenslab
