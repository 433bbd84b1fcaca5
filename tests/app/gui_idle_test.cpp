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
  // The script ends without quitting once the preview has its last sample (a small window keeps
  // that quick): the session goes on as an ordinary one.
  std::ofstream(scratch / "commands.script") << "wait-spp 1024\ndump-ui converged.json\n";
  testing::BackgroundProcess viewer("cd '" + scratch.string() + "' && exec '" + LENSLAB_BINARY +
                                    "' --size 360x270 --script commands.script 2>stderr.txt");
  ASSERT_TRUE(testing::waitForFile(scratch / "converged.json", std::chrono::seconds(120)))
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
