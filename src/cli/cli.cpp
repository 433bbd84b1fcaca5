#include "cli/cli.h"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "app/viewer.h"
#include "cli/analyze_command.h"
#include "cli/convert_command.h"
#include "cli/exit_codes.h"
#include "cli/focus_command.h"
#include "cli/glass_command.h"
#include "cli/info_command.h"
#include "cli/nearest_name.h"
#include "cli/render_command.h"
#include "cli/size_argument.h"
#include "cli/subcommand.h"
#include "cli/usage_error.h"
#include "optics/lens_file_formats.h"

namespace lenslab::cli {

namespace {

constexpr int kInternalError = 1;

struct ViewerArguments {
  std::string lensPath;
  std::string scenePath;
  std::string filePath;  // a lens or scene named without --lens/--scene (the desktop entry's %f)
  std::string screenshotPath;
  std::string scriptPath;
  std::string statsJsonPath;
  int frames = 10;
  int waitSpp = 0;  // 0: not given (the first pass, at most 60 s)
  double waitSeconds = 0;
  std::string size;
};

void addViewerOptions(CLI::App& app, ViewerArguments& arguments) {
  app.add_option("--lens", arguments.lensPath,
                 "Lens file to open (" + optics::lensFileExtensionsText() + ")")
      ->check(CLI::ExistingFile);
  app.add_option("--scene", arguments.scenePath, "Scene file to open (.pbrt)")
      ->check(CLI::ExistingFile);
  app.add_option("file", arguments.filePath,
                 "Lens (" + optics::lensFileExtensionsText() +
                     ") or scene (.pbrt) to open, as --lens or --scene would")
      ->check(CLI::ExistingFile);
  app.add_option("--screenshot", arguments.screenshotPath,
                 "Draw --frames frames, save the window as this PNG, and exit");
  app.add_option("--script", arguments.scriptPath,
                 "Run viewer commands from this file (see src/app/automation/script.h)")
      ->check(CLI::ExistingFile);
  app.add_option("--stats-json", arguments.statsJsonPath,
                 "On exit, write the viewer's frame times and edit-to-preview latency as JSON");
  app.add_option("--frames", arguments.frames, "Frames to draw before --screenshot (default 10)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--wait-spp", arguments.waitSpp,
                 "--screenshot waits until the preview has N samples per pixel (default 1), "
                 "and fails if it takes longer than --wait-timeout")
      ->check(CLI::Range(1, 1 << 20));
  app.add_option("--wait-timeout", arguments.waitSeconds,
                 "Seconds --screenshot waits for --wait-spp (default 300, or 60 for the first "
                 "pass)")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_option("--size", arguments.size, "Window size WIDTHxHEIGHT, e.g. 1280x800");
}

// A file opened by a file manager or the desktop entry (lenslab %f): a scene by its extension,
// otherwise a lens, as the viewer's file drop tells them apart. Empty when there is none.
std::string takeFileArgument(const ViewerArguments& arguments, app::ViewerOptions& options) {
  if (arguments.filePath.empty()) return "";
  const bool isScene = std::filesystem::path(arguments.filePath).extension() == ".pbrt";
  std::string& path = isScene ? options.scenePath : options.lensPath;
  if (!path.empty()) {
    return arguments.filePath + " and " + (isScene ? "--scene" : "--lens") + " both name the " +
           (isScene ? "scene" : "lens") + ": give one";
  }
  path = arguments.filePath;
  return "";
}

// The options' names `parsed` (the app or one of its subcommands) knows, with their dashes.
std::vector<std::string> optionNames(const CLI::App& parsed) {
  std::vector<std::string> names;
  for (const CLI::Option* option : parsed.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

// The headless subcommands' names.
std::vector<std::string> subcommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* subcommand : app.get_subcommands({}))
    names.push_back(subcommand->get_name());
  return names;
}

// "did you mean `render`?" for the first word of the command line that is a slip from a name
// the command knows: an option of the subcommand it follows (or of the viewer), or, in place of
// a subcommand, a subcommand (unless a file of that name exists: then it is the viewer's file).
// Empty when no word is near one.
std::string didYouMean(const CLI::App& app, const CLI::App& innermost,
                       const std::vector<std::string>& words) {
  const CLI::App* reading = &app;
  bool first = true;
  for (const std::string& word : words) {
    if (word == "--") break;
    if (reading == &app && &innermost != &app && word == innermost.get_name()) {
      reading = &innermost;
      continue;
    }
    if (word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1]))) {
      const std::string name = word.substr(0, word.find('='));
      if (reading->get_option_no_throw(name) != nullptr) continue;
      if (const auto near = nearestName(name, optionNames(*reading)))
        return "did you mean `" + *near + "`?";
      continue;
    }
    std::error_code ignored;  // a name too long for a path is no file either
    if (first && reading == &app && !std::filesystem::exists(word, ignored)) {
      if (const auto near = nearestName(word, subcommandNames(app)))
        return "did you mean `" + *near + "`?";
    }
    first = false;
  }
  return "";
}

int runViewer(const ViewerArguments& arguments) {
  app::ViewerOptions options;
  options.lensPath = arguments.lensPath;
  options.scenePath = arguments.scenePath;
  if (const std::string error = takeFileArgument(arguments, options); !error.empty()) {
    printUsageError("lenslab", error);
    return kUsageError;
  }
  options.frames = arguments.frames;
  if (arguments.waitSpp > 0) {
    options.waitSpp = arguments.waitSpp;
    options.screenshotWaitSeconds = 300.0;
  }
  if (arguments.waitSeconds > 0) options.screenshotWaitSeconds = arguments.waitSeconds;
  options.scriptPath = arguments.scriptPath;
  options.statsJsonPath = arguments.statsJsonPath;
  if (!arguments.screenshotPath.empty()) options.screenshotPath = arguments.screenshotPath;
  if (!arguments.size.empty()) {
    std::string error;
    const auto size = parsePixelSize(arguments.size, &error);
    if (!size) {
      printUsageError("lenslab", "--size: " + error);
      return kUsageError;
    }
    options.width = size->width;
    options.height = size->height;
  }
  return app::runViewer(options);
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"lenslab: see what a real camera lens does", "lenslab"};
  app.set_version_flag("--version", std::string("lenslab ") + LENSLAB_VERSION);
  ViewerArguments viewerArguments;
  addViewerOptions(app, viewerArguments);
  SubcommandRunner subcommand;  // set when a headless subcommand was named
  addInfoCommand(app, subcommand);
  addFocusCommand(app, subcommand);
  addAnalyzeCommand(app, subcommand);
  addRenderCommand(app, subcommand);
  addGlassCommand(app, subcommand);
  addConvertCommand(app, subcommand);
  // After the subcommands: CLI11 gives a subcommand its parent's footer when it is added, and a
  // subcommand's help is no place for the viewer's.
  app.footer(
      "With no subcommand, opens the viewer (needs a display).\n"
      "Headless: lenslab SUBCOMMAND --help for each subcommand.");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ParseError& error) {
    // The error belongs to the innermost subcommand parsed so far (render for render --spp 0).
    std::string command = "lenslab";
    const CLI::App* innermost = &app;
    while (!innermost->get_subcommands().empty()) {
      innermost = innermost->get_subcommands().back();
      command += " " + innermost->get_name();
    }
    std::string message = error.what();
    const std::string hint =
        didYouMean(app, *innermost, std::vector<std::string>(argv + 1, argv + argc));
    if (!hint.empty()) message += " (" + hint + ")";
    printUsageError(command, message);
    return kUsageError;
  }
  // Last resort: nothing a user passes may end in an uncaught exception (an abort, exit 134).
  // Expected problems are reported where they arise; this names the unexpected ones.
  try {
    if (subcommand) return subcommand();
    return runViewer(viewerArguments);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "lenslab: internal error: %s\n", error.what());
  } catch (...) {
    std::fprintf(stderr, "lenslab: internal error: an unknown exception\n");
  }
  return kInternalError;
}

}  // namespace lenslab::cli
