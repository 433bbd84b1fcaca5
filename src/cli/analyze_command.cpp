#include "cli/analyze_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/analyze/analysis_report.h"
#include "cli/analyze_options.h"
#include "cli/exit_codes.h"
#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "common/distance_text.h"
#include "optics/field_coverage.h"
#include "optics/focus.h"

namespace lenslab::cli {

namespace {

std::string objectText(const std::optional<double>& objectDistanceMm) {
  return objectDistanceMm ? distanceText(*objectDistanceMm) + " from the film" : "infinity";
}

// Where the analysed lens is focused.
struct Focus {
  bool atObject = true;  // focused at the analysed object; false: --film-distance put the film
  // The object distance in focus, from the film (infinity allowed); nullopt when none is
  // (the film nearer the lens than its infinity focus: whyNot).
  std::optional<double> objectDistanceMm;
  std::string whyNot;
};

// "focused at infinity", "focused at 3.720 m from the film", or why no object is in focus.
std::string focusText(const Focus& focus) {
  if (!focus.objectDistanceMm) return "focused at no object distance: " + focus.whyNot;
  if (std::isinf(*focus.objectDistanceMm)) return "focused at infinity";
  return "focused at " + distanceText(*focus.objectDistanceMm) + " from the film";
}

// Whether the analysed object is the one in focus: a given film within 1 um of the film distance
// that focuses it (inside the depth of focus, 2 lambda N^2, of any lens slower than f/0.7).
bool objectInFocus(const Focus& focus, const optics::LensSystem& lens,
                   const std::optional<double>& objectDistanceMm) {
  if (focus.atObject) return true;
  const optics::FocusResult film = optics::filmDistanceForObjectDistance(
      lens, objectDistanceMm.value_or(std::numeric_limits<double>::infinity()));
  return film.ok() && std::abs(*film.valueMm - lens.filmDistanceMm()) <= 1e-3;
}

// The film and fields a lens file's design states as image heights (FTYP 2 or 3, YIM, a
// patent's image height without an angle of view): a film whose half diagonal is the largest,
// and each design field as a fraction of it. Object angles and heights are left to the defaults:
// where they land on the film takes a search through the lens.
struct DesignFilm {
  double diagonalMm = 0.0;
  std::vector<double> fieldFractions;
};

std::optional<DesignFilm> designFilm(const optics::DesignFields& fields) {
  if (fields.kind != optics::FieldKind::ParaxialImageHeightMm &&
      fields.kind != optics::FieldKind::RealImageHeightMm)
    return std::nullopt;
  double largest = 0.0;
  for (double value : fields.values)
    if (std::isfinite(value)) largest = std::max(largest, std::abs(value));
  if (!(largest > 0.0)) return std::nullopt;
  DesignFilm film;
  film.diagonalMm = 2.0 * largest;
  for (double value : fields.values)
    if (std::isfinite(value))
      film.fieldFractions.push_back(std::min(std::abs(value) / largest, 1.0));
  std::sort(film.fieldFractions.begin(), film.fieldFractions.end());
  film.fieldFractions.erase(std::unique(film.fieldFractions.begin(), film.fieldFractions.end()),
                            film.fieldFractions.end());
  return film;
}

// Which of the settings the command line gave (the others come from each lens's design, or
// the defaults).
struct GivenOptions {
  bool film = false, object = false, wavelength = false, filmDiagonal = false, fields = false;
};

// One lens's analyses: the JSON and the text `analyze` prints for it alone.
struct LensAnalysis {
  nlohmann::json json;
  std::string text;
  bool complete = true;  // every report ran (none unavailable)
};

// The analyses of the lens at `lensPath` with the options' settings; nullopt once the reason it
// cannot be analysed at all (unreadable, cannot be focused) has been printed.
std::optional<LensAnalysis> analyzeLens(const std::string& lensPath,
                                        const AnalyzeArguments& arguments,
                                        const AnalyzeRequest& request, const GivenOptions& given) {
  const std::vector<const AnalysisReport*>& reports = request.reports;
  const std::optional<double>& objectDistanceMm = request.objectDistanceMm;
  CommandWavelength wavelength;
  const optics::LoadedLens loaded = loadLensAtWavelengthOrReport(
      lensPath, "analyze",
      given.wavelength ? std::optional<double>(arguments.wavelengthNm) : std::nullopt,
      {kAnalyzeMinWavelengthNm, kAnalyzeMaxWavelengthNm}, wavelength);
  auto lens = loaded.system;
  if (!lens) return std::nullopt;
  // The film and fields: the options', else the design's image heights, else the defaults.
  double filmDiagonalMm = arguments.filmDiagonalMm;
  std::vector<double> fieldFractions = arguments.fieldFractions;
  const char* filmFrom = given.filmDiagonal ? "option" : "default";
  if (const auto film = designFilm(loaded.file.design.fields); film && !given.filmDiagonal) {
    filmDiagonalMm = film->diagonalMm;
    filmFrom = "design";
    if (!given.fields) fieldFractions = film->fieldFractions;
  }
  if (arguments.stopDiameterMm > 0.0) {
    // Before focusing: the focus of a real lens moves as it is stopped down.
    lens = lens->withStopDiameter(arguments.stopDiameterMm);
    if (!lens) {
      std::cerr << "lenslab analyze: --stop-diameter " << arguments.stopDiameterMm
                << " mm is beyond what a lens may have\n";
      return std::nullopt;
    }
  }
  // Where the lens is focused: at the object (infinity unless --object-distance says otherwise)
  // unless --film-distance puts the film elsewhere; then the header says which object distance
  // that film distance focuses, so that numbers for an object at infinity are never read as the
  // in-focus ones when they are not.
  Focus focus;
  if (given.film) {
    lens = lens->withFilmDistance(arguments.filmDistanceMm);
    if (!lens) {
      std::cerr << "lenslab analyze: --film-distance " << arguments.filmDistanceMm
                << " mm is beyond what a lens may have\n";
      return std::nullopt;
    }
    const optics::FocusResult object =
        optics::objectDistanceForFilmDistance(*lens, lens->filmDistanceMm());
    focus.atObject = false;
    focus.objectDistanceMm = object.valueMm;
    focus.whyNot = object.whyNot;
  } else {
    const double focusAtMm = objectDistanceMm.value_or(std::numeric_limits<double>::infinity());
    const optics::FocusResult film = optics::filmDistanceForObjectDistance(*lens, focusAtMm);
    if (!film.ok()) {
      // Named by its file: with --compare, either lens may be the one that cannot.
      std::cerr << "lenslab analyze: " << lensPath << ": cannot focus "
                << (objectDistanceMm ? "at " + distanceText(*objectDistanceMm)
                                     : std::string("at infinity (the default object distance)"))
                << ": " << film.whyNot
                << "\n(give --film-distance MM to analyse the lens with the film there)\n";
      return std::nullopt;
    }
    lens = lens->withFilmDistance(*film.valueMm);
    if (!lens) return std::nullopt;
    focus.objectDistanceMm = focusAtMm;
  }

  AnalyzeContext context;
  context.lensPath = lensPath;
  context.lens = lens;
  context.points = arguments.points;
  context.setup.fieldFractions = fieldFractions;
  context.setup.filmHalfDiagonalMm = 0.5 * filmDiagonalMm;
  context.setup.objectDistanceFromFilmMm = objectDistanceMm;
  context.setup.wavelengthNm = wavelength.nm;
  // The fields' one scale (optics/field_coverage.h), searched once for every report. A film
  // corner beyond the lens's image circle is said in the header and the JSON, as the viewer's
  // panels say it: the fields then spread over the circle, not the film.
  const optics::FieldScale fieldScale = optics::fieldScaleFor(*lens, context.setup);
  context.setup.coverageMm = fieldScale.coverageMm;
  const std::string coverageWarning = optics::coverageWarning(fieldScale);

  const bool inFocus = objectInFocus(focus, *lens, objectDistanceMm);
  nlohmann::json json{
      {"lens", lensPath},
      {"film_distance_mm", lens->filmDistanceMm()},
      {"film_diagonal_mm", filmDiagonalMm},
      // "option", "design" (twice the file's largest design image height) or "default".
      {"film_diagonal_from", filmFrom},
      {"stop_diameter_mm", lens->stopDiameterMm()},
      {"wavelength_nm", wavelength.nm},
      {"wavelength_from", wavelength.from},  // "option", "design" (the file's) or "default"
      {"object_distance_mm",
       objectDistanceMm ? nlohmann::json(*objectDistanceMm) : nlohmann::json(nullptr)},
      {"object_at_infinity", !objectDistanceMm.has_value()},
      // Where the lens is focused, and so whether the object is sharp:
      // "object_distance" (focused there first) or "film_distance" (as given).
      {"focused_by", focus.atObject ? "object_distance" : "film_distance"},
      {"focus_object_distance_mm", focus.objectDistanceMm && std::isfinite(*focus.objectDistanceMm)
                                       ? nlohmann::json(*focus.objectDistanceMm)
                                       : nlohmann::json(nullptr)},
      {"focused_at_infinity", focus.objectDistanceMm && std::isinf(*focus.objectDistanceMm)},
      {"object_in_focus", inFocus},
      {"field_fractions", fieldFractions}};
  std::string text;
  if (!focus.whyNot.empty()) json["focus_why_not"] = focus.whyNot;
  json["film_covered"] = fieldScale.filmCovered();
  json["field_radius_mm"] = fieldScale.radiusMm();
  if (!coverageWarning.empty()) json["coverage_warning"] = coverageWarning;
  // The header says where the film is, what it focuses, and which object the numbers are for.
  text += lensPath + ": film distance " + millimetresText(lens->filmDistanceMm()) + " (" +
          (focus.atObject ? "" : "as given, ") + focusText(focus) + "), film diagonal " +
          millimetresText(filmDiagonalMm) +
          (std::string(filmFrom) == "design" ? " (twice the lens's design image height)" : "") +
          ", object at " + objectText(objectDistanceMm) + (inFocus ? "" : " (out of focus)") + ", ";
  char wavelengthText[32];
  std::snprintf(wavelengthText, sizeof wavelengthText, "%.2f nm ", wavelength.nm);
  text += wavelengthText + wavelength.describe() + "\n";
  if (!coverageWarning.empty()) text += "warning: " + coverageWarning + "\n";
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
  return LensAnalysis{std::move(json), std::move(text), unavailable.empty()};
}

int runAnalyze(const AnalyzeArguments& arguments, const GivenOptions& given) {
  const std::optional<AnalyzeRequest> request = checkAnalyzeArguments(arguments, given.object);
  if (!request) return kUsageError;
  const std::optional<LensAnalysis> lens =
      analyzeLens(arguments.lensPath, arguments, *request, given);
  if (!lens) return 1;
  if (arguments.comparePath.empty()) {
    std::cout << (arguments.json ? lens->json.dump(2) + "\n" : lens->text);
    return lens->complete ? 0 : 1;
  }
  // --compare B: the reference analysed with the same options, as `analyze B` alone would be;
  // both in one JSON object, {"lens": A's, "reference": B's}, or one text after the other.
  const std::optional<LensAnalysis> reference =
      analyzeLens(arguments.comparePath, arguments, *request, given);
  if (!reference) return 1;
  if (arguments.json) {
    const nlohmann::json both{{"lens", lens->json}, {"reference", reference->json}};
    std::cout << both.dump(2) << "\n";
  } else {
    std::cout << lens->text << "\n=== reference ===\n" << reference->text;
  }
  return lens->complete && reference->complete ? 0 : 1;
}

}  // namespace

void addAnalyzeCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<AnalyzeArguments>();
  CLI::App* analyze = app.add_subcommand(
      "analyze",
      "Analyse a lens focused at the object distance (infinity by default) or at a "
      "given film distance: " +
          knownAnalysisKeys() + " (JSON keys)");
  const AnalyzeOptions options = addAnalyzeOptions(*analyze, *arguments);
  analyze->callback([arguments, options, &run] {
    GivenOptions given;
    given.film = options.filmDistance->count() > 0;
    given.object = options.objectDistance->count() > 0;
    given.wavelength = options.wavelength->count() > 0;
    given.filmDiagonal = options.filmDiagonal->count() > 0;
    given.fields = options.fields->count() > 0;
    run = [arguments, given] { return runAnalyze(*arguments, given); };
  });
}

}  // namespace lenslab::cli
