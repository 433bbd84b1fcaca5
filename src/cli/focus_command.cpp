#include "cli/focus_command.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/json_numbers.h"
#include "cli/lens_loading.h"
#include "cli/number_validators.h"
#include "cli/usage_error.h"
#include "common/distance_text.h"
#include "optics/focus.h"
#include "optics/lens_file_formats.h"

namespace lenslab::cli {

namespace {

struct FocusArguments {
  std::string lensPath;
  std::string objectDistance;  // text, so that "inf" works
  double filmDistanceMm = 0.0;
  bool json = false;
};

int runFocus(const FocusArguments& arguments, bool objectGiven) {
  std::optional<double> objectDistance;
  if (objectGiven) {
    objectDistance = parseDistanceMm(arguments.objectDistance);
    if (!objectDistance) {
      printUsageError("lenslab focus",
                      "--object-distance: '" + arguments.objectDistance +
                          "' is not a positive distance (mm, or with a unit: 3.6 m; or 'inf')");
      return 2;
    }
  }
  const auto lens = loadLensOrReport(arguments.lensPath, "focus");
  if (!lens) return 1;
  if (objectGiven) {
    const optics::FocusResult film = optics::filmDistanceForObjectDistance(*lens, *objectDistance);
    if (!film.ok()) {
      std::cerr << "lenslab focus: no solution: " << film.whyNot << "\n";
      return 1;
    }
    if (arguments.json) {
      std::cout << nlohmann::json{{"lens", arguments.lensPath},
                                  {"object_distance_mm", finiteOrNull(*objectDistance)},
                                  {"object_distance_from", "film"},
                                  {"film_distance_mm", *film.valueMm},
                                  {"efl_mm", lens->firstOrder().eflMm}}
                       .dump(2)
                << "\n";
    } else {
      // An object at infinity is at no distance "from the film".
      const std::string where = std::isinf(*objectDistance)
                                    ? std::string("infinity")
                                    : distanceText(*objectDistance) + " from the film";
      std::printf("film distance %s (rear vertex to film) focuses an object at %s\n",
                  millimetresText(*film.valueMm).c_str(), where.c_str());
    }
    return 0;
  }
  const optics::FocusResult object =
      optics::objectDistanceForFilmDistance(*lens, arguments.filmDistanceMm);
  if (!object.ok()) {
    std::cerr << "lenslab focus: no solution: " << object.whyNot << "\n";
    return 1;
  }
  if (arguments.json) {
    std::cout << nlohmann::json{{"lens", arguments.lensPath},
                                {"film_distance_mm", arguments.filmDistanceMm},
                                {"object_distance_mm", finiteOrNull(*object.valueMm)},
                                {"object_distance_from", "film"},
                                {"object_at_infinity", std::isinf(*object.valueMm)}}
                     .dump(2)
              << "\n";
  } else if (std::isinf(*object.valueMm)) {
    std::printf("film distance %s focuses at infinity\n",
                millimetresText(arguments.filmDistanceMm).c_str());
  } else {
    std::printf("film distance %s focuses an object at %s from the film\n",
                millimetresText(arguments.filmDistanceMm).c_str(),
                distanceText(*object.valueMm).c_str());
  }
  return 0;
}

}  // namespace

void addFocusCommand(CLI::App& app, SubcommandRunner& run) {
  auto arguments = std::make_shared<FocusArguments>();
  CLI::App* focus = app.add_subcommand(
      "focus", "Real-ray focus: the film distance for an object distance, or the reverse");
  focus
      ->add_option("LENS", arguments->lensPath,
                   "Lens file (" + optics::lensFileExtensionsText() + ")")
      ->required();
  auto* object = focus->add_option("--object-distance", arguments->objectDistance,
                                   "Object distance from the film plane (mm, or 3.6 m), or 'inf'");
  auto* film = focus
                   ->add_option("--film-distance", arguments->filmDistanceMm,
                                "Film distance in mm (rear vertex to film): print the object "
                                "distance in focus instead")
                   ->check(PositiveFiniteNumber());
  object->excludes(film);
  focus->add_flag("--json", arguments->json, "Print JSON instead of text");
  focus->callback([arguments, object, film, &run] {
    if (object->count() == 0 && film->count() == 0)
      throw CLI::RequiredError("--object-distance or --film-distance");
    const bool objectGiven = object->count() > 0;
    run = [arguments, objectGiven] { return runFocus(*arguments, objectGiven); };
  });
}

}  // namespace lenslab::cli
