#pragma once
// `lenslab render SCENE ...`: the headless renderer.

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli/subcommand.h"

namespace lenslab::cli {

struct RenderArguments {
  CLI::App* command = nullptr;
  std::string scenePath;
  std::string lensPath;
  int samplesPerPixel = 0;  // 0: the scene's
  std::string resolution;
  int threads = 0;
  unsigned seed = 0;
  std::string integrator;  // empty: the scene's
  std::string outPath;
  std::string statsJsonPath;
  std::string exposure;  // stops (a number), "auto", or empty: the scene's
  bool quiet = false;
  bool noCos4 = false, noRims = false;  // the teaching toggles (render/falloff_toggles.h)
  std::string spectral = "auto";        // on, off, auto (render/spectral_mode.h)
};

// Adds the subcommand to `app`; when the user names it, `run` is set to run it (subcommand.h).
void addRenderCommand(CLI::App& app, SubcommandRunner& run);
// Adds the subcommand to `app`; the returned arguments fill in when it is parsed.
std::shared_ptr<RenderArguments> registerRenderCommand(CLI::App& app);
// Runs it; returns the process exit code.
int runRenderCommand(const RenderArguments& arguments);

}  // namespace lenslab::cli
