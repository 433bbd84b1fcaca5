// The lenslab binary's command line, run as a real process without a display.

#include <gtest/gtest.h>

#include <algorithm>

#include "support/run_process.h"

namespace lenslab {
namespace {

std::string lenslab(const std::string& arguments) {
  return std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + LENSLAB_BINARY + "' " + arguments;
}

class CommandLine : public ::testing::Test {
 protected:
  std::filesystem::path scratch = testing::makeTestDirectory("cli");
};

TEST_F(CommandLine, HelpWorksWithoutADisplay) {
  const auto result = testing::runProcess(lenslab("--help"), scratch);
  EXPECT_EQ(result.exitCode, 0);
  EXPECT_NE(result.out.find("--screenshot"), std::string::npos);
  EXPECT_NE(result.out.find("Usage"), std::string::npos);
}

TEST_F(CommandLine, VersionWorksWithoutADisplay) {
  const auto result = testing::runProcess(lenslab("--version"), scratch);
  EXPECT_EQ(result.exitCode, 0);
  EXPECT_NE(result.out.find("lenslab 0."), std::string::npos);
}

TEST_F(CommandLine, UnknownFlagPrintsUsageAndExits2) {
  const auto result = testing::runProcess(lenslab("--frobnicate"), scratch);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("--frobnicate"), std::string::npos);
  EXPECT_NE(result.err.find("Usage"), std::string::npos);
}

TEST_F(CommandLine, BadSizesAreClearErrorsWithExit2) {
  for (const char* size : {"0x0", "garbage", "10x-3"}) {
    const auto result =
        testing::runProcess(lenslab("--screenshot x.png --size " + std::string(size)), scratch);
    EXPECT_EQ(result.exitCode, 2) << size;
    EXPECT_NE(result.err.find("--size"), std::string::npos) << size << ": " << result.err;
  }
}

TEST_F(CommandLine, NoDisplayIsOneLineAndExit2) {
  const auto result = testing::runProcess(lenslab(""), scratch);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("no display"), std::string::npos);
  EXPECT_NE(result.err.find("lenslab render"), std::string::npos);
  EXPECT_TRUE(result.out.empty());
}

TEST_F(CommandLine, UnreachableDisplayIsOneLineAndExit2) {
  const auto result = testing::runProcess(
      "env -u WAYLAND_DISPLAY DISPLAY=:987 '" + std::string(LENSLAB_BINARY) + "'", scratch);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

}  // namespace
}  // namespace lenslab
