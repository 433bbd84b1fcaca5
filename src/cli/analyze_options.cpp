#include "cli/analyze_options.h"

#include <cmath>
#include <sstream>

#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "common/distance_text.h"
#include "optics/lens_file_formats.h"

namespace lenslab::cli {

namespace {

// The reports `--only` names, in the registry's order; nullopt (after a usage error) when a key
// is unknown.
std::optional<std::vector<const AnalysisReport*>> selectedReports(const std::string& only) {
  std::vector<const AnalysisReport*> selected;
  if (only.empty()) {
    for (const AnalysisReport& report : analysisReports()) selected.push_back(&report);
    return selected;
  }
  std::vector<bool> wanted(analysisReports().size(), false);
  std::stringstream keys(only);
  for (std::string key; std::getline(keys, key, ',');) {
    // "mtf, spot" as a person types a list: the spaces around a key are no part of it.
    const auto first = key.find_first_not_of(" \t");
    key = first == std::string::npos ? ""
                                     : key.substr(first, key.find_last_not_of(" \t") + 1 - first);
    const AnalysisReport* report = findAnalysisReport(key);
    if (!report) {
      printUsageError("lenslab analyze", "--only: unknown analysis '" + key.substr(0, 40) +
                                             "' (known: " + knownAnalysisKeys() + ")");
      return std::nullopt;
    }
    wanted[static_cast<std::size_t>(report - analysisReports().data())] = true;
  }
  for (std::size_t i = 0; i < wanted.size(); ++i)
    if (wanted[i]) selected.push_back(&analysisReports()[i]);
  return selected;
}

}  // namespace

std::string knownAnalysisKeys() {
  std::string keys;
  for (const AnalysisReport& report : analysisReports())
    keys += (keys.empty() ? "" : ", ") + std::string(report.key);
  return keys;
}

AnalyzeOptions addAnalyzeOptions(CLI::App& analyze, AnalyzeArguments& arguments) {
  AnalyzeOptions options;
  analyze
      .add_option("LENS", arguments.lensPath,
                  "Lens file (" + optics::lensFileExtensionsText() + ")")
      ->required();
  analyze.add_flag("--json", arguments.json, "Print JSON instead of a readable summary");
  analyze
      .add_option("--compare", arguments.comparePath,
                  "A second lens analysed with the same options, as the reference: --json "
                  "writes {\"lens\": ..., \"reference\": ...}")
      ->check(CLI::ExistingFile);
  options.filmDistance =
      analyze
          .add_option("--film-distance", arguments.filmDistanceMm,
                      "Film distance in mm (rear vertex to film; default: the one that focuses "
                      "the object distance, not the file's)")
          ->check(PositiveFiniteNumber());
  options.objectDistance = analyze.add_option(
      "--object-distance", arguments.objectDistance,
      "Object distance from the film plane (mm, or 3.6 m), or 'inf' (the default). Without "
      "--film-distance the lens is focused there first; with it the film stays where it is "
      "given, and the header says which object distance is then in focus");
  options.filmDiagonal =
      analyze
          .add_option("--film-diagonal", arguments.filmDiagonalMm,
                      "Film diagonal in mm; curves run from the axis to its corner (default: "
                      "twice the lens's largest design image height when its file states its "
                      "fields as image heights, else 43.27, full frame)")
          ->check(PositiveFiniteNumber());
  analyze
      .add_option("--stop-diameter", arguments.stopDiameterMm,
                  "Open or close the iris to this diameter in mm (default: the file's)")
      ->check(PositiveFiniteNumber());
  analyze
      .add_option("--points", arguments.points,
                  "Points from the axis to the film corner (default 64)")
      ->check(CLI::Range(2, 4096));
  options.fields =
      analyze
          .add_option("--fields", arguments.fieldFractions,
                      "Fields as fractions of the film's half diagonal (default: the lens's "
                      "design image heights when the film is sized from them, else 0,0.7,1)")
          ->delimiter(',')
          ->check(FiniteNumberBetween(0.0, 1.0, "of the half diagonal"));
  options.wavelength =
      analyze
          .add_option("--wavelength", arguments.wavelengthNm,
                      "Wavelength in nm for the monochromatic analyses (default: the lens's "
                      "primary design wavelength when its file states one, else 587.56, the d "
                      "line)")
          ->check(FiniteNumberBetween(kAnalyzeMinWavelengthNm, kAnalyzeMaxWavelengthNm, "nm"));
  analyze.add_option("--only", arguments.only,
                     "Run only these analyses, comma-separated (" + knownAnalysisKeys() + ")");
  return options;
}

std::optional<AnalyzeRequest> checkAnalyzeArguments(const AnalyzeArguments& arguments,
                                                    bool objectGiven) {
  AnalyzeRequest request;
  auto reports = selectedReports(arguments.only);
  if (!reports) return std::nullopt;
  request.reports = std::move(*reports);
  for (double fraction : arguments.fieldFractions) {
    if (!(fraction >= 0.0 && fraction <= 1.0)) {
      printUsageError("lenslab analyze",
                      "--fields: each field is a fraction of the film's half "
                      "diagonal from 0 to 1 (got " +
                          std::to_string(fraction) + ")");
      return std::nullopt;
    }
  }
  if (objectGiven) {
    const auto parsed = parseDistanceMm(arguments.objectDistance);
    if (!parsed) {
      printUsageError("lenslab analyze",
                      "--object-distance: '" + arguments.objectDistance.substr(0, 40) +
                          "' is not a positive distance (mm, or with a unit: 3.6 m; or 'inf')");
      return std::nullopt;
    }
    if (std::isfinite(*parsed)) request.objectDistanceMm = *parsed;
  }
  return request;
}

}  // namespace lenslab::cli
