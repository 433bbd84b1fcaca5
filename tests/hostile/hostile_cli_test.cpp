// Runs every case of the bad-input catalogue (hostile_cases.h) through the real CLI: each must
// end with a clear, short message at its place, a non-zero exit (not a crash), no output file and
// no temporary left behind, in bounded time.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "hostile/hostile_cases.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

namespace fs = std::filesystem;

std::string lenslabHeadless(const std::string& arguments) {
  return std::string("env -u DISPLAY -u WAYLAND_DISPLAY timeout 120 '") + LENSLAB_BINARY + "' " +
         arguments;
}

// Files in `directory` whose name an atomic write gives its temporary (common/atomic_file.cpp).
std::vector<std::string> temporaries(const fs::path& directory) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-lenslab-") != std::string::npos) found.push_back(name);
  }
  return found;
}

class HostileFiles : public ::testing::Test {
 protected:
  // Runs `arguments` and checks the refusal of `hostile`; `output` must not appear.
  void expectRefused(const hostile::HostileCase& hostile, const std::string& arguments,
                     const fs::path& output) {
    const std::string name = hostile.file.filename().string();
    SCOPED_TRACE(name + ": lenslab " + arguments);
    const auto start = std::chrono::steady_clock::now();
    const auto result = testing::runProcess(lenslabHeadless(arguments), scratch);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // 1: a bad file; 2: a bad option value (--resolution). Not 124 (timeout) nor a signal (-1).
    EXPECT_TRUE(result.exitCode == 1 || result.exitCode == 2) << result.exitCode << result.err;
    EXPECT_LT(seconds, 60.0);
    // The message names the file and where, and what is wrong, in a few lines at most.
    const std::string place = hostile::placeOf(hostile);
    EXPECT_NE(result.err.find(place), std::string::npos)
        << "expected '" << place << "' in: " << result.err.substr(0, 2000);
    EXPECT_NE(result.err.find(hostile.expect), std::string::npos)
        << "expected '" << hostile.expect << "' in: " << result.err.substr(0, 2000);
    if (!hostile.at.empty()) {  // a parse error says so ("file:line:column: error: ...")
      EXPECT_NE(result.err.find(place + " error: "), std::string::npos)
          << result.err.substr(0, 2000);
    }
    EXPECT_LT(result.err.size(), 4096u) << result.err.substr(0, 2000);
    EXPECT_FALSE(fs::exists(output));
    EXPECT_TRUE(temporaries(scratch).empty());
  }

  fs::path scratch = testing::makeTestDirectory("hostile-cli");
};

TEST_F(HostileFiles, TheSweepBasesAreValid) {
  // The NaN/inf cases are errors because of the one number each replaces, not of the rest.
  const auto scene = testing::runProcess(
      lenslabHeadless("render '" + std::string(LENSLAB_SOURCE_DIR) +
                      "/tests/hostile/sweep/every-number.pbrt' --spp 1 --out '" +
                      (scratch / "base.png").string() + "'"),
      scratch);
  EXPECT_EQ(scene.exitCode, 0) << scene.err;
  EXPECT_TRUE(fs::exists(scratch / "base.png"));
}

TEST_F(HostileFiles, EachIsRefusedWithItsPlaceAndNothingIsWritten) {
  const std::vector<hostile::HostileCase> cases = hostile::buildCases(scratch);
  ASSERT_GT(cases.size(), 100u);  // the committed files, the generated ones and the sweeps
  int scenes = 0, lenses = 0;
  for (const hostile::HostileCase& hostile : cases) {
    const std::string quoted = "'" + hostile.file.string() + "'";
    if (hostile.scene) {
      const fs::path output = scratch / (hostile.file.stem().string() + "-out.png");
      expectRefused(
          hostile,
          "render " + quoted + " --spp 1 --out '" + output.string() + "' " + hostile.extraArguments,
          output);
      ++scenes;
    } else {
      // info and focus write nothing; render --lens would write the picture (the sweep's cases
      // through info and focus only: the same reader refuses them for render).
      expectRefused(hostile, "info " + quoted, scratch / "none");
      expectRefused(hostile, "focus " + quoted + " --object-distance inf", scratch / "none");
      ++lenses;
      if (hostile.file.filename().string().rfind("every-number", 0) == 0) continue;
      const fs::path output = scratch / (hostile.file.stem().string() + "-out.png");
      expectRefused(hostile,
                    "render '" + (scratch / "every-number.pbrt").string() + "' --lens " + quoted +
                        " --spp 1 --out '" + output.string() + "'",
                    output);
    }
  }
  EXPECT_GT(scenes, 60);
  EXPECT_GT(lenses, 40);
}

}  // namespace
}  // namespace lenslab
