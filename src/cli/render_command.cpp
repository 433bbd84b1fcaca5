#include "cli/render_command.h"

#include "cli/exit_codes.h"
#include "common/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli/number_validators.h"
#include "cli/size_argument.h"
#include "cli/usage_error.h"
#include "optics/lens_file_formats.h"
#include "render/auto_exposure.h"
#include "render/camera_factory.h"
#include "render/image_io.h"
#include "render/pbrt_parser.h"
#include "render/progressive_renderer.h"
#include "render/scene_builder.h"
#include "render/scene_content.h"

namespace lenslab::cli {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void printDiagnostics(const Diagnostics& diagnostics) {
  std::fputs(diagnostics.formatAll().c_str(), stderr);
}

// "42 s", "3 min 05 s", "2 h 07 min": a duration as a person reads it.
std::string durationText(double seconds) {
  char text[48];
  const long whole = std::lround(std::max(0.0, seconds));
  if (seconds < 10.0)
    std::snprintf(text, sizeof text, "%.1f s", std::max(0.0, seconds));
  else if (whole < 60)
    std::snprintf(text, sizeof text, "%ld s", whole);
  else if (whole < 3600)
    std::snprintf(text, sizeof text, "%ld min %02ld s", whole / 60, whole % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", whole / 3600, (whole % 3600) / 60);
  return text;
}

// The bar with the time left, extrapolated from the time the waves so far took (each wave is
// the same samples per pixel over the whole image, so the rate holds).
void drawProgress(double fraction, double elapsedSeconds) {
  constexpr int kWidth = 40;
  const int filled = static_cast<int>(fraction * kWidth + 0.5);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  const std::string left =
      fraction >= 1.0  ? "done in " + durationText(elapsedSeconds)
      : fraction > 0.0 ? durationText(elapsedSeconds * (1.0 - fraction) / fraction) + " left"
                       : std::string("starting");
  // Padded so that a shorter text overwrites the end of a longer one on the same line.
  std::fprintf(stderr, "\r[%s] %3d%%  %-20s", bar.c_str(), static_cast<int>(fraction * 100.0 + 0.5),
               left.c_str());
  if (fraction >= 1.0) std::fputc('\n', stderr);
  std::fflush(stderr);
}

// --exposure: a number of stops, or "auto" (the viewer's metering, render/auto_exposure.h).
class ExposureValue : public CLI::Validator {
 public:
  ExposureValue() {
    name_ = "STOPS|auto";
    func_ = [](std::string& text) -> std::string {
      if (text == "auto") return {};
      return FiniteNumber()(text).empty() ? std::string()
                                          : "'" + text + "' is neither a number of stops nor auto";
    };
  }
};

// ".png" for out.PNG: the extension that says the output's format, in lower case.
std::string lowerExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

bool knownImageExtension(const std::string& path) {
  const std::string extension = lowerExtension(path);
  return extension == ".png" || extension == ".exr" || extension == ".pfm";
}

// Before any rendering: the picture (and the statistics) can be written where they are to go,
// so that a typo in a directory name costs no render. Prints the error; false if not.
bool checkOutputs(const std::string& outPath, const std::string& statsJsonPath, bool* usage) {
  *usage = false;
  if (!knownImageExtension(outPath)) {
    printUsageError("lenslab render", outPath + ": unknown image format (use .png, .exr or .pfm)");
    *usage = true;
    return false;
  }
  for (const std::string& path : {outPath, statsJsonPath}) {
    if (path.empty()) continue;
    if (const std::string error = checkWritable(path); !error.empty()) {
      std::fprintf(stderr, "lenslab render: %s (nothing was rendered)\n", error.c_str());
      return false;
    }
  }
  return true;
}

bool writeStats(const std::string& path, const nlohmann::json& stats, std::string& error) {
  error = writeFileAtomically(path, stats.dump(2) + "\n");
  return error.empty();
}

}  // namespace

std::shared_ptr<RenderArguments> registerRenderCommand(CLI::App& app) {
  auto arguments = std::make_shared<RenderArguments>();
  CLI::App* command = app.add_subcommand("render", "Render a pbrt scene to an image, headless");
  arguments->command = command;
  command->add_option("scene", arguments->scenePath, "Scene file (.pbrt)")->required();
  command->add_option(
      "--lens", arguments->lensPath,
      "Lens file (" + optics::lensFileExtensionsText() +
          ") to render through. It replaces a realistic camera's lens "
          "(keeping the scene's stop and focus). A perspective camera becomes a "
          "realistic one at the same place: this lens at its own stop, focused at the "
          "camera's \"focaldistance\" (default: infinity), with the Film's "
          "\"diagonal\" (default 35 mm)");
  command->add_option("--spp", arguments->samplesPerPixel, "Samples per pixel (default: scene's)")
      ->check(CLI::Range(1, 1 << 20));
  command->add_option("--resolution", arguments->resolution, "Image size WIDTHxHEIGHT");
  command->add_option("--threads", arguments->threads, "Worker threads (default: all)")
      ->check(CLI::Range(1, 1024));
  command->add_option("--seed", arguments->seed, "Sample seed");
  command->add_option("--integrator", arguments->integrator, "path or direct")
      ->check(CLI::IsMember({"path", "direct"}));
  command->add_option("--out", arguments->outPath,
                      "Output image; format from the extension: .png .exr .pfm "
                      "(default: the scene's film filename, else out.png)");
  command->add_option("--stats-json", arguments->statsJsonPath, "Write timing statistics here");
  command
      ->add_option("--exposure", arguments->exposure,
                   "PNG exposure in stops, or 'auto': metered as the viewer's auto exposure "
                   "does (default: log2 of the Film's \"scale\", else 0)")
      ->check(ExposureValue())
      ->type_name("STOPS|auto");
  command->add_flag("--quiet", arguments->quiet,
                    "No progress bar (on a terminal) and no closing line");
  command->add_flag("--no-cos4", arguments->noCos4,
                    "Realistic camera without Kolb's cos^4 in the exposure weight (teaching)");
  command
      ->add_option("--spectral", arguments->spectral,
                   "on, off or auto (default): trace every camera sample at a wavelength of its "
                   "own, so that the lens's dispersion (lateral and longitudinal colour) is in the "
                   "picture; auto when some glass of the lens has an Abbe number (V_d)")
      ->check(CLI::IsMember({"on", "off", "auto"}));
  command->add_flag("--no-rims", arguments->noRims,
                    "Realistic camera whose only clipping aperture is the stop: no mechanical "
                    "vignetting (teaching)");
  return arguments;
}

void addRenderCommand(CLI::App& app, SubcommandRunner& run) {
  const std::shared_ptr<RenderArguments> arguments = registerRenderCommand(app);
  arguments->command->callback(
      [arguments, &run] { run = [arguments] { return runRenderCommand(*arguments); }; });
}

int runRenderCommand(const RenderArguments& arguments) {
  const Clock::time_point started = Clock::now();
  render::CameraOverrides overrides;
  if (!arguments.resolution.empty()) {
    std::string error;
    const auto size = parsePixelSize(arguments.resolution, &error);
    if (!size) {
      printUsageError("lenslab render", "--resolution: " + error);
      return kUsageError;
    }
    overrides.width = size->width;
    overrides.height = size->height;
  }
  if (!arguments.lensPath.empty()) overrides.lensPath = arguments.lensPath;
  overrides.falloff = {
      !arguments.noCos4, !arguments.noRims,
      render::parseSpectralMode(arguments.spectral).value_or(render::SpectralMode::Auto)};

  // A named output is checked before the scene is even read (a large scene takes a while).
  bool usage = false;
  if (!arguments.outPath.empty() &&
      !checkOutputs(arguments.outPath, arguments.statsJsonPath, &usage)) {
    return usage ? kUsageError : kFailure;
  }

  render::ParseResult parsed = render::parsePbrtFile(arguments.scenePath);
  printDiagnostics(parsed.diagnostics);
  if (!parsed.scene) return kFailure;
  const render::SceneDescription& description = *parsed.scene;

  std::string outPath = arguments.outPath;
  // Without --out the picture goes where the scene says, else out.png, in the working
  // directory: the closing line names it, as nothing on the command line does.
  std::string outOrigin;
  if (outPath.empty()) {
    outPath = description.film.filename.empty() ? "out.png" : description.film.filename;
    outOrigin = description.film.filename.empty() ? "no --out, the default name"
                                                  : "no --out, the scene's Film \"filename\"";
    if (!checkOutputs(outPath, arguments.statsJsonPath, &usage))
      return usage ? kUsageError : kFailure;
  }

  Diagnostics cameraDiagnostics;
  auto camera = render::makeCamera(description, overrides, cameraDiagnostics);
  printDiagnostics(cameraDiagnostics);
  if (!camera) return kFailure;
  Diagnostics contentDiagnostics;
  render::reportEmptyScene(description, contentDiagnostics);
  printDiagnostics(contentDiagnostics);
  if (contentDiagnostics.hasErrors()) return kFailure;  // no black image for an empty scene
  // The exit-pupil table is set-up, as pbrt's is. It and the scene (image textures, Embree's
  // BVH) are independent, so they are built side by side (a jthread joins even if the scene's
  // build throws).
  std::jthread preparingCamera([&camera] { camera->prepare(); });
  render::BuildResult built = render::buildScene(description);
  preparingCamera.join();
  printDiagnostics(built.diagnostics);
  if (!built.scene) return kFailure;
  const double setupSeconds = secondsSince(started);

  render::RenderJob job;
  job.camera = camera;
  job.scene = built.scene;
  job.settings.samplesPerPixel =
      arguments.samplesPerPixel > 0 ? arguments.samplesPerPixel : description.pixelSamples;
  job.settings.threads = arguments.threads;
  job.settings.seed = arguments.seed;
  job.settings.integrator.kind = description.integrator.kind;
  job.settings.integrator.maxDepth = description.integrator.maxDepth;
  if (arguments.integrator == "path") job.settings.integrator.kind = render::IntegratorKind::Path;
  if (arguments.integrator == "direct") {
    job.settings.integrator.kind = render::IntegratorKind::DirectLighting;
  }
  const bool showProgress = !arguments.quiet && isatty(STDERR_FILENO);
  const Clock::time_point renderStarted = Clock::now();
  std::function<void(double)> progress;
  if (showProgress) {
    progress = [renderStarted](double fraction) {
      drawProgress(fraction, secondsSince(renderStarted));
    };
  }
  const auto snapshot = render::renderToCompletion(job, progress);
  if (!snapshot) {
    std::fprintf(stderr, "lenslab render: nothing was rendered\n");
    return kFailure;
  }
  render::FloatImage image{snapshot->width, snapshot->height, snapshot->rgb};
  // A PNG's exposure: --exposure, else the one the scene sets (Film "scale", as the viewer shows
  // it); EXR and PFM hold the radiance.
  double exposureStops = 0.0;
  std::string exposureText;  // for the closing line, when it applies (a PNG)
  if (arguments.exposure == "auto") {
    exposureStops = render::autoExposureStops(image);
    exposureText = "auto exposure";
  } else if (!arguments.exposure.empty()) {
    exposureStops = std::stod(arguments.exposure);  // checked by ExposureValue
    exposureText = "exposure";
  } else if (description.film.scale) {
    exposureStops = std::log2(*description.film.scale);
    exposureText = "the Film's exposure";
  }
  const render::WriteResult written = render::writeImage(outPath, image, exposureStops);
  if (!written.ok) {
    std::fprintf(stderr, "lenslab render: %s\n", written.error.c_str());
    return kFailure;
  }
  const bool png = lowerExtension(outPath) == ".png";  // the only format with an exposure
  if (!arguments.quiet) {
    // The closing line: what was made, how long it took, and where it is.
    std::string where = outPath;
    if (!outOrigin.empty()) {
      std::error_code ignored;
      const auto absolute = std::filesystem::absolute(outPath, ignored);
      where = (absolute.empty() ? outPath : absolute.string()) + " (" + outOrigin + ")";
    }
    char exposure[64] = "";
    if (png && !exposureText.empty())
      std::snprintf(exposure, sizeof exposure, ", %s %+.2f stops", exposureText.c_str(),
                    exposureStops);
    std::fprintf(stderr, "lenslab render: %dx%d, %d spp, %s%s: wrote %s\n", snapshot->width,
                 snapshot->height, snapshot->samplesPerPixel,
                 durationText(snapshot->renderSeconds).c_str(), exposure, where.c_str());
  }
  if (!arguments.statsJsonPath.empty()) {
    const auto& statistics = snapshot->statistics;
    nlohmann::json stats;
    stats["wall_seconds"] = secondsSince(started);
    stats["setup_seconds"] = setupSeconds;
    stats["render_seconds"] = snapshot->renderSeconds;
    stats["spp"] = snapshot->samplesPerPixel;
    stats["width"] = snapshot->width;
    stats["height"] = snapshot->height;
    // Rays asked of the camera: spp x pixels x lens points per sample (more than one for a stop
    // shape that opens under half of the region its sampler covers, as pbrt's gaussian
    // halftone: Camera::lensPointsPerSample).
    stats["camera_samples"] = statistics.cameraSamples;
    stats["lens_points_per_sample"] = camera->lensPointsPerSample();
    stats["lens_pass_fraction"] =
        statistics.cameraSamples > 0
            ? static_cast<double>(statistics.lensPassed) / statistics.cameraSamples
            : 0.0;
    stats["discarded_samples"] = statistics.discardedSamples;
    stats["falloff"] = overrides.falloff.describe();
    stats["spectral"] = camera->spectral();
    stats["output"] = outPath;
    if (png) stats["exposure_stops"] = exposureStops;
    std::string error;
    if (!writeStats(arguments.statsJsonPath, stats, error)) {
      std::fprintf(stderr, "lenslab render: %s\n", error.c_str());
      return kFailure;
    }
  }
  return 0;
}

}  // namespace lenslab::cli
