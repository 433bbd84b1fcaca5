#pragma once
// Distortion: how far the real chief ray lands from the Gaussian image height, from the axis to
// the film's corner, and the image of a square grid through the lens.
//
// percent = 100 (y - y0) / y0, with y the real chief ray's height on the film (traced, not
// assumed) and y0 the paraxial chief ray's height on the film for the same object point
// (analysis/paraxial_image.h):
// - object at infinity: y0 = f tan(theta), f the EFL and theta the chief ray's angle in object
//   space (FieldPoint::fieldAngleDeg): "f-tan(theta) distortion";
// - object at a finite distance: y0 = m Y, m the paraxial magnification of the object plane and
//   Y the height of the chief ray's object point: the same Gaussian image height for a near
//   object (f tan(theta) would mix the entrance pupil's position into the reference).
// Both are heights in the Gaussian image plane. With the film elsewhere (the course lenses' film
// distances are the full-aperture best focus, a fraction of a millimetre in front of the
// paraxial one) the paraxial chief ray, which leaves through the centre of the exit pupil, meets
// the film at that height times (exit pupil to film) / (exit pupil to Gaussian focus), and y0
// is scaled by that (ParaxialImage::filmHeightScale): a focus shift scales the whole picture and
// is not distortion, which therefore still starts from 0 on the axis (the double-Gauss at its
// film distance would otherwise read +1.2 % there). With the film at the Gaussian focus y0 is
// exactly f tan(theta) or m Y. On the axis percent is 0 by definition (the limit of an even
// function of the field).

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::optics {

struct DistortionPoint {
  double imageHeightMm = 0.0;  // the requested image height (the real chief ray's, when found)
  // Each nullopt, with whyNot, when no chief ray reaches this image height.
  std::optional<double> fieldAngleDeg;
  std::optional<double> idealHeightMm;  // y0, on the film
  std::optional<double> percent;
  std::string whyNot;
};

struct DistortionCurve {
  std::vector<DistortionPoint> points;  // evenly spaced image heights, axis to corner
  bool objectAtInfinity = true;
  double eflMm = 0.0;
  std::optional<double> magnification;  // finite object only
  double filmHeightScale = 1.0;         // ParaxialImage::filmHeightScale
};

// `points` (at least 2) image heights from 0 to setup.filmHalfDiagonalMm. nullopt, with
// *whyNot, when there is no Gaussian image to measure against (afocal lens, object at the front
// focal point).
std::optional<DistortionCurve> distortionCurve(const LensSystem& lens, const AnalysisSetup& setup,
                                               int points, std::string* whyNot = nullptr);

// Grid distortion: a square grid of object points (directions (tan theta_x, tan theta_y) for an
// object at infinity, object-plane points otherwise) whose Gaussian image fills the film, and
// where the real chief rays put the same points. Lines in film coordinates (mm, x across, y up,
// the film's centre at 0); a real line is broken where its chief rays are not found.
struct DistortionGrid {
  double filmHalfWidthMm = 0.0;
  double filmHalfHeightMm = 0.0;
  std::vector<std::vector<glm::dvec2>> ideal;
  std::vector<std::vector<glm::dvec2>> real;
};

// The film is setup.filmHalfDiagonalMm across its half diagonal with width / height =
// filmAspect; the grid's cells are squares, cellsDown of them from the bottom edge to the top.
// By the lens's rotational symmetry a grid point's real image lies on the line from the centre
// through its Gaussian image, at the radius where the real chief ray of the same field angle
// lands; that radius is interpolated (cubic) between real chief rays traced every
// `radialSamples`-th of the half diagonal, continued past the corner as far as the grid needs
// (pincushion). nullopt as for distortionCurve.
std::optional<DistortionGrid> distortionGrid(const LensSystem& lens, const AnalysisSetup& setup,
                                             double filmAspect = 1.5, int cellsDown = 8,
                                             int radialSamples = 64, std::string* whyNot = nullptr);

}  // namespace lenslab::optics
