#pragma once
// `lenslab analyze`'s options (analyze_command.h lists them): registering them on the CLI11
// subcommand and the checks across them that CLI11's per-option validators cannot make. Apart
// from running the analyses, so that the fuzz target (tests/fuzz/analyze_options_fuzz.cpp) can
// parse command lines without reading lenses.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/analyze/analysis_report.h"
#include "optics/lens_system.h"

namespace lenslab::cli {

struct AnalyzeArguments {
  std::string lensPath;
  bool json = false;
  double filmDistanceMm = 0.0;
  std::string objectDistance;     // text, so that "inf" works
  double filmDiagonalMm = 43.27;  // 36 x 24 mm full frame
  double stopDiameterMm = 0.0;    // 0: the file's
  // --wavelength's; when it is not given, runAnalyze uses the lens's primary design wavelength
  // (its file's) or the d line.
  double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm;
  int points = 64;
  std::vector<double> fieldFractions{0.0, 0.7, 1.0};
  std::string only;  // comma-separated keys; empty: every analysis
  // --compare B: B analysed with the same options beside the lens (the viewer's pinned
  // reference); empty: the lens alone.
  std::string comparePath;
};

// The options whose presence matters (a given film distance wins over focusing at the object).
struct AnalyzeOptions {
  CLI::Option* filmDistance = nullptr;
  CLI::Option* objectDistance = nullptr;
  CLI::Option* wavelength = nullptr;
  CLI::Option* filmDiagonal = nullptr;
  CLI::Option* fields = nullptr;
};

// What --wavelength accepts, and so the design wavelengths analyze traces at.
inline constexpr double kAnalyzeMinWavelengthNm = 350.0;
inline constexpr double kAnalyzeMaxWavelengthNm = 1000.0;

// Adds the options to `analyze` (the subcommand); parsing stores them in `arguments`, which must
// outlive it.
AnalyzeOptions addAnalyzeOptions(CLI::App& analyze, AnalyzeArguments& arguments);

// What the parsed options ask for, once checked together.
struct AnalyzeRequest {
  std::vector<const AnalysisReport*> reports;  // --only's, in the registry's order; else all
  std::optional<double> objectDistanceMm;      // nullopt: infinity
};

// nullopt after printing the usage error (an unknown --only key, a field outside 0..1, an
// object distance that is not one).
std::optional<AnalyzeRequest> checkAnalyzeArguments(const AnalyzeArguments& arguments,
                                                    bool objectGiven);

// "relative_illumination, ...": every analysis's key, for help and messages.
std::string knownAnalysisKeys();

}  // namespace lenslab::cli
