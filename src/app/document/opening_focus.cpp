#include "app/document/opening_focus.h"

#include <cmath>

#include "common/distance_text.h"
#include "optics/focus.h"
#include "optics/lens_system.h"

namespace lenslab::app {

OpeningFocus focusForOpening(const optics::LensSystem& lens, const SceneFocus& scene,
                             bool keepFileFilmDistance) {
  const std::string fileFilm = millimetresText(lens.filmDistanceMm());
  if (keepFileFilmDistance) {
    return {std::nullopt,
            "Kept the lens file's film distance " + fileFilm + " (keep film distance is on)"};
  }
  if (!scene.distanceMm) {
    if (scene.whyNone.empty()) return {};
    return {std::nullopt, "Kept the lens file's film distance " + fileFilm + ": " + scene.whyNone};
  }
  const std::string where = std::isinf(*scene.distanceMm)
                                ? std::string("infinity")
                                : distanceText(*scene.distanceMm) + " from the film";
  const optics::FocusResult focus = optics::filmDistanceForObjectDistance(lens, *scene.distanceMm);
  if (!focus.ok()) {
    return {std::nullopt, "Kept the lens file's film distance " + fileFilm +
                              ": it cannot focus at the scene's focus distance, " + where + " (" +
                              focus.whyNot + ")"};
  }
  return {*focus.valueMm, "Focused at " + where + " (the scene's focus distance): film distance " +
                              millimetresText(*focus.valueMm) + ", the file's " + fileFilm};
}

}  // namespace lenslab::app
