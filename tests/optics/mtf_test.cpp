// Diffraction MTF (optics/analysis/mtf.h, pupil_mtf.h, wavefront.h) against independent
// computations: the analytic MTF of a circular aperture, the defocused OTF by a pupil-overlap
// integral written here, and a singlet's third-order spherical aberration by hand (Seidel).

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <thread>
#include <vector>

#include "optics/analysis/mtf.h"
#include "optics/analysis/pupil_mtf.h"
#include "optics/analysis/wavefront.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kPi = std::numbers::pi;

// The MTF of an aberration-free circular pupil at v = frequency / cutoff.
double circularApertureMtf(double v) {
  if (v >= 1.0) return 0.0;
  return 2.0 / kPi * (std::acos(v) - v * std::sqrt(1.0 - v * v));
}

// The OTF of a circular pupil (radius 1) with defocus W = w020 rho^2 (waves), at v = shift / 2,
// as the overlap integral of the pupil with itself shifted by s = 2v along x:
//   OTF(s) = (1 / pi) Int_overlap exp(2 pi i [W(p + s/2) - W(p - s/2)]) dp,
// where the phase is 2 pi w020 * 2 px s, and the overlap at px has the chord
// |py| <= sqrt(1 - (|px| + s/2)^2). The imaginary part vanishes by symmetry; midpoint rule in px.
double defocusedMtf(double v, double w020) {
  const double s = 2.0 * v;
  const double halfWidth = 1.0 - s / 2.0;
  if (halfWidth <= 0.0) return 0.0;
  const int steps = 20000;
  const double step = 2.0 * halfWidth / steps;
  double sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    const double px = -halfWidth + (k + 0.5) * step;
    const double reach = std::abs(px) + s / 2.0;
    const double chord = 2.0 * std::sqrt(std::max(0.0, 1.0 - reach * reach));
    sum += chord * std::cos(2.0 * kPi * w020 * 2.0 * px * s) * step;
  }
  return std::abs(sum) / kPi;
}

// An n x n pupil sampled at the cell centres over [-1, 1]^2, W(px, py) in waves inside the disk.
template <class Opd>
std::vector<std::complex<double>> pupilGrid(int n, Opd opdWaves) {
  std::vector<std::complex<double>> pupil(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double px = (2.0 * i + 1.0) / n - 1.0, py = (2.0 * j + 1.0) / n - 1.0;
      if (px * px + py * py <= 1.0)
        pupil[static_cast<std::size_t>(j) * n + i] = std::polar(1.0, 2.0 * kPi * opdWaves(px, py));
    }
  return pupil;
}

TEST(PupilMtf, AberrationFreeDiskIsTheCircularApertureMtf) {
  const int n = 128;
  const AxisMtf mtf = pupilAxisMtf(pupilGrid(n, [](double, double) { return 0.0; }), n, 256);
  ASSERT_EQ(mtf.alongX.size(), n + 1u);
  for (int k = 0; k <= n; ++k) {
    const double expected = circularApertureMtf(double(k) / n);
    EXPECT_NEAR(mtf.alongX[k], expected, 0.01) << "lag " << k;
    EXPECT_NEAR(mtf.alongY[k], expected, 0.01) << "lag " << k;
  }
}

TEST(PupilMtf, DefocusedDiskMatchesThePupilOverlapIntegral) {
  const int n = 128;
  for (const double w020 : {0.25, 0.5, 1.0}) {
    const AxisMtf mtf = pupilAxisMtf(
        pupilGrid(n, [&](double x, double y) { return w020 * (x * x + y * y); }), n, 256);
    for (int k = 0; k <= n; k += 4) {
      const double expected = defocusedMtf(double(k) / n, w020);
      EXPECT_NEAR(mtf.alongX[k], expected, 0.01) << "W020 " << w020 << " lag " << k;
      EXPECT_NEAR(mtf.alongY[k], expected, 0.01) << "W020 " << w020 << " lag " << k;
    }
  }
}

TEST(PupilMtf, TiltAlongXLeavesTheMtfAlone) {
  // A tilt only moves the PSF; astigmatism-like W = px^2 blurs along x but not along y.
  const int n = 64;
  const AxisMtf tilted =
      pupilAxisMtf(pupilGrid(n, [](double x, double) { return 3.0 * x; }), n, 128);
  const AxisMtf cylinder =
      pupilAxisMtf(pupilGrid(n, [](double x, double) { return 0.5 * x * x; }), n, 128);
  for (int k = 0; k <= n; ++k) {
    const double perfect = circularApertureMtf(double(k) / n);
    EXPECT_NEAR(tilted.alongX[k], perfect, 0.02) << k;
    EXPECT_NEAR(cylinder.alongY[k], perfect, 0.02) << k;
  }
  EXPECT_LT(cylinder.alongX[n / 2], circularApertureMtf(0.5) - 0.1);
}

// A paraxial y-u trace in the usual frame (light toward +z, slopes u, curvature c = 1/R with
// R > 0 when the centre is behind the surface, as lenslab's prescriptions count it), written
// here for the hand computations.
struct ParaxialSurface {
  double curvature;   // 1/mm
  double indexAfter;  // the medium behind it
  double gapAfterMm;  // to the next surface
};
struct ParaxialRay {
  double y, u;
};
// Refract at surface k (from indexBefore), returning the refraction invariant A = n (u + y c).
double refractParaxial(ParaxialRay& ray, const ParaxialSurface& s, double indexBefore) {
  const double invariant = indexBefore * (ray.u + ray.y * s.curvature);
  ray.u = (indexBefore * ray.u - ray.y * s.curvature * (s.indexAfter - indexBefore)) / s.indexAfter;
  return invariant;
}

// A biconvex singlet (BK7-like, no dispersion) with the stop 1 mm in front of it.
struct StopFirstSinglet {
  double r1 = 60.0, r2 = -200.0, thicknessMm = 5.0, index = 1.5168;
  double stopDiameterMm;
  std::vector<ParaxialSurface> lensSurfaces() const {
    return {{1.0 / r1, index, thicknessMm}, {1.0 / r2, 1.0, 0.0}};
  }
  // Paraxial marginal ray from infinity at the stop's edge, through both surfaces.
  // Returns the rear vertex to focus distance and fills the Seidel SI = -sum A^2 y delta(u/n).
  double backFocusMm(double* seidelSpherical = nullptr) const {
    ParaxialRay ray{0.5 * stopDiameterMm, 0.0};
    double indexBefore = 1.0, si = 0.0;
    for (const ParaxialSurface& s : lensSurfaces()) {
      const double uOverNBefore = ray.u / indexBefore;
      const double a = refractParaxial(ray, s, indexBefore);
      si -= a * a * ray.y * (ray.u / s.indexAfter - uOverNBefore);
      indexBefore = s.indexAfter;
      ray.y += ray.u * s.gapAfterMm;
    }
    if (seidelSpherical) *seidelSpherical = si;
    return -ray.y / ray.u;
  }
  double eflMm() const {
    ParaxialRay ray{1.0, 0.0};
    double indexBefore = 1.0;
    for (const ParaxialSurface& s : lensSurfaces()) {
      refractParaxial(ray, s, indexBefore);
      indexBefore = s.indexAfter;
      ray.y += ray.u * s.gapAfterMm;
    }
    return -1.0 / ray.u;
  }
  // The exit pupil (the stop's image): its distance behind the rear vertex (negative: in front)
  // and its semi-diameter, from a chief ray and the marginal ray.
  std::pair<double, double> exitPupil() const {
    auto traced = [&](ParaxialRay ray) {
      ray.y += ray.u * 1.0;  // stop to lens
      double indexBefore = 1.0;
      for (const ParaxialSurface& s : lensSurfaces()) {
        refractParaxial(ray, s, indexBefore);
        indexBefore = s.indexAfter;
        ray.y += ray.u * s.gapAfterMm;
      }
      return ray;
    };
    const ParaxialRay chief = traced({0.0, 0.01});
    const double pupilZ = -chief.y / chief.u;
    const ParaxialRay marginal = traced({0.5 * stopDiameterMm, 0.0});
    return {pupilZ, std::abs(marginal.y + marginal.u * pupilZ)};
  }
  std::shared_ptr<const LensSystem> build(double filmDistanceMm) const {
    Prescription p;
    p.surfaces = {{0.0, 1.0, 1.0, std::nullopt, stopDiameterMm},
                  {r1, thicknessMm, index, std::nullopt, 20.0},
                  {r2, filmDistanceMm, 1.0, std::nullopt, 20.0}};
    auto built = LensSystem::build(p);
    EXPECT_TRUE(built.ok());
    return built.system;
  }
};

constexpr double kWavelengthMm = LensSystem::kDefaultWavelengthNm * 1e-6;

AnalysisSetup onAxis() {
  AnalysisSetup setup;
  setup.fieldFractions = {0.0};
  return setup;
}

TEST(DiffractionMtf, SlowSingletAtFocusIsDiffractionLimited) {
  // f/40: third-order spherical of about 0.01 wave, so the real MTF is the aperture's.
  const StopFirstSinglet singlet{.stopDiameterMm = 2.5};
  const auto lens = singlet.build(singlet.backFocusMm());
  ASSERT_TRUE(lens);
  const MtfResult result = diffractionMtf(*lens, onAxis());
  ASSERT_EQ(result.fields.size(), 1u);
  const FieldMtf& field = result.fields[0];
  ASSERT_FALSE(field.whyNot) << *field.whyNot;
  // Cutoff 1 / (lambda N) with N = EFL / D, by hand.
  const double cutoff = singlet.stopDiameterMm / (kWavelengthMm * singlet.eflMm());
  EXPECT_NEAR(field.cutoffCyclesPerMm, cutoff, 0.005 * cutoff);
  EXPECT_NEAR(field.tangentialCutoffCyclesPerMm, cutoff, 0.005 * cutoff);
  EXPECT_NEAR(field.sagittalCutoffCyclesPerMm, cutoff, 0.005 * cutoff);
  EXPECT_NEAR(field.workingFNumber, singlet.eflMm() / singlet.stopDiameterMm,
              0.005 * field.workingFNumber);
  ASSERT_EQ(field.frequenciesCyclesPerMm.size(), 65u);
  EXPECT_DOUBLE_EQ(field.frequenciesCyclesPerMm.back(), field.cutoffCyclesPerMm);
  for (std::size_t k = 0; k < field.frequenciesCyclesPerMm.size(); ++k) {
    const double expected = circularApertureMtf(field.frequenciesCyclesPerMm[k] / cutoff);
    EXPECT_NEAR(field.tangential[k], expected, 0.01) << k;
    EXPECT_NEAR(field.sagittal[k], expected, 0.01) << k;
    EXPECT_NEAR(field.diffractionLimitTangential[k], expected, 0.01) << k;
    EXPECT_NEAR(field.diffractionLimitSagittal[k], expected, 0.01) << k;
  }
  EXPECT_LT(field.rmsWavefrontErrorWaves, 0.01);
  EXPECT_DOUBLE_EQ(field.passedFraction, 1.0);
}

TEST(DiffractionMtf, DefocusedSingletMatchesThePupilOverlapIntegral) {
  // The film moved dz behind the paraxial focus F. Measured on a sphere about the film point C
  // through the exit pupil's centre, the wave converging on F has the defocus
  //   W020 = h^2 dz / (2 R_F R_C)
  // (h the exit pupil's semi-diameter, R_F and R_C the pupil's distances to F and to C), and
  // the cutoff seen from C is 2 (h / R_C) / lambda.
  const StopFirstSinglet singlet{.stopDiameterMm = 2.5};
  const auto [pupilZMm, pupilRadiusMm] = singlet.exitPupil();
  const double focusMm = singlet.backFocusMm();
  for (const double dzMm : {3.0, 7.0, -5.0}) {
    const auto lens = singlet.build(focusMm + dzMm);
    ASSERT_TRUE(lens);
    const double toFocusMm = focusMm - pupilZMm, toFilmMm = focusMm + dzMm - pupilZMm;
    const double w020 =
        pupilRadiusMm * pupilRadiusMm * dzMm / (2.0 * toFocusMm * toFilmMm) / kWavelengthMm;
    const double cutoff = 2.0 * pupilRadiusMm / toFilmMm / kWavelengthMm;
    const FieldMtf field = diffractionMtf(*lens, onAxis()).fields.at(0);
    ASSERT_FALSE(field.whyNot) << *field.whyNot;
    EXPECT_NEAR(field.cutoffCyclesPerMm, cutoff, 0.005 * cutoff);
    for (std::size_t k = 0; k < field.frequenciesCyclesPerMm.size(); k += 2) {
      const double v = field.frequenciesCyclesPerMm[k] / cutoff;
      const double expected = defocusedMtf(std::min(v, 1.0), w020);
      EXPECT_NEAR(field.tangential[k], expected, 0.015) << "dz " << dzMm << " v " << v;
      EXPECT_NEAR(field.sagittal[k], expected, 0.015) << "dz " << dzMm << " v " << v;
      EXPECT_NEAR(field.diffractionLimitTangential[k], circularApertureMtf(v), 0.01);
    }
    // Pure defocus: rms = W020 / sqrt(12) (piston removed).
    EXPECT_NEAR(field.rmsWavefrontErrorWaves, std::abs(w020) / std::sqrt(12.0),
                0.03 * std::abs(w020));
  }
}

TEST(Wavefront, SingletOnAxisHasTheSeidelSphericalAberration) {
  // f/8, film at the paraxial focus: W = W040 rho^4 + W060 rho^6 + ..., W040 = SI / 8 by hand.
  const StopFirstSinglet singlet{.stopDiameterMm = 12.5};
  double seidelSpherical = 0.0;
  const double focusMm = singlet.backFocusMm(&seidelSpherical);
  const double w040 = seidelSpherical / 8.0 / kWavelengthMm;
  ASSERT_GT(w040, 0.5);  // an undercorrected positive lens: about a wave
  const auto lens = singlet.build(focusMm);
  ASSERT_TRUE(lens);
  const auto field = FieldPoint::resolve(*lens, 0.0, std::nullopt);
  ASSERT_TRUE(field);
  const int n = 64;
  const auto front = traceWavefront(*lens, *field, n);
  ASSERT_TRUE(front);
  EXPECT_EQ(front->passedCount, front->insideCount);
  // Least squares W ~ c0 + c4 rho^4 + c6 rho^6 over the passing samples.
  double normal[3][4] = {};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!front->passed[front->at(i, j)]) continue;
      const double px = Wavefront::pupilCoordinate(i, n), py = Wavefront::pupilCoordinate(j, n);
      const double r2 = px * px + py * py;
      const double basis[3] = {1.0, r2 * r2, r2 * r2 * r2};
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) normal[r][c] += basis[r] * basis[c];
        normal[r][3] += basis[r] * front->opdWaves[front->at(i, j)];
      }
    }
  for (int p = 0; p < 3; ++p)  // Gauss-Jordan
    for (int r = 0; r < 3; ++r) {
      if (r == p) continue;
      const double factor = normal[r][p] / normal[p][p];
      for (int c = 0; c < 4; ++c) normal[r][c] -= factor * normal[p][c];
    }
  const double c4 = normal[1][3] / normal[1][1];
  EXPECT_NEAR(c4, w040, 0.02 * w040);
  // rho^4 from the centre to the edge, with next to no tilt to remove: PV = W040 (+ W060).
  EXPECT_NEAR(front->peakToValleyWaves, w040, 0.03 * w040);
  // Chief ray at the centre: no piston to speak of.
  EXPECT_NEAR(normal[0][3] / normal[0][0], 0.0, 0.01 * w040);
}

TEST(DiffractionMtf, OffAxisSlowSingletIsNearlyDiffractionLimitedAndUntilted) {
  // 3 degrees off axis at f/40 the aberrations are a small fraction of a wave. The reference
  // sphere is centred where the chief ray lands, so the wavefront has next to no tilt: a wrong
  // start for the plane wavefront, or a wrong centre, would tilt it by tens of waves.
  const StopFirstSinglet singlet{.stopDiameterMm = 2.5};
  const auto lens = singlet.build(singlet.backFocusMm());
  ASSERT_TRUE(lens);
  const double imageHeightMm = singlet.eflMm() * std::tan(3.0 * kPi / 180.0);
  const auto field = FieldPoint::resolve(*lens, imageHeightMm, std::nullopt);
  ASSERT_TRUE(field);
  const int n = 32;
  const auto front = traceWavefront(*lens, *field, n);
  ASSERT_TRUE(front);
  EXPECT_EQ(front->passedCount, front->insideCount);
  double sumW = 0.0, sumWy = 0.0, sumY2 = 0.0, maxAbs = 0.0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!front->passed[front->at(i, j)]) continue;
      const double w = front->opdWaves[front->at(i, j)];
      const double py = Wavefront::pupilCoordinate(j, n);
      sumW += w;
      sumWy += w * py;
      sumY2 += py * py;
      maxAbs = std::max(maxAbs, std::abs(w));
    }
  EXPECT_LT(std::abs(sumWy / sumY2), 0.05);  // the tilt along y at the pupil's edge, waves
  EXPECT_LT(maxAbs, 0.25);
  EXPECT_LT(front->rmsWaves, 0.05);

  AnalysisSetup setup = onAxis();
  setup.fieldFractions = {1.0};
  setup.filmHalfDiagonalMm = imageHeightMm;
  const FieldMtf mtf = diffractionMtf(*lens, setup).fields.at(0);
  ASSERT_FALSE(mtf.whyNot) << *mtf.whyNot;
  EXPECT_NEAR(mtf.fieldAngleDeg, 3.0, 0.05);  // positive: an inverting lens
  for (std::size_t k = 0; k < mtf.frequenciesCyclesPerMm.size(); ++k) {
    EXPECT_NEAR(mtf.tangential[k], mtf.diffractionLimitTangential[k], 0.03) << k;
    EXPECT_NEAR(mtf.sagittal[k], mtf.diffractionLimitSagittal[k], 0.03) << k;
  }
}

TEST(DiffractionMtf, AFieldNoRayReachesSaysWhy) {
  const StopFirstSinglet singlet{.stopDiameterMm = 2.5};
  const auto lens = singlet.build(singlet.backFocusMm());
  ASSERT_TRUE(lens);
  AnalysisSetup setup;
  setup.fieldFractions = {0.0, 1.0};
  setup.filmHalfDiagonalMm = 5000.0;  // far beyond what a 20 mm singlet images
  // Fields spread over the coverage (field_coverage.h) unless the caller says the lens covers
  // the film: then the corner is a field no ray reaches.
  const MtfResult covered = diffractionMtf(*lens, setup);
  ASSERT_EQ(covered.fields.size(), 2u);
  EXPECT_LT(covered.fields[1].imageHeightMm, 5000.0);
  setup.coverageMm = 1e9;
  const MtfResult result = diffractionMtf(*lens, setup);
  ASSERT_EQ(result.fields.size(), 2u);
  EXPECT_FALSE(result.fields[0].whyNot);
  ASSERT_TRUE(result.fields[1].whyNot);
  EXPECT_FALSE(result.fields[1].whyNot->empty());
  EXPECT_TRUE(result.fields[1].tangential.empty());
  EXPECT_DOUBLE_EQ(result.fields[1].imageHeightMm, 5000.0);
}

TEST(DiffractionMtf, VignettingNarrowsTheDiffractionLimit) {
  // The double-Gauss at its corner: the rims cut the pupil, so the aberration-free MTF of that
  // pupil differs from a full circle's and fewer than all samples pass.
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  AnalysisSetup setup;
  setup.fieldFractions = {1.0};
  const FieldMtf field = diffractionMtf(*lens, setup).fields.at(0);
  ASSERT_FALSE(field.whyNot) << *field.whyNot;
  EXPECT_LT(field.passedFraction, 0.95);
  EXPECT_GT(field.passedFraction, 0.1);
  EXPECT_LT(field.tangentialCutoffCyclesPerMm, 0.95 * field.sagittalCutoffCyclesPerMm);
  for (std::size_t k = 0; k < field.tangential.size(); ++k) {
    EXPECT_LE(field.tangential[k], field.diffractionLimitTangential[k] + 0.02);
    EXPECT_LE(field.sagittal[k], field.diffractionLimitSagittal[k] + 0.02);
    EXPECT_TRUE(std::isfinite(field.tangential[k]) && std::isfinite(field.sagittal[k]));
  }
}

TEST(DiffractionMtf, ACommonFrequencyAxisEndsAtTheLargestCutoff) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  MtfOptions options;
  const MtfResult own = diffractionMtf(*lens, AnalysisSetup{}, options);
  options.commonFrequencyAxis = true;
  const MtfResult common = diffractionMtf(*lens, AnalysisSetup{}, options);
  double largest = 0.0;
  for (const FieldMtf& f : own.fields) largest = std::max(largest, f.cutoffCyclesPerMm);
  for (std::size_t i = 0; i < common.fields.size(); ++i) {
    const FieldMtf& f = common.fields[i];
    ASSERT_EQ(f.frequenciesCyclesPerMm.size(), 65u);
    EXPECT_NEAR(f.frequenciesCyclesPerMm.back(), largest, 1e-9 * largest);
    EXPECT_EQ(f.frequenciesCyclesPerMm, common.fields[0].frequenciesCyclesPerMm);
    EXPECT_DOUBLE_EQ(f.cutoffCyclesPerMm, own.fields[i].cutoffCyclesPerMm);
    for (std::size_t k = 0; k < f.frequenciesCyclesPerMm.size(); ++k)
      if (f.frequenciesCyclesPerMm[k] >= f.tangentialCutoffCyclesPerMm) {
        EXPECT_EQ(f.tangential[k], 0.0);
        EXPECT_EQ(f.diffractionLimitTangential[k], 0.0);
      }
  }
}

TEST(DiffractionMtf, ThreadsShareThePlansAndGetTheSameAnswer) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  const MtfResult alone = diffractionMtf(*lens, AnalysisSetup{});
  std::vector<MtfResult> results(4);
  std::vector<std::thread> threads;
  for (MtfResult& r : results)
    threads.emplace_back([&] { r = diffractionMtf(*lens, AnalysisSetup{}); });
  for (std::thread& t : threads) t.join();
  for (const MtfResult& r : results)
    for (std::size_t f = 0; f < alone.fields.size(); ++f) {
      EXPECT_EQ(r.fields[f].tangential, alone.fields[f].tangential);
      EXPECT_EQ(r.fields[f].sagittal, alone.fields[f].sagittal);
    }
}

}  // namespace
}  // namespace lenslab::optics
