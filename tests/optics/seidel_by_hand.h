#pragma once
// A hand computation for the distortion and field-curve tests, written apart from the production
// code: a paraxial y-u trace of the marginal and chief rays through a prescription and the
// surface-by-surface Seidel sums, as Welford gives them (W. T. Welford, Aberrations of Optical
// Systems, Adam Hilger 1986, ch. 8, eqs. 8.20-8.25):
//   A = n (u + y c),  Abar = n (ubar + ybar c),  H = n (ubar y - u ybar)   (Lagrange invariant)
//   S_I   = -sum A^2 y delta(u/n)
//   S_II  = -sum A Abar y delta(u/n)
//   S_III = -sum Abar^2 y delta(u/n)
//   S_IV  = -sum H^2 c delta(1/n)
//   S_V   =  sum (Abar / A) (S_III + S_IV)  (surface by surface)
// with n'u' = n u - y c (n' - n) at each surface and slopes u = dy/dz along the light. The
// wavefront aberration is W = S_I r^4 / 8 + S_II eta r^3 cos(phi) / 2 + S_III eta^2 r^2
// cos^2(phi) / 2 + (S_III + S_IV) eta^2 r^2 / 4 + S_V eta^3 r cos(phi) / 2 (normalised field eta
// and pupil r), and the transverse ray aberration is dW/d(pupil y) / (n' u'), u' the marginal
// ray's slope in image space (Welford sec. 8.3; the sign makes a positive S_IV, a positive
// lens's Petzval term, curve the field toward the lens). So, at the field of the traced chief
// ray (eta = 1):
//   distortion (fraction of the paraxial height eta') = S_V / (2 n' u' eta')
//   sagittal focus shift along the light              = -(S_III + S_IV) / (2 n' u'^2)
//   tangential focus shift                            = -(3 S_III + S_IV) / (2 n' u'^2)
// (a defocus dz moves a ray by u' r dz, which cancels 2 W_20 r / (n' u') when
// dz = -2 W_20 / (n' u'^2)).

#include <cmath>
#include <cstddef>
#include <vector>

#include "optics/prescription.h"

namespace lenslab::optics::testing {

struct SeidelByHand {
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0;
  double imageSlope = 0;       // u' of the marginal ray leaving the last surface
  double imageDistanceMm = 0;  // last surface to the paraxial image
  double imageHeightMm = 0;    // the chief ray's height there (eta')
  double distortionFraction() const { return s5 / (2.0 * imageSlope * imageHeightMm); }
  double sagittalShiftMm() const { return -(s3 + s4) / (2.0 * imageSlope * imageSlope); }
  double tangentialShiftMm() const { return -(3 * s3 + s4) / (2.0 * imageSlope * imageSlope); }
};

// Object at infinity (objectDistanceMm <= 0) or at objectDistanceMm in front of the first
// surface; the chief ray leaves the object at slope chiefSlope (infinity) or from height
// objectHeightMm (finite object) and passes through the centre of the stop.
inline SeidelByHand seidelByHand(const Prescription& p, double chiefSlope,
                                 double objectDistanceMm = 0.0, double objectHeightMm = 0.0) {
  const std::size_t n = p.surfaces.size();
  auto indexAfter = [&](std::size_t i) { return p.surfaces[i].mediumIndexD(); };
  struct Ray {
    double y, u;
  };
  // Trace from the first surface through surfaces [0, last), refracting at each, and to surface
  // `last` (not refracted there); returns the ray at each surface before refraction.
  auto trace = [&](Ray ray, std::vector<Ray>* atSurfaces, std::vector<double>* slopesAfter) {
    double nBefore = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (atSurfaces) atSurfaces->push_back(ray);
      const double c = p.surfaces[i].curvaturePerMm(), nAfter = indexAfter(i);
      ray.u = (nBefore * ray.u - ray.y * c * (nAfter - nBefore)) / nAfter;
      if (slopesAfter) slopesAfter->push_back(ray.u);
      if (i + 1 < n) ray.y += ray.u * p.surfaces[i].thicknessMm;
      nBefore = nAfter;
    }
    return ray;
  };
  std::size_t stop = 0;
  while (!p.surfaces[stop].isStop()) ++stop;
  auto heightAtStop = [&](Ray ray) {
    std::vector<Ray> at;
    trace(ray, &at, nullptr);
    return at[stop].y;
  };
  const bool atInfinity = objectDistanceMm <= 0.0;
  // Marginal ray: from the axial object point (or parallel), scaled to any height (the sums'
  // ratios below do not depend on it).
  const Ray marginalStart = atInfinity ? Ray{1.0, 0.0} : Ray{objectDistanceMm * 0.01, 0.01};
  // Chief ray: a combination of two rays that reaches the stop at height 0.
  Ray chiefStart;
  if (atInfinity) {
    const double a = heightAtStop({0.0, chiefSlope}), b = heightAtStop({1.0, chiefSlope});
    chiefStart = {-a / (b - a), chiefSlope};
  } else {
    // From (objectHeight) at the object with slope v: y at the first surface = h + v d.
    auto start = [&](double v) { return Ray{objectHeightMm + v * objectDistanceMm, v}; };
    const double a = heightAtStop(start(0.0)), b = heightAtStop(start(1.0));
    chiefStart = start(-a / (b - a));
  }
  std::vector<Ray> m, c;
  std::vector<double> mu, cu;
  const Ray mEnd = trace(marginalStart, &m, &mu);
  const Ray cEnd = trace(chiefStart, &c, &cu);
  const double lagrange = chiefStart.u * marginalStart.y - marginalStart.u * chiefStart.y;
  SeidelByHand out;
  double nBefore = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double cv = p.surfaces[i].curvaturePerMm(), nAfter = indexAfter(i);
    if (nAfter != nBefore) {
      const double a = nBefore * (m[i].u + m[i].y * cv);
      const double abar = nBefore * (c[i].u + c[i].y * cv);
      const double duN = mu[i] / nAfter - m[i].u / nBefore;
      const double s3 = -abar * abar * m[i].y * duN;
      const double s4 = -lagrange * lagrange * cv * (1.0 / nAfter - 1.0 / nBefore);
      out.s1 += -a * a * m[i].y * duN;
      out.s2 += -a * abar * m[i].y * duN;
      out.s3 += s3;
      out.s4 += s4;
      out.s5 += abar / a * (s3 + s4);
    }
    nBefore = nAfter;
  }
  out.imageSlope = mEnd.u;
  out.imageDistanceMm = -mEnd.y / mEnd.u;
  out.imageHeightMm = cEnd.y + cEnd.u * out.imageDistanceMm;
  return out;
}

}  // namespace lenslab::optics::testing
