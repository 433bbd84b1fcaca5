#pragma once
// Aperture shapes for the optics tests.

#include "optics/aperture_shape.h"

namespace lenslab::optics::testing {

// N blades of the given curvature (0 straight .. 1 round), the first corner rotationDeg from +x.
inline ApertureShape blades(int n, double curvature, double rotationDeg) {
  ApertureShape s;
  s.kind = ApertureShape::Kind::Blades;
  s.bladeCount = n;
  s.curvature = curvature;
  s.rotationDeg = rotationDeg;
  return s;
}

}  // namespace lenslab::optics::testing
