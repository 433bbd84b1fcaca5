#pragma once
// Where the rays of a field meet a film plane, for the analyses that measure ray errors there
// (transverse ray fans, spot diagrams): a real ray traced with the clear apertures (so the rays
// the lens blocks are known), and the chief ray traced without them (the reference every error
// is measured from, even when a rim vignettes the chief ray itself).
//
// Frame: the lens frame (mm; film at z = 0, object side +z). A plane is named by its z; a film
// moved away from the lens by s mm is the plane z = -s.

#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

// The ray leaving the lens's rear surface toward the film, or nullopt when the lens blocks it
// or it does not travel toward -z.
std::optional<LensRay> exitTowardFilm(const LensSystem& lens, const LensRay& fromObject);

// (x, y) where an exit ray meets the plane z = planeZMm.
glm::dvec2 onPlane(const LensRay& exitRay, double planeZMm);

// The chief ray of `field` leaving the rear surface, traced without clear apertures; nullopt
// only when it misses a surface's sphere (which FieldPoint::resolve already excluded).
std::optional<LensRay> chiefExitRay(const LensSystem& lens, const FieldPoint& field);

// A field at image height imageHeightMm and its chief ray leaving the lens: where the ray fans
// and the spot diagram start. nullopt with *whyNot set when either cannot be found.
struct TracedField {
  FieldPoint field;
  LensRay chiefExit;
};
std::optional<TracedField> traceField(const LensSystem& lens, double imageHeightMm,
                                      const std::optional<double>& objectDistanceFromFilmMm,
                                      std::string* whyNot);

}  // namespace lenslab::optics
