#pragma once
// Where the film goes when a lens is opened over a scene. A camera focuses where the scene's
// camera is focused (the default scene's chart at 3.6 m), so a lens opens sharp instead of at the
// film distance its file happens to carry (three bundled lenses carry one nearer than their
// infinity focus, and opened to "In focus: nothing"). The user can ask for the file's film
// distance instead (Settings::keepLensFilmDistance, the File menu, `set keep-film-distance`).
//
// Pure: the viewer puts the answer into the one ReplaceLens command that opens the lens, so
// opening and focusing are one undo step.

#include <optional>
#include <string>

namespace lenslab::optics {
class LensSystem;
}

namespace lenslab::app {

// The scene's focus, as far as opening a lens is concerned.
struct SceneFocus {
  // Object distance from the film, in mm (infinity allowed); nullopt when the scene gives none.
  std::optional<double> distanceMm;
  std::string whyNone;  // set with no distance: why ("the scene sets a film distance, ...")
};

struct OpeningFocus {
  std::optional<double> filmDistanceMm;  // the film distance to open with; nullopt: the file's
  std::string message;  // one line for the log: what was done, or why the file's was kept
};

// The choice as the File menu and the Open lens browser show it.
inline constexpr const char* kKeepFilmDistanceLabel = "Keep the lens file's film distance";
inline constexpr const char* kKeepFilmDistanceTooltip =
    "Open lenses at the film distance their file gives, instead of focused\n"
    "at the scene's focus distance as a camera would be";

// `lens` as built from the file (its film distance is the file's).
OpeningFocus focusForOpening(const optics::LensSystem& lens, const SceneFocus& scene,
                             bool keepFileFilmDistance);

}  // namespace lenslab::app
