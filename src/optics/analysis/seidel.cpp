#include "optics/analysis/seidel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics/analysis/chromatic.h"
#include "optics/analysis/paraxial_ray.h"
#include "optics/analysis/why_not.h"
#include "optics/field_coverage.h"
#include "optics/glass.h"
#include "optics/limiting_aperture.h"

namespace lenslab::optics {

namespace {

// n_F - n_C of the medium behind each surface (index i), and in front of the first (index -1:
// the object space, air, but computed all the same).
struct Dispersion {
  double objectSpace = 0;
  std::vector<double> behind;
};

Dispersion dispersionOf(const LensSystem& lens) {
  const auto atF = lens.withWavelength(kWavelengthFNm);
  const auto atC = lens.withWavelength(kWavelengthCNm);
  Dispersion out;
  out.behind.assign(lens.surfaces().size(), 0.0);
  if (!atF || !atC) return out;
  out.objectSpace = atF->surfaces().front().indexFront - atC->surfaces().front().indexFront;
  for (std::size_t i = 0; i < out.behind.size(); ++i)
    out.behind[i] = atF->surfaces()[i].indexRear - atC->surfaces()[i].indexRear;
  return out;
}

// The surface's r^4 sag coefficient beyond that of the sphere of its paraxial curvature c_p =
// c + 2 A_2: near the axis S(r) = (c_p / 2) r^2 + ((1 + k) c^3 / 8 + A_4) r^4 + O(r^5) (the
// conic's c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) = c r^2 / 2 + (1 + k) c^3 r^4 / 8 + ...), while
// the sphere of curvature c_p has c_p^3 / 8 there. So
//   delta = (1 + k) c^3 / 8 + A_4 - c_p^3 / 8 = k c^3 / 8 - A_2 (c_p^2 + c_p c + c^2) / 4 + A_4,
// the second form from c_p^3 - c^3 = (c_p - c)(c_p^2 + c_p c + c^2) with c_p - c = 2 A_2: it has no
// cancellation between large terms, and is exactly 0 for a sphere (k = A_2 = A_4 = 0), whose sums
// therefore stay bit for bit what they were. An r^2 term thus counts twice: it is part of the
// paraxial curvature, and, because it adds no r^4 sag of its own, the surface's r^4 sag falls
// short of the sphere it bends to (A_2 > 0; c_p^2 + c_p c + c^2 is never negative) or exceeds it.
double asphericR4DeparturePerMm3(const SurfaceGeometry& s) {
  const double c = s.curvaturePerMm, cp = s.paraxialCurvaturePerMm();
  const double a2 = s.profile.coefficient(2), a4 = s.profile.coefficient(4);
  return s.profile.conic() * c * c * c / 8.0 - a2 * (cp * cp + cp * c + c * c) / 4.0 + a4;
}

// Odd powers (A_3 r^3, A_5 r^5, ...) are not in the third-order scheme at all: the sag, and so
// the wavefront, gains terms in |r|^3, |r|^5, which are not polynomials in the pupil coordinates
// x and y, and an r^3 term acts at a lower order than S_I's rho^4. The sums leave them out and
// say which surfaces have them. (Even powers from r^6 on are fifth order and beyond, as a
// sphere's own higher terms are: leaving them out is what third order means.)
bool hasOddPowerTerms(const AsphericProfile& profile) {
  for (int power = 3; power <= profile.highestPower(); power += 2)
    if (profile.coefficient(power) != 0.0) return true;
  return false;
}

}  // namespace

std::string seidelOddTermsNote(const SeidelSums& sums) {
  if (sums.surfacesWithOddTerms.empty()) return {};
  std::string list;
  for (std::size_t k = 0; k < sums.surfacesWithOddTerms.size(); ++k) {
    if (k > 0) list += k + 1 == sums.surfacesWithOddTerms.size() ? " and " : ", ";
    list += std::to_string(sums.surfacesWithOddTerms[k] + 1);
  }
  const bool one = sums.surfacesWithOddTerms.size() == 1;
  return std::string(one ? "surface " : "surfaces ") + list + (one ? " has" : " have") +
         " odd-power aspheric terms (r^3, r^5, ...), which third-order sums do not describe: "
         "they are left out";
}

double seidelFieldHeightMm(const LensSystem& lens, const AnalysisSetup& setup) {
  double largest = 0.0;
  for (double fraction : setup.fieldFractions) largest = std::max(largest, fraction);
  return fieldScaleFor(lens, setup).imageHeightMm(largest > 0.0 ? largest : 1.0);
}

SeidelTerms& SeidelTerms::operator+=(const SeidelTerms& other) {
  s1 += other.s1;
  s2 += other.s2;
  s3 += other.s3;
  s4 += other.s4;
  s5 += other.s5;
  cl += other.cl;
  ct += other.ct;
  return *this;
}

std::optional<SeidelSums> computeSeidelSums(const LensSystem& lens,
                                            const std::optional<double>& objectDistanceFromFilmMm,
                                            double fieldHeightMm, std::string* whyNot) {
  if (!(fieldHeightMm > 0.0) || !std::isfinite(fieldHeightMm)) {
    sayWhyNot(whyNot, "the field height for the chief ray must be a positive distance");
    return std::nullopt;
  }
  const auto objectMm = objectFromFrontVertexMm(lens, objectDistanceFromFilmMm);
  if (!objectMm) {
    sayWhyNot(whyNot, "the object plane must lie in front of the lens");
    return std::nullopt;
  }
  const bool atInfinity = std::isinf(*objectMm);
  const auto& surfaces = lens.surfaces();
  const std::size_t stop = lens.stopIndex();

  // The height at the stop is linear in the ray's (height, slope) at the front vertex: a h + b u.
  const double a = traceParaxialRay(surfaces, 1.0, 0.0)[stop].heightMm;
  const double b = traceParaxialRay(surfaces, 0.0, 1.0)[stop].heightMm;

  // Marginal ray: to the limited edge of the stop (what FieldPoint's pupil edge aims at).
  const FirstOrderData& firstOrder = lens.firstOrder();
  const LimitingAperture limit = findLimitingAperture(lens, *objectMm);
  const double irisPupilMm = firstOrder.entrancePupil.diameterMm;
  double stopTargetMm = surfaces[stop].semiApertureMm;
  if (limit.paraxial && limit.paraxial->entrancePupilDiameterMm > 0.0 && irisPupilMm > 0.0 &&
      std::isfinite(irisPupilMm))
    stopTargetMm *= limit.paraxial->entrancePupilDiameterMm / irisPupilMm;
  double marginalHeight = 0.0, marginalSlope = 0.0;
  const double perObjectSlope = atInfinity ? 0.0 : a * *objectMm + b;  // stop height per unit u
  if (atInfinity) {
    if (!(std::abs(a) > 1e-12)) {
      sayWhyNot(whyNot,
                "no ray parallel to the axis reaches the stop (entrance pupil at infinity)");
      return std::nullopt;
    }
    marginalHeight = stopTargetMm / a;
  } else {
    if (!(std::abs(perObjectSlope) > 1e-12)) {
      sayWhyNot(whyNot,
                "the object lies on the entrance pupil, so no ray from it marks the pupil's edge");
      return std::nullopt;
    }
    marginalSlope = stopTargetMm / perObjectSlope;
    marginalHeight = marginalSlope * *objectMm;
  }
  // Chief ray through the stop's centre: unit slope from infinity, or from a unit object height.
  double chiefHeight = 0.0, chiefSlope = 0.0;
  if (atInfinity) {
    if (!(std::abs(a) > 1e-12)) {
      sayWhyNot(whyNot, "the entrance pupil is at infinity");
      return std::nullopt;
    }
    chiefSlope = 1.0;
    chiefHeight = -b / a;
  } else {
    chiefSlope = -a / perObjectSlope;
    chiefHeight = 1.0 + chiefSlope * *objectMm;
  }

  const auto marginal = traceParaxialRay(surfaces, marginalHeight, marginalSlope);
  auto chief = traceParaxialRay(surfaces, chiefHeight, chiefSlope);
  const double nObject = surfaces.front().indexFront;
  const double nImage = surfaces.back().indexRear;
  const double uImage = marginal.back().slopeAfter;
  if (!(std::abs(uImage) > 1e-12) || !std::isfinite(uImage)) {
    sayWhyNot(whyNot,
              "the lens is afocal: its image lies at infinity, where third-order sums in this "
              "form do not apply");
    return std::nullopt;
  }
  // Scale the chief ray so that its Gaussian image height H / (n' u') is fieldHeightMm.
  const double unitH = nObject * (marginal.front().slopeBefore * chief.front().heightMm -
                                  chief.front().slopeBefore * marginal.front().heightMm);
  const double unitImageHeight = unitH / (nImage * uImage);
  if (!(std::abs(unitImageHeight) > 1e-15) || !std::isfinite(unitImageHeight)) {
    sayWhyNot(whyNot, "the chief ray reaches no image height (the Lagrange invariant is zero)");
    return std::nullopt;
  }
  const double scale = fieldHeightMm / unitImageHeight;
  for (ParaxialRayAtSurface& r : chief) {
    r.heightMm *= scale;
    r.slopeBefore *= scale;
    r.slopeAfter *= scale;
  }
  const double H = unitH * scale;

  SeidelSums out;
  out.wavelengthNm = lens.wavelengthNm();
  out.chromatic = lensHasDispersion(lens.prescription());
  const Dispersion dispersion =
      out.chromatic ? dispersionOf(lens) : Dispersion{0.0, std::vector<double>(surfaces.size())};
  out.surfaces.resize(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const SurfaceGeometry& s = surfaces[i];
    // The spherical part sees the paraxial curvature (c + 2 A_2), as the paraxial rays do.
    const double n = s.indexFront, nAfter = s.indexRear, c = s.paraxialCurvaturePerMm();
    const double h = marginal[i].heightMm, hBar = chief[i].heightMm;
    const double u = marginal[i].slopeBefore, uAfter = marginal[i].slopeAfter;
    const double A = n * (h * c + u);
    const double ABar = n * (hBar * c + chief[i].slopeBefore);
    const double deltaUOverN = uAfter / nAfter - u / n;
    const double petzval = c * (1.0 / nAfter - 1.0 / n);
    const double deltaInvN2 = 1.0 / (nAfter * nAfter) - 1.0 / (n * n);
    const double dnBefore = i == 0 ? dispersion.objectSpace : dispersion.behind[i - 1];
    const double deltaDnOverN = dispersion.behind[i] / nAfter - dnBefore / n;
    SeidelTerms& t = out.surfaces[i];
    t.s1 = -A * A * h * deltaUOverN;
    t.s2 = -A * ABar * h * deltaUOverN;
    t.s3 = -ABar * ABar * h * deltaUOverN;
    t.s4 = -H * H * petzval;
    t.s5 = -ABar * ABar * ABar * h * deltaInvN2 +
           ABar * hBar * (2.0 * ABar * h - A * hBar) * c * (1.0 / nAfter - 1.0 / n);
    t.cl = A * h * deltaDnOverN;
    t.ct = ABar * h * deltaDnOverN;
    // The aspheric part (seidel.h): 8 delta (n' - n) h^4 times (h_bar / h)^j for S_I, S_II, S_III
    // and S_V, written without dividing by h, which is 0 on a surface at an intermediate image.
    const double aspheric = 8.0 * asphericR4DeparturePerMm3(s) * (nAfter - n);
    if (aspheric != 0.0) {
      t.s1 += aspheric * h * h * h * h;
      t.s2 += aspheric * h * h * h * hBar;
      t.s3 += aspheric * h * h * hBar * hBar;
      t.s5 += aspheric * h * hBar * hBar * hBar;
    }
    if (hasOddPowerTerms(s.profile)) out.surfacesWithOddTerms.push_back(i);
    out.total += t;
  }

  out.entrancePupilRadiusMm = std::abs(marginalHeight);
  if (!atInfinity && firstOrder.entrancePupil.diameterMm > 0.0 &&
      !firstOrder.entrancePupil.atInfinity) {
    // The marginal ray's height on the entrance-pupil plane.
    out.entrancePupilRadiusMm =
        std::abs(marginalHeight + marginalSlope * firstOrder.entrancePupil.positionMm);
  }
  out.fieldHeightMm = fieldHeightMm;
  out.lagrangeInvariant = H;
  out.imageIndex = nImage;
  out.marginalImageSlope = uImage;
  out.chiefObjectSlope = chief.front().slopeBefore;
  // The Gaussian image lies -h/u' behind the rear vertex; the film filmDistance behind it.
  out.gaussianImageFromFilmMm = -marginal.back().heightMm / uImage - lens.filmDistanceMm();

  const SeidelTerms& S = out.total;
  const double nu = nImage * uImage, nu2 = nImage * uImage * uImage;
  SeidelTransverse& tr = out.transverse;
  tr.sphericalMm = S.s1 / (2.0 * nu);
  tr.sphericalLongMm = -S.s1 / (2.0 * nu2);
  tr.comaTangentialMm = 3.0 * S.s2 / (2.0 * nu);
  tr.comaSagittalMm = S.s2 / (2.0 * nu);
  tr.tangentialFocusMm = -(3.0 * S.s3 + S.s4) / (2.0 * nu2);
  tr.sagittalFocusMm = -(S.s3 + S.s4) / (2.0 * nu2);
  tr.petzvalFocusMm = -S.s4 / (2.0 * nu2);
  tr.distortionMm = S.s5 / (2.0 * nu);
  tr.distortionPercent = 100.0 * tr.distortionMm / fieldHeightMm;
  tr.axialColourMm = S.cl / nu;
  tr.axialColourLongMm = -S.cl / nu2;
  tr.lateralColourMm = S.ct / nu;
  return out;
}

}  // namespace lenslab::optics
