#include "cli/analyze_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/analyze/analysis_report.h"
#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "common/distance_text.h"
#include "optics/focus.h"

namespace lenslab::cli {

namespace {

constexpr int kUsageError = 2;  // as for every usage error (cli.cpp)

struct AnalyzeArguments {
  std::string lensPath;
  bool json = false;
  double filmDistanceMm = 0.0;
  std::string objectDistance;     // text, so that "inf" works
  double filmDiagonalMm = 43.27;  // 36 x 24 mm full frame
  double stopDiameterMm = 0.0;    // 0: the file's
  double wavelengthNm = optics::LensSystem::kDefaultWavelengthNm;
  int points = 64;
  std::vector<double> fieldFractions{0.0, 0.7, 1.0};
  std::string only;  // comma-separated keys; empty: every analysis
};

std::string knownKeys() {
  std::string keys;
  for (const AnalysisReport& report : analysisReports())
    keys += (keys.empty() ? "" : ", ") + std::string(report.key);
  return keys;
}

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
    const AnalysisReport* report = findAnalysisReport(key);
    if (!report) {
      printUsageError("lenslab analyze", "--only: unknown analysis '" + key.substr(0, 40) +
                                             "' (known: " + knownKeys() + ")");
      return std::nullopt;
    }
    wanted[static_cast<std::size_t>(report - analysisReports().data())] = true;
  }
  for (std::size_t i = 0; i < wanted.size(); ++i)
    if (wanted[i]) selected.push_back(&analysisReports()[i]);
  return selected;
}

std::string objectText(const std::optional<double>& objectDistanceMm) {
  return objectDistanceMm ? distanceText(*objectDistanceMm) + " from the film" : "infinity";
}

int runAnalyze(const AnalyzeArguments& arguments, bool filmGiven, bool objectGiven) {
  const auto reports = selectedReports(arguments.only);
  if (!reports) return kUsageError;
  for (double fraction : arguments.fieldFractions) {
    if (!(fraction >= 0.0 && fraction <= 1.0)) {
      printUsageError("lenslab analyze",
                      "--fields: each field is a fraction of the film's half "
                      "diagonal from 0 to 1 (got " +
                          std::to_string(fraction) + ")");
      return kUsageError;
    }
  }
  std::optional<double> objectDistanceMm;  // nullopt: infinity
  if (objectGiven) {
    const auto parsed = parseDistanceMm(arguments.objectDistance);
    if (!parsed) {
      printUsageError("lenslab analyze",
                      "--object-distance: '" + arguments.objectDistance.substr(0, 40) +
                          "' is not a positive distance (mm, or with a unit: 3.6 m; or 'inf')");
      return kUsageError;
    }
    if (std::isfinite(*parsed)) objectDistanceMm = *parsed;
  }
  auto lens = loadLensOrReport(arguments.lensPath, "analyze", arguments.wavelengthNm);
  if (!lens) return 1;
  if (arguments.stopDiameterMm > 0.0) {
    // Before focusing: the focus of a real lens moves as it is stopped down.
    lens = lens->withStopDiameter(arguments.stopDiameterMm);
    if (!lens) {
      std::cerr << "lenslab analyze: --stop-diameter " << arguments.stopDiameterMm
                << " mm is beyond what a lens may have\n";
      return 1;
    }
  }
  if (filmGiven) {
    lens = lens->withFilmDistance(arguments.filmDistanceMm);
    if (!lens) {
      std::cerr << "lenslab analyze: --film-distance " << arguments.filmDistanceMm
                << " mm is beyond what a lens may have\n";
      return 1;
    }
  } else if (objectGiven) {
    const double focusAtMm = objectDistanceMm.value_or(std::numeric_limits<double>::infinity());
    const optics::FocusResult film = optics::filmDistanceForObjectDistance(*lens, focusAtMm);
    if (!film.ok()) {
      std::cerr << "lenslab analyze: cannot focus "
                << (objectDistanceMm ? "at " + distanceText(*objectDistanceMm) : "at infinity")
                << ": " << film.whyNot << "\n";
      return 1;
    }
    lens = lens->withFilmDistance(*film.valueMm);
    if (!lens) return 1;
  }

  AnalyzeContext context;
  context.lensPath = arguments.lensPath;
  context.lens = lens;
  context.points = arguments.points;
  context.setup.fieldFractions = arguments.fieldFractions;
  context.setup.filmHalfDiagonalMm = 0.5 * arguments.filmDiagonalMm;
  context.setup.objectDistanceFromFilmMm = objectDistanceMm;
  context.setup.wavelengthNm = arguments.wavelengthNm;

  nlohmann::json json{{"lens", arguments.lensPath},
                      {"film_distance_mm", lens->filmDistanceMm()},
                      {"film_diagonal_mm", arguments.filmDiagonalMm},
                      {"stop_diameter_mm", lens->stopDiameterMm()},
                      {"wavelength_nm", arguments.wavelengthNm},
                      {"object_distance_mm", objectDistanceMm ? nlohmann::json(*objectDistanceMm)
                                                              : nlohmann::json(nullptr)},
                      {"object_at_infinity", !objectDistanceMm.has_value()},
                      {"field_fractions", arguments.fieldFractions}};
  std::string text;
  char header[512];
  std::snprintf(header, sizeof header,
                "%s: film distance %s, film diagonal %s, object at %s, %.2f nm\n",
                arguments.lensPath.c_str(), millimetresText(lens->filmDistanceMm()).c_str(),
                millimetresText(arguments.filmDiagonalMm).c_str(),
                objectText(objectDistanceMm).c_str(), arguments.wavelengthNm);
  text += header;
  nlohmann::json unavailable = nlohmann::json::object();
  for (const AnalysisReport* report : *reports) {
    text += std::string("\n== ") + report->key + " ==\n";
    try {
      ReportPart part = report->run(context);
      if (part.json) json[report->key] = std::move(*part.json);
      text += part.text;
    } catch (const AnalysisUnavailable& error) {
      std::cerr << "lenslab analyze: " << report->key << ": " << error.what() << "\n";
      json[report->key] = nullptr;
      unavailable[report->key] = error.what();
      text += std::string("not available: ") + error.what() + "\n";
    }
  }
  if (!unavailable.empty()) json["unavailable"] = unavailable;
  if (arguments.json)
    std::cout << json.dump(2) << "\n";
  else
    std::cout << text;
  return unavailable.empty() ? 0 : 1;
}

}  // namespace

void addAnalyzeCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<AnalyzeArguments>();
  CLI::App* analyze = app.add_subcommand(
      "analyze", "Analyse a lens at its film distance: " + knownKeys() + " (JSON keys)");
  analyze->add_option("LENS", arguments->lensPath, "Lens file (.dat, pbrt format)")->required();
  analyze->add_flag("--json", arguments->json, "Print JSON instead of a readable summary");
  auto* film = analyze
                   ->add_option("--film-distance", arguments->filmDistanceMm,
                                "Film distance in mm (rear vertex to film; default: the file's)")
                   ->check(PositiveFiniteNumber());
  auto* object = analyze->add_option(
      "--object-distance", arguments->objectDistance,
      "Object distance from the film plane (mm, or 3.6 m), or 'inf' (the default); without "
      "--film-distance the lens is focused there first");
  analyze
      ->add_option("--film-diagonal", arguments->filmDiagonalMm,
                   "Film diagonal in mm; curves run from the axis to its corner (default "
                   "43.27, full frame)")
      ->check(PositiveFiniteNumber());
  analyze
      ->add_option("--stop-diameter", arguments->stopDiameterMm,
                   "Open or close the iris to this diameter in mm (default: the file's)")
      ->check(PositiveFiniteNumber());
  analyze
      ->add_option("--points", arguments->points,
                   "Points from the axis to the film corner (default 64)")
      ->check(CLI::Range(2, 4096));
  analyze
      ->add_option("--fields", arguments->fieldFractions,
                   "Fields as fractions of the film's half diagonal (default 0,0.7,1)")
      ->delimiter(',')
      ->check(FiniteNumberBetween(0.0, 1.0, "of the half diagonal"));
  analyze
      ->add_option("--wavelength", arguments->wavelengthNm,
                   "Wavelength in nm for the monochromatic analyses (default 587.56, the d line)")
      ->check(FiniteNumberBetween(350.0, 1000.0, "nm"));
  analyze->add_option("--only", arguments->only,
                      "Run only these analyses, comma-separated (" + knownKeys() + ")");
  analyze->callback([arguments, film, object, &run] {
    const bool filmGiven = film->count() > 0, objectGiven = object->count() > 0;
    run = [arguments, filmGiven, objectGiven] {
      return runAnalyze(*arguments, filmGiven, objectGiven);
    };
  });
}

}  // namespace lenslab::cli
