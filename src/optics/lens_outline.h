#pragma once
// The true shape of a lens in its meridional (y-z) section, as plain data for the viewer's
// cross-section and its SVG export: one closed polygon per glass element (spherical profiles
// joined by flat edges at the clear aperture), the stop, and the film plane.
//
// Frame: the lens frame of the optics library: millimetres, optical axis z, film plane at
// z = 0, lens at z > 0 (object side +z); y is the height above the axis.

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "optics/prescription.h"

namespace lenslab::optics {

struct OutlinePoint {
  double zMm = 0, yMm = 0;
};

struct ElementOutline {
  std::size_t frontSurface = 0;  // the glass lies between this surface and the next
  double indexD = 1;
  bool cementedToNext = false;  // the next element shares this one's rear surface
  // The two boundaries, sampled at the same heights from -rim to +rim. A surface smaller than
  // the rim continues as a flat annulus, as lens drawings show. Quads between matching samples
  // fill the element even when it is concave (a meniscus).
  std::vector<OutlinePoint> front, rear;
  // front followed by rear reversed: a closed outline.
  std::vector<OutlinePoint> polygon() const;
};

struct StopOutline {
  std::size_t surface = 0;
  double zMm = 0;
  double apertureRadiusMm = 0;  // the opening (the stop's semi-diameter)
  double outerRadiusMm = 0;     // where the drawn bar ends
  // A shaped stop (aperture_shape.h): where its opening ends along +y and -y, the section's
  // plane (the blades' edges there), and its outline face-on in mm (x, y), closed. For the
  // circle both are apertureRadiusMm and the outline is empty.
  double openingUpMm = 0, openingDownMm = 0;
  std::vector<glm::dvec2> shapeOutlineMm;
};

struct LensOutline {
  std::vector<ElementOutline> elements;
  // Each refracting surface's profile from -semi-aperture to +semi-aperture, by surface index
  // (empty for the stop).
  std::vector<std::vector<OutlinePoint>> surfaceProfiles;
  std::vector<double> vertexZMm;  // z of each surface's vertex
  std::optional<StopOutline> stop;
  double frontVertexZMm = 0;
  double maxSemiApertureMm = 0;
};

// Axial sag of a spherical surface at height y: how far the surface lies toward the film from its
// vertex (positive for a positive radius). Heights beyond |radius| are clamped to it; a flat
// surface (infinite radius) has no sag.
double sphericalSagMm(double radiusMm, double heightMm);

// Works for invalid prescriptions too (semi-apertures beyond |radius| are clamped), so the
// viewer can draw a lens while the user is still fixing it. Never produces NaN.
LensOutline computeLensOutline(const Prescription& lens, int segmentsPerSurface = 48);

}  // namespace lenslab::optics
