#pragma once
// Focusing with real rays: where the film must be for an object distance, and which object
// distance is sharp for a film distance.
//
// "In focus" means the plane of least RMS spot size of an axial fan of real rays that fill the
// beam that really passes in equal-area zones on the stop (meridional least squares; closed
// form, e.g. Smith, Modern Optical Engineering, ch. 11, "best focus"). The beam is the widest
// passing axial ray's (limiting_aperture.h): the iris when it limits, a rim when the iris is
// opened past it, so the focus does not depend on how far past the rims the iris opens. Rays are
// aimed at the stop, not at the front element, so the
// answer stays well defined at f/22 and at 1:1 magnification, where pbrt's thick-lens focusing
// fails (mmp/pbrt-v3#122, #123). As the stop closes it converges to the paraxial focus.
//
// Distances: object distances are measured from the film plane along the axis (as a camera's
// distance scale is); infinity is allowed.

#include <optional>
#include <string>

namespace lenslab::optics {

class LensSystem;

struct FocusResult {
  std::optional<double> valueMm;
  std::string whyNot;  // set when there is no solution
  bool ok() const { return valueMm.has_value(); }
};

// Whether the lens forms a real image of an object at infinity, in the words that `info`, `focus`
// and the viewer all use: whyNot reads "the lens forms no real image of an object at infinity:"
// and the reason (no axial ray passes the lens; the rays that pass leave it parallel; or they
// leave it diverging, from a virtual image in front of the rear vertex).
struct InfinityImage {
  std::optional<double> focusBehindRearVertexMm;  // the real-ray best focus, when it is real
  std::string whyNot;
  bool ok() const { return focusBehindRearVertexMm.has_value(); }
};
InfinityImage infinityImage(const LensSystem& lens);

// Film distance (last surface to film) that focuses an axial object `objectDistanceMm` from the
// film (std::numeric_limits<double>::infinity() for infinity). When two film positions focus the
// object (beyond 1:1), returns the one nearer the lens.
FocusResult filmDistanceForObjectDistance(const LensSystem& lens, double objectDistanceMm);

// Object distance from the film that is in focus when the film is `filmDistanceMm` behind the
// rear vertex; infinity when it is the infinity focus, no solution when the film is nearer than
// that.
FocusResult objectDistanceForFilmDistance(const LensSystem& lens, double filmDistanceMm);

// The nearest object that any film position brings into focus, by the same real-ray criterion:
// the minimum over film distances of objectDistanceForFilmDistance (near 1:1 for a simple lens,
// where it is 4 f plus the principal-plane gap).
struct ClosestFocus {
  double objectDistanceMm = 0.0;  // from the film
  double filmDistanceMm = 0.0;    // rear vertex to film, at that focus
};
// nullopt when the lens forms no real image.
std::optional<ClosestFocus> closestFocus(const LensSystem& lens);

// Real-ray best focus for an axial object `objectFromFrontVertexMm` in front of the front vertex
// (infinity allowed): distance of the focus behind the rear vertex (negative when the image is
// virtual, in front of it). nullopt when no zone's ray passes.
std::optional<double> bestFocusBehindRearVertexMm(const LensSystem& lens,
                                                  double objectFromFrontVertexMm);

}  // namespace lenslab::optics
