#include "cli/cli.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "app/viewer.h"
#include "cli/analyze_command.h"
#include "cli/focus_command.h"
#include "cli/info_command.h"
#include "cli/render_command.h"
#include "cli/size_argument.h"
#include "cli/subcommand.h"
#include "cli/usage_error.h"

namespace lenslab::cli {

namespace {

constexpr int kUsageError = 2;
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
  app.add_option("--lens", arguments.lensPath, "Lens file to open (.dat)")
      ->check(CLI::ExistingFile);
  app.add_option("--scene", arguments.scenePath, "Scene file to open (.pbrt)")
      ->check(CLI::ExistingFile);
  app.add_option("file", arguments.filePath,
                 "Lens (.dat) or scene (.pbrt) to open, as --lens or --scene would")
      ->check(CLI::ExistingFile);
  app.add_option("--screenshot", arguments.screenshotPath,
                 "Draw --frames frames, save the window as this PNG, and exit");
  app.add_option("--script", arguments.scriptPath,
                 "Run viewer commands from this file (see src/app/script.h)")
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
  app.footer(
      "With no subcommand, opens the viewer (needs a display).\n"
      "Headless: lenslab SUBCOMMAND --help for each subcommand.");
  ViewerArguments viewerArguments;
  addViewerOptions(app, viewerArguments);
  SubcommandRunner subcommand;  // set when a headless subcommand was named
  addInfoCommand(app, subcommand);
  addFocusCommand(app, subcommand);
  addAnalyzeCommand(app, subcommand);
  addRenderCommand(app, subcommand);

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
    for (const CLI::App* parsed = &app; !parsed->get_subcommands().empty();) {
      parsed = parsed->get_subcommands().back();
      command += " " + parsed->get_name();
    }
    printUsageError(command, error.what());
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
