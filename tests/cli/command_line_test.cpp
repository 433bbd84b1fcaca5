// The lenslab binary's command line, run as a real process without a display.

#include <gtest/gtest.h>

#include <algorithm>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

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

// A usage error is one line naming the command and the problem, then the command's --help hint:
// not the whole help text (which it used to print, burying the line that matters).
TEST_F(CommandLine, UsageErrorsAreOneLineAndTheCommandsHelpHint) {
  const std::string scene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt";
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  struct Case {
    std::string arguments, command, mentioned;
  };
  const Case cases[] = {
      {"--frobnicate", "lenslab", "--frobnicate"},
      {"--frames 0", "lenslab", "--frames"},
      {"render " + scene + " --spp 0", "lenslab render", "--spp"},
      {"render " + scene + " --integrator bidir", "lenslab render", "--integrator"},
      {"render " + scene + " --resolution 0x0", "lenslab render", "--resolution"},
      {"render", "lenslab render", "scene"},
      {"info --wavelength 100 " + lens, "lenslab info",
       "--wavelength: '100' is not between 200 and 2000 nm"},
      {"info", "lenslab info", "LENS"},
      {"focus --object-distance far " + lens, "lenslab focus", "--object-distance"},
  };
  for (const auto& c : cases) {
    const auto result = testing::runProcess(lenslab(c.arguments), scratch);
    EXPECT_EQ(result.exitCode, 2) << c.arguments;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 2)
        << c.arguments << ": " << result.err;
    EXPECT_EQ(result.err.rfind(c.command + ": ", 0), 0u) << c.arguments << ": " << result.err;
    const std::string firstLine = result.err.substr(0, result.err.find('\n'));
    EXPECT_NE(firstLine.find(c.mentioned), std::string::npos) << c.arguments << ": " << firstLine;
    EXPECT_NE(result.err.find("\nRun '" + c.command + " --help' for its options.\n"),
              std::string::npos)
        << c.arguments << ": " << result.err;
    EXPECT_EQ(result.err.find("Usage"), std::string::npos) << c.arguments;
    EXPECT_TRUE(result.out.empty()) << c.arguments;
  }
}

// The viewer's --script help points at the file that lists the script commands.
TEST_F(CommandLine, ScriptHelpNamesTheRealPathOfTheCommands) {
  const auto result = testing::runProcess(lenslab("--help"), scratch);
  ASSERT_EQ(result.exitCode, 0);
  const std::size_t at = result.out.find("src/app/automation/script.h");
  ASSERT_NE(at, std::string::npos) << result.out;
  EXPECT_TRUE(
      std::filesystem::exists(std::string(LENSLAB_SOURCE_DIR) + "/src/app/automation/script.h"));
  EXPECT_EQ(result.out.find("src/app/script.h"), std::string::npos) << result.out;
  // The viewer's own help keeps its footer.
  EXPECT_NE(result.out.find("With no subcommand, opens the viewer"), std::string::npos);
}

// A subcommand's help is about the subcommand: not the viewer's footer nor its options.
TEST_F(CommandLine, SubcommandHelpHasNothingOfTheViewer) {
  for (const char* subcommand : {"info", "focus", "analyze", "render"}) {
    const auto result = testing::runProcess(lenslab(std::string(subcommand) + " --help"), scratch);
    ASSERT_EQ(result.exitCode, 0) << subcommand;
    EXPECT_NE(result.out.find(std::string("lenslab ") + subcommand), std::string::npos)
        << result.out;
    for (const char* viewerOnly :
         {"opens the viewer", "--screenshot", "--script", "--wait-spp", "--frames"}) {
      EXPECT_EQ(result.out.find(viewerOnly), std::string::npos)
          << subcommand << " --help shows " << viewerOnly << ":\n"
          << result.out;
    }
  }
}

// A misspelt subcommand or option is answered with the nearest one, in the error's one line;
// a word near nothing gets no guess.
TEST_F(CommandLine, MisspeltNamesAreAnsweredWithTheNearestOne) {
  const std::string lens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
  const std::string scene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt";
  struct Case {
    std::string arguments, command, suggestion;
  };
  const Case cases[] = {
      {"rendr x.pbrt", "lenslab", "did you mean `render`?"},
      {"anlayze " + lens, "lenslab", "did you mean `analyze`?"},
      {"analyze " + lens + " --ony spot", "lenslab analyze", "did you mean `--only`?"},
      {"analyze " + lens + " --film-distnace 40", "lenslab analyze",
       "did you mean `--film-distance`?"},
      {"render " + scene + " --sp 4", "lenslab render", "did you mean `--spp`?"},
      {"--screenshots x.png", "lenslab", "did you mean `--screenshot`?"},
  };
  for (const auto& c : cases) {
    const auto result = testing::runProcess(lenslab(c.arguments), scratch);
    EXPECT_EQ(result.exitCode, 2) << c.arguments << ": " << result.err;
    const std::string firstLine = result.err.substr(0, result.err.find('\n'));
    EXPECT_EQ(firstLine.rfind(c.command + ": ", 0), 0u) << c.arguments << ": " << result.err;
    EXPECT_NE(firstLine.find(c.suggestion), std::string::npos) << c.arguments << ": " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 2) << result.err;
  }
  for (const char* far : {"--frobnicate", "render-everything-now", "-q"}) {
    const auto result = testing::runProcess(lenslab(far), scratch);
    EXPECT_EQ(result.exitCode, 2) << far;
    EXPECT_EQ(result.err.find("did you mean"), std::string::npos) << far << ": " << result.err;
  }
}

TEST_F(CommandLine, BadSizesAreClearErrorsWithExit2) {
  for (const char* size : {"0x0", "garbage", "10x-3"}) {
    const auto result =
        testing::runProcess(lenslab("--screenshot x.png --size " + std::string(size)), scratch);
    EXPECT_EQ(result.exitCode, 2) << size;
    EXPECT_NE(result.err.find("--size"), std::string::npos) << size << ": " << result.err;
  }
}

// The viewer's file argument (the desktop entry's lenslab %f) is checked before any window opens.
TEST_F(CommandLine, AFileArgumentMustExistAndNotRepeatTheLensOrScene) {
  const auto missing = testing::runProcess(lenslab("no-such-lens.dat"), scratch);
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find("does not exist: no-such-lens.dat"), std::string::npos) << missing.err;

  const std::string lenses = std::string(LENSLAB_SOURCE_DIR) + "/lenses/";
  const auto twoLenses = testing::runProcess(
      lenslab("--lens " + lenses + "wide-22mm.dat " + lenses + "dgauss-50mm.dat"), scratch);
  EXPECT_EQ(twoLenses.exitCode, 2);
  EXPECT_NE(twoLenses.err.find("dgauss-50mm.dat and --lens both name the lens"), std::string::npos)
      << twoLenses.err;

  const std::string scene = std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt";
  const auto twoScenes = testing::runProcess(lenslab("--scene " + scene + " " + scene), scratch);
  EXPECT_EQ(twoScenes.exitCode, 2);
  EXPECT_NE(twoScenes.err.find("and --scene both name the scene"), std::string::npos)
      << twoScenes.err;

  // A lens beside a --scene is no conflict: it gets as far as looking for a display.
  const auto lensAndScene =
      testing::runProcess(lenslab("--scene " + scene + " " + lenses + "wide-22mm.dat"), scratch);
  EXPECT_EQ(lensAndScene.exitCode, 2);
  EXPECT_NE(lensAndScene.err.find("no display"), std::string::npos) << lensAndScene.err;
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
