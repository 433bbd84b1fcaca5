// "It is idle when nothing changes": once the preview has refined to its last sample, the viewer
// (its UI thread, render workers and every other thread) waits for input instead of looping.

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "support/background_process.h"
#include "support/run_process.h"
#include "support/xdotool_session.h"

namespace lenslab {
namespace {

// CPU time (user + system) of all of a process's threads so far, in milliseconds.
double processCpuMs(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  // Fields after the command name (which is in parentheses and may hold spaces): state is the
  // 3rd field, utime the 14th, stime the 15th.
  std::istringstream fields(text.substr(text.rfind(')') + 2));
  std::string field;
  double ticks = 0;
  for (int index = 3; fields >> field && index <= 15; ++index) {
    if (index >= 14) ticks += std::stod(field);
  }
  return ticks * 1000.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
}

TEST(IdleViewer, UsesAlmostNoCpuOnceThePreviewHasConverged) {
  const auto scratch = testing::makeTestDirectory("idle");
  // The script ends without quitting once the preview has its last sample: the session goes on as
  // an ordinary one. The default scene at a film of 48 x 32 pixels (RGB) keeps that quick: at
  // the preview's size its 1024 samples per pixel took over two minutes on a loaded machine.
  std::string scene =
      testing::readWholeFile(std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = scene.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    scene.replace(at, from.size(), to);
  };
  replace("\"../lenses/", "\"" + std::string(LENSLAB_SOURCE_DIR) + "/lenses/");
  replace("[600] \"integer yresolution\" [400]", "[48] \"integer yresolution\" [32]");
  std::ofstream(scratch / "small.pbrt") << scene;
  std::ofstream(scratch / "commands.script")
      << "load-scene small.pbrt\nset spectral off\nwait-spp 1024\ndump-ui converged.json\n";
  testing::BackgroundProcess viewer("cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
                                    "' --size 360x270 --script commands.script 2>stderr.txt");
  ASSERT_TRUE(testing::waitForFile(scratch / "converged.json", std::chrono::seconds(150)))
      << testing::readWholeFile(scratch / "stderr.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the last frames
  const double before = processCpuMs(viewer.pid());
  constexpr double kSeconds = 3.0;
  std::this_thread::sleep_for(std::chrono::duration<double>(kSeconds));
  const double used = processCpuMs(viewer.pid()) - before;
  // Waking four times a second took 10 ms in 3 s here; frames at 60 per second even without
  // repainting took 100 ms, and a busy loop would take a whole core.
  EXPECT_LT(used, 0.015 * kSeconds * 1000.0) << used << " ms of CPU in " << kSeconds << " s";
}

}  // namespace
}  // namespace lenslab
