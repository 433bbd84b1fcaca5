#include "cli/analyze_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/analyze/analysis_report.h"
#include "cli/analyze_options.h"
#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "common/distance_text.h"
#include "optics/focus.h"

namespace lenslab::cli {

namespace {

constexpr int kUsageError = 2;  // as for every usage error (cli.cpp)

std::string objectText(const std::optional<double>& objectDistanceMm) {
  return objectDistanceMm ? distanceText(*objectDistanceMm) + " from the film" : "infinity";
}

int runAnalyze(const AnalyzeArguments& arguments, bool filmGiven, bool objectGiven) {
  const std::optional<AnalyzeRequest> request = checkAnalyzeArguments(arguments, objectGiven);
  if (!request) return kUsageError;
  const std::vector<const AnalysisReport*>& reports = request->reports;
  const std::optional<double>& objectDistanceMm = request->objectDistanceMm;
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
  for (const AnalysisReport* report : reports) {
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
      "analyze", "Analyse a lens at its film distance: " + knownAnalysisKeys() + " (JSON keys)");
  const AnalyzeOptions options = addAnalyzeOptions(*analyze, *arguments);
  CLI::Option* film = options.filmDistance;
  CLI::Option* object = options.objectDistance;
  analyze->callback([arguments, film, object, &run] {
    const bool filmGiven = film->count() > 0, objectGiven = object->count() > 0;
    run = [arguments, filmGiven, objectGiven] {
      return runAnalyze(*arguments, filmGiven, objectGiven);
    };
  });
}

}  // namespace lenslab::cli
