#include "cli/analyze_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "common/distance_text.h"
#include "optics/focus.h"
#include "optics/relative_illumination.h"

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
  int points = 64;
};

// Surfaces count from 1 for users, as in `info`, the viewer's table and the scripts.
std::string surfaceList(const std::vector<int>& surfaces) {
  std::string text;
  for (int s : surfaces) text += (text.empty() ? "" : ", ") + std::to_string(s + 1);
  return text.empty() ? "-" : text;
}

nlohmann::json toJson(const AnalyzeArguments& arguments, const optics::LensSystem& lens,
                      const std::optional<double>& objectDistanceMm,
                      const optics::RelativeIllumination& curve) {
  nlohmann::json points = nlohmann::json::array();
  for (const optics::RelativeIlluminationPoint& p : curve.points) {
    nlohmann::json clipped = nlohmann::json::array();
    for (int s : p.clippedBy) clipped.push_back(s + 1);
    points.push_back({{"image_height_mm", p.imageHeightMm},
                      {"field_angle_deg", p.fieldAngleDeg ? nlohmann::json(*p.fieldAngleDeg)
                                                          : nlohmann::json(nullptr)},
                      {"total", p.total},
                      {"cos4", p.cos4},
                      {"vignetting", p.vignetting},
                      {"clipped_by", clipped},
                      {"rear_disk_total", p.rearDiskTotal.value_or(0.0)}});
  }
  nlohmann::json json{{"lens", arguments.lensPath},
                      {"film_distance_mm", lens.filmDistanceMm()},
                      {"film_diagonal_mm", arguments.filmDiagonalMm},
                      {"stop_diameter_mm", lens.stopDiameterMm()},
                      {"relative_illumination", points}};
  if (objectDistanceMm) {
    json["object_distance_mm"] =
        std::isfinite(*objectDistanceMm) ? nlohmann::json(*objectDistanceMm) : nullptr;
    json["object_at_infinity"] = std::isinf(*objectDistanceMm);
  }
  return json;
}

void printText(const AnalyzeArguments& arguments, const optics::LensSystem& lens,
               const std::optional<double>& objectDistanceMm,
               const optics::RelativeIllumination& curve) {
  std::printf("%s: relative illumination, film distance %s, film diagonal %s\n",
              arguments.lensPath.c_str(), millimetresText(lens.filmDistanceMm()).c_str(),
              millimetresText(arguments.filmDiagonalMm).c_str());
  if (objectDistanceMm) {
    const std::string where =
        std::isinf(*objectDistanceMm) ? "infinity" : distanceText(*objectDistanceMm);
    std::printf("focused at %s\n", where.c_str());
  }
  std::printf(
      "total = E(h)/E(0); cos4 = cos^4 of the image-side chief ray; vignetting = total / cos4;\n"
      "rear disk = total as the course scenes' sampling of the rear element's disk sees it\n");
  std::printf("%10s %8s %8s %11s %10s  %s\n", "height mm", "total", "cos4", "vignetting",
              "rear disk", "clipped by surfaces");
  for (const optics::RelativeIlluminationPoint& p : curve.points)
    std::printf("%10.3f %8.4f %8.4f %11.4f %10.4f  %s\n", p.imageHeightMm, p.total, p.cos4,
                p.vignetting, p.rearDiskTotal.value_or(0.0), surfaceList(p.clippedBy).c_str());
}

int runAnalyze(const AnalyzeArguments& arguments, bool filmGiven, bool objectGiven) {
  std::optional<double> objectDistanceMm;
  if (objectGiven) {
    objectDistanceMm = parseDistanceMm(arguments.objectDistance);
    if (!objectDistanceMm) {
      printUsageError("lenslab analyze",
                      "--object-distance: '" + arguments.objectDistance +
                          "' is not a positive distance (mm, or with a unit: 3.6 m; or 'inf')");
      return kUsageError;
    }
  }
  auto lens = loadLensOrReport(arguments.lensPath, "analyze");
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
  } else if (objectDistanceMm) {
    const optics::FocusResult film =
        optics::filmDistanceForObjectDistance(*lens, *objectDistanceMm);
    if (!film.ok()) {
      std::cerr << "lenslab analyze: cannot focus "
                << (std::isinf(*objectDistanceMm) ? "at infinity"
                                                  : "at " + distanceText(*objectDistanceMm))
                << ": " << film.whyNot << "\n";
      return 1;
    }
    lens = lens->withFilmDistance(*film.valueMm);
    if (!lens) return 1;
  }
  const auto curve =
      optics::relativeIllumination(*lens, 0.5 * arguments.filmDiagonalMm, arguments.points, {},
                                   /*withRearDiskTotal=*/true);
  if (!curve) {
    std::cerr << "lenslab analyze: no ray from the centre of the film passes the lens, so there is "
                 "no illumination to compare with\n";
    return 1;
  }
  if (arguments.json)
    std::cout << toJson(arguments, *lens, objectDistanceMm, *curve).dump(2) << "\n";
  else
    printText(arguments, *lens, objectDistanceMm, *curve);
  return 0;
}

}  // namespace

void addAnalyzeCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<AnalyzeArguments>();
  CLI::App* analyze =
      app.add_subcommand("analyze", "Analyse a lens: relative illumination and vignetting");
  analyze->add_option("LENS", arguments->lensPath, "Lens file (.dat, pbrt format)")->required();
  analyze->add_flag("--json", arguments->json, "Print JSON instead of a table");
  auto* film = analyze
                   ->add_option("--film-distance", arguments->filmDistanceMm,
                                "Film distance in mm (rear vertex to film; default: the file's)")
                   ->check(PositiveFiniteNumber());
  auto* object = analyze->add_option(
      "--object-distance", arguments->objectDistance,
      "Focus first: object distance from the film plane (mm, or 3.6 m), or 'inf'");
  object->excludes(film);
  analyze
      ->add_option("--film-diagonal", arguments->filmDiagonalMm,
                   "Film diagonal in mm; the curve runs from the axis to its corner (default "
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
  analyze->callback([arguments, film, object, &run] {
    const bool filmGiven = film->count() > 0, objectGiven = object->count() > 0;
    run = [arguments, filmGiven, objectGiven] {
      return runAnalyze(*arguments, filmGiven, objectGiven);
    };
  });
}

}  // namespace lenslab::cli
