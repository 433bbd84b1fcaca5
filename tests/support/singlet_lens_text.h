#pragma once
// A plano-convex singlet as .lens text, for the library's tests: its focal length is exactly
// R / (n - 1) = 2R (n = 1.5) whatever its thickness, so a test's expected figures are worked out
// by hand. The glass is thick enough at the rim: the front surface's sag plus 1.5 mm.

#include <cmath>
#include <cstdio>
#include <string>

namespace lenslab::testing {

// `header`: .lens lines before the rows (title, type, year, ...); `profile`: extra properties of
// the convex surface (" conic -1", " a4 1e-6").
inline std::string planoConvexLensText(const std::string& header, double radiusMm,
                                       const std::string& profile, double diameterMm) {
  const double semi = 0.5 * diameterMm;
  const double thicknessMm = radiusMm - std::sqrt(radiusMm * radiusMm - semi * semi) + 1.5;
  char rows[512];
  std::snprintf(rows, sizeof rows,
                "stop thickness 1 diameter %g\n"
                "surface radius %g thickness %.17g nd 1.5 diameter %g%s\n"
                "surface radius inf thickness %g diameter %g\n",
                semi, radiusMm, thicknessMm, diameterMm, profile.c_str(), 2.0 * radiusMm,
                diameterMm);
  return "lenslab-lens 1\n" + header + rows;
}

}  // namespace lenslab::testing
