#include "optics/paraxial.h"

#include <cmath>
#include <numbers>

namespace lenslab::optics {

namespace {

// Paraxial ray-transfer matrix acting on (y, w) with w = n u, the reduced angle. In these
// coordinates refraction is [[1, 0], [-phi, 1]] with phi = (n' - n) c and a gap of thickness d in
// index n is [[1, d/n], [0, 1]]; both have determinant 1 (e.g. Smith, Modern Optical Engineering,
// ch. 3 / Gerrard and Burch, Introduction to Matrix Methods in Optics).
struct Matrix {
  double a = 1, b = 0, c = 0, d = 1;
  Matrix then(const Matrix& next) const {  // next * this
    return {next.a * a + next.b * c, next.a * b + next.b * d, next.c * a + next.d * c,
            next.c * b + next.d * d};
  }
};

Matrix refraction(const SurfaceGeometry& s) {
  return {1, 0, -(s.indexRear - s.indexFront) * s.paraxialCurvaturePerMm(), 1};
}

// Surfaces [first, last] with the gaps between them (light going front to rear).
Matrix span(const std::vector<SurfaceGeometry>& surfaces, std::size_t first, std::size_t last) {
  Matrix m;
  for (std::size_t i = first; i <= last; ++i) {
    if (i > first) {
      const double gap = surfaces[i - 1].vertexZMm - surfaces[i].vertexZMm;
      m = m.then({1, gap / surfaces[i - 1].indexRear, 0, 1});
    }
    m = m.then(refraction(surfaces[i]));
  }
  return m;
}

constexpr double kTiny = 1e-12;

}  // namespace

double FirstOrderData::fieldOfViewDeg(double filmDiagonalMm) const {
  if (afocal || eflMm == 0.0) return 0.0;
  return 2.0 * std::atan(0.5 * filmDiagonalMm / std::abs(eflMm)) * 180.0 / std::numbers::pi;
}

FirstOrderData computeFirstOrder(const std::vector<SurfaceGeometry>& surfaces,
                                 std::size_t stopIndex, double wavelengthNm) {
  FirstOrderData out;
  out.wavelengthNm = wavelengthNm;
  if (surfaces.empty()) return out;
  const std::size_t last = surfaces.size() - 1;
  const double nObject = surfaces.front().indexFront;
  const double nImage = surfaces.back().indexRear;
  out.totalTrackMm = surfaces.front().vertexZMm;
  out.lensLengthMm = surfaces.front().vertexZMm - surfaces.back().vertexZMm;

  const Matrix m = span(surfaces, 0, last);
  out.afocal = std::abs(m.c) < kTiny;
  if (!out.afocal) {
    // An input ray parallel to the axis at height 1 leaves with y = A, w = C: it crosses the axis
    // A n'/(-C) behind the rear vertex, and EFL = n' / (-C) (n' = 1 in air).
    out.eflMm = -nImage / m.c;
    out.bflMm = -m.a * nImage / m.c;
    // A ray from the front focal point leaves parallel: C s/n + D = 0 with s in front.
    out.fflMm = -m.d * nObject / m.c;
    const double frontFocalLength = nObject * out.eflMm / nImage;
    out.frontPrincipalPlaneMm = frontFocalLength - out.fflMm;
    out.rearPrincipalPlaneMm = out.bflMm - out.eflMm;
  }

  const double stopRadius = surfaces[stopIndex].semiApertureMm;
  // Entrance pupil: the object-space plane p (from the front vertex) conjugate to the stop. With
  // M the front-vertex-to-stop matrix, a ray (y, w) at p reaches the stop at
  // A y + (B - A p / n) w, independent of w when p = n B / A; the magnification is A.
  if (stopIndex == 0) {
    out.entrancePupil = {2 * stopRadius, 0.0, surfaces.front().vertexZMm, false};
  } else {
    Matrix front = span(surfaces, 0, stopIndex - 1);
    front = front.then({1,
                        (surfaces[stopIndex - 1].vertexZMm - surfaces[stopIndex].vertexZMm) /
                            surfaces[stopIndex - 1].indexRear,
                        0, 1});
    if (std::abs(front.a) < kTiny) {
      out.entrancePupil.atInfinity = true;
    } else {
      const double p = nObject * front.b / front.a;
      out.entrancePupil = {2 * stopRadius / std::abs(front.a), p, surfaces.front().vertexZMm - p,
                           false};
    }
  }
  // Exit pupil: image-space plane q behind the rear vertex conjugate to the stop. With M the
  // stop-to-rear-vertex matrix, y_q = (A + q C / n') y + (B + q D / n') w, so q = -n' B / D and the
  // magnification is A - B C / D = 1 / D (det M = 1).
  if (stopIndex == last) {
    out.exitPupil = {2 * stopRadius, 0.0, surfaces.back().vertexZMm, false};
  } else {
    Matrix rear{1,
                (surfaces[stopIndex].vertexZMm - surfaces[stopIndex + 1].vertexZMm) /
                    surfaces[stopIndex].indexRear,
                0, 1};
    rear = rear.then(span(surfaces, stopIndex + 1, last));
    if (std::abs(rear.d) < kTiny) {
      out.exitPupil.atInfinity = true;
    } else {
      const double q = -nImage * rear.b / rear.d;
      out.exitPupil = {2 * stopRadius * std::abs(1.0 / rear.d), q, surfaces.back().vertexZMm - q,
                       false};
    }
  }
  if (!out.afocal && !out.entrancePupil.atInfinity && out.entrancePupil.diameterMm > 0)
    out.fNumber = std::abs(out.eflMm) / out.entrancePupil.diameterMm;
  return out;
}

}  // namespace lenslab::optics
