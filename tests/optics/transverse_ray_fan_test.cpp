// Transverse ray fans (optics/analysis/transverse_ray_fan.h) against independent computations:
// a bare opening, where every error is the geometric spread of a straight bundle; a plano-convex
// singlet traced in closed form here and against its third-order (Seidel) spherical aberration;
// a defocused slow singlet, whose fan is a line of the paraxial slope; the symmetry of an axial
// fan; and what a field no ray reaches, a blocked ray and a lens without Abbe numbers give.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "optics/analysis/transverse_ray_fan.h"
#include "optics/glass.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

std::shared_ptr<const LensSystem> buildFanLens(const std::string& text) {
  const auto file = parseLensText(text, "fan.dat");
  EXPECT_TRUE(file.ok()) << file.diagnostics.formatAll();
  return file.ok() ? LensSystem::build(file.lens->prescription).system : nullptr;
}

AnalysisSetup fanFieldsAt(std::vector<double> fractions, double halfDiagonalMm = 20.0) {
  AnalysisSetup setup;
  setup.fieldFractions = std::move(fractions);
  setup.filmHalfDiagonalMm = halfDiagonalMm;
  return setup;
}

// The plano-convex singlet of the tests below: R = 50 mm toward the object, 4 mm of n = 1.5, the
// flat toward the film. Its paraxial marginal ray of entering height h (angles are slopes,
// u' = u - h c (n' - n) / n' at each surface) and its third-order transverse spherical
// aberration at the paraxial focus, S_I / (2 n' u'), with Welford's S_I = -A^2 y delta(u/n),
// A = n (y c + u), summed over the two surfaces.
struct PlanoConvex {
  static constexpr double R = 50.0, t = 4.0, n = 1.5;
  struct Marginal {
    double u1, y2, u2;  // slope in the glass, height on the flat, slope behind the lens
  };
  static Marginal paraxial(double h) {
    const double u1 = -h * (n - 1.0) / (n * R);
    return {u1, h + t * u1, n * u1};
  }
  static double backFocusMm() {
    const Marginal m = paraxial(1.0);
    return -m.y2 / m.u2;
  }
  static double thirdOrderSphericalMm(double h) {
    const Marginal m = paraxial(h);
    const double s1 = -(h / R) * (h / R) * h * (m.u1 / n);
    const double s2 = -(n * m.u1) * (n * m.u1) * m.y2 * (m.u2 - m.u1 / n);
    return (s1 + s2) / (2.0 * 1.0 * m.u2);
  }
};

// A 20 mm opening 30 mm from the film. From infinity every ray of a field is parallel to its
// chief ray, so a ray through the opening at 10 (px, py) mm from its centre lands 10 (px, py) mm
// from the chief ray: both fans are the line error = 10 mm * pupil, at every field. From an object
// point D from the film the bundle spreads by D / (D - 30): the fan of a defocused image.
TEST(TransverseRayFan, BareOpeningIsTheGeometricSpreadOfTheBundle) {
  const auto lens = buildFanLens("0 30 0 20\n");
  ASSERT_TRUE(lens);
  for (std::optional<double> objectMm : {std::optional<double>(), std::optional<double>(200.0)}) {
    AnalysisSetup setup = fanFieldsAt({0.0, 0.25, 0.75});
    setup.objectDistanceFromFilmMm = objectMm;
    const double slopeMm = objectMm ? 10.0 * 200.0 / (200.0 - 30.0) : 10.0;
    const TransverseRayFans fans = computeTransverseRayFans(*lens, setup);
    ASSERT_EQ(fans.fields.size(), 3u);
    for (const TransverseFanField& field : fans.fields) {
      ASSERT_EQ(field.wavelengths.size(), 1u);
      const TransverseFansAtWavelength& at = field.wavelengths[0];
      ASSERT_EQ(at.tangential.size(), 64u);
      ASSERT_EQ(at.sagittal.size(), 64u);
      EXPECT_DOUBLE_EQ(at.tangential.front().pupil, -1.0);
      EXPECT_DOUBLE_EQ(at.tangential.back().pupil, 1.0);
      for (const auto* fan : {&at.tangential, &at.sagittal})
        for (const TransverseFanSample& s : *fan) {
          // The ray at the very edge grazes the opening: it may pass or be clipped by rounding.
          if (std::abs(s.pupil) == 1.0) continue;
          ASSERT_TRUE(s.errorMm) << field.imageHeightMm << " " << s.pupil;
          EXPECT_NEAR(*s.errorMm, slopeMm * s.pupil, 1e-7) << field.imageHeightMm;
        }
    }
  }
}

// A plano-convex singlet, R = 50 mm toward the object, 4 mm of n = 1.5, a 6 mm stop 1 mm in front,
// the film at the paraxial focus. An axial ray at height h is traced here in closed form (two
// refractions by the vector Snell law), and its error at the paraxial focus is the third-order
// transverse spherical aberration S_I / (2 n' u') (Welford) to within the fifth order, small at
// f/16. The lens is under-corrected: the top ray crosses the axis before the focus and lands below.
TEST(TransverseRayFan, PlanoConvexAxialFanIsItsSphericalAberration) {
  const double R = PlanoConvex::R, t = PlanoConvex::t, n = PlanoConvex::n, stopRadius = 3.0;
  const double bfl = PlanoConvex::backFocusMm();  // 97.333 mm
  const auto lens = buildFanLens("0 1 0 " + std::to_string(2 * stopRadius) + "\n50 4 1.5 30\ninf " +
                                 std::to_string(bfl) + " 1 30\n");
  ASSERT_TRUE(lens);
  ASSERT_NEAR(lens->filmDistanceMm(), bfl, 1e-5);

  auto exactFilmY = [&](double h) {
    const double film = lens->filmDistanceMm();
    const double vertexZ = film + t, centreZ = vertexZ - R;
    const double z1 = centreZ + std::sqrt(R * R - h * h);
    const double ny = h / R, nz = (z1 - centreZ) / R;
    const double eta = 1.0 / n, cosi = nz, k = 1.0 - eta * eta * (1.0 - cosi * cosi);
    const double dy = (eta * cosi - std::sqrt(k)) * ny;
    const double dz = -eta + (eta * cosi - std::sqrt(k)) * nz;
    const double y2 = h + (film - z1) / dz * dy;
    // The flat rear surface: n sin(i) = sin(i'), with the ray's sine measured from -z.
    const double sinIn = dy / std::hypot(dy, dz), sinOut = n * sinIn;
    const double tanOut = sinOut / std::sqrt(1.0 - sinOut * sinOut);
    return y2 + film * tanOut;  // the ray travels a further `film` toward -z
  };

  const TransverseRayFans fans = computeTransverseRayFans(*lens, fanFieldsAt({0.0}));
  ASSERT_EQ(fans.fields.size(), 1u);
  const TransverseFansAtWavelength& at = fans.fields[0].wavelengths.at(0);
  for (const TransverseFanSample& s : at.tangential) {
    if (std::abs(s.pupil) == 1.0) continue;
    ASSERT_TRUE(s.errorMm);
    EXPECT_NEAR(*s.errorMm, exactFilmY(stopRadius * s.pupil), 1e-9) << s.pupil;
  }

  const double h = stopRadius * at.tangential[62].pupil;
  const double thirdOrder = PlanoConvex::thirdOrderSphericalMm(h);
  ASSERT_TRUE(at.tangential[62].errorMm);
  EXPECT_LT(*at.tangential[62].errorMm, 0.0);
  EXPECT_NEAR(*at.tangential[62].errorMm, thirdOrder, 0.01 * std::abs(thirdOrder));
}

// The singlet at f/50 with the film 10 mm beyond its paraxial focus: the fan is the straight
// line error = -y' * 10 / BFL * pupil (y' the paraxial marginal ray's height on the flat, which
// reaches the axis BFL behind it), plus the small third-order spherical aberration.
TEST(TransverseRayFan, DefocusedFanIsALineOfTheParaxialSlope) {
  const double stopRadius = 1.0;
  const double bfl = PlanoConvex::backFocusMm();
  const auto lens =
      buildFanLens("0 1 0 2\n50 4 1.5 30\ninf " + std::to_string(bfl + 10.0) + " 1 30\n");
  ASSERT_TRUE(lens);
  const double slope =
      -PlanoConvex::paraxial(stopRadius).y2 * (lens->filmDistanceMm() - bfl) / bfl;  // -0.1
  const TransverseRayFans fans = computeTransverseRayFans(*lens, fanFieldsAt({0.0}));
  const TransverseFansAtWavelength& at = fans.fields.at(0).wavelengths.at(0);
  for (const auto* fan : {&at.tangential, &at.sagittal})
    for (const TransverseFanSample& s : *fan) {
      if (std::abs(s.pupil) == 1.0) continue;
      ASSERT_TRUE(s.errorMm);
      const double expected =
          slope * s.pupil + PlanoConvex::thirdOrderSphericalMm(stopRadius * s.pupil);
      EXPECT_NEAR(*s.errorMm, expected, 2e-4 * std::abs(slope)) << s.pupil;
    }
}

// On the axis the fans are odd in the pupil coordinate, and the sagittal fan is the tangential one
// (the lens is round), at every wavelength.
TEST(TransverseRayFan, AxialFansAreOddAndAlike) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-100mm.dat");
  ASSERT_TRUE(lens);
  const TransverseRayFans fans = computeTransverseRayFans(*lens, fanFieldsAt({0.0}));
  ASSERT_EQ(fans.fields.at(0).wavelengths.size(), 3u);
  for (const TransverseFansAtWavelength& at : fans.fields[0].wavelengths) {
    const std::size_t n = at.tangential.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto& a = at.tangential[i];
      const auto& b = at.tangential[n - 1 - i];
      EXPECT_EQ(a.pupil, -b.pupil);
      ASSERT_EQ(a.errorMm.has_value(), b.errorMm.has_value());
      if (!a.errorMm) continue;
      EXPECT_NEAR(*a.errorMm, -*b.errorMm, 1e-9) << at.wavelengthNm << " " << a.pupil;
      ASSERT_TRUE(at.sagittal[i].errorMm);
      EXPECT_NEAR(*at.sagittal[i].errorMm, *a.errorMm, 1e-9);
    }
  }
}

// The double-Gauss 100 mm has Abbe numbers: d, F and C fans, the chromatic ones measured from
// the d chief ray (so off the axis they are offset by the lateral colour near the pupil's
// centre, and on the axis they are not). The 50 mm file has none: the d fan alone.
TEST(TransverseRayFan, ColourFansOnlyForALensWithAbbeNumbers) {
  // The course's double-Gauss 50 mm, as pbrt has it: no Abbe numbers.
  const auto plain = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(plain);
  const TransverseRayFans d = computeTransverseRayFans(*plain, fanFieldsAt({0.0, 0.7}));
  EXPECT_EQ(d.wavelengthsNm, std::vector<double>{kWavelengthDNm});
  for (const TransverseFanField& field : d.fields) EXPECT_EQ(field.wavelengths.size(), 1u);

  const auto coloured = testing::loadLens(testing::bundledLensDir() / "dgauss-100mm.dat");
  ASSERT_TRUE(coloured);
  const TransverseRayFans dfc = computeTransverseRayFans(*coloured, fanFieldsAt({0.0, 0.7}));
  EXPECT_EQ(dfc.wavelengthsNm,
            (std::vector<double>{kWavelengthDNm, kWavelengthFNm, kWavelengthCNm}));
  // Near the pupil's centre (pupil +-1/63) the F and C errors differ from d's by the lateral
  // colour: zero on the axis, not zero at 0.7 of the field.
  const auto nearCentre = [](const TransverseFansAtWavelength& at) {
    return 0.5 * (*at.tangential[31].errorMm + *at.tangential[32].errorMm);
  };
  const auto& axis = dfc.fields[0].wavelengths;
  EXPECT_NEAR(nearCentre(axis[1]), 0.0, 1e-9);
  EXPECT_NEAR(nearCentre(axis[2]), 0.0, 1e-9);
  const auto& off = dfc.fields[1].wavelengths;
  EXPECT_GT(std::abs(nearCentre(off[1]) - nearCentre(off[0])), 1e-4);
  EXPECT_GT(std::abs(nearCentre(off[2]) - nearCentre(off[0])), 1e-4);
}

// Rays the rims block are absent, not zero: at the corner of the double-Gauss 50 mm the
// tangential fan loses its ends (each blocked ray checked by a traced path), and a field beyond
// the lens's coverage has no fans and says why.
TEST(TransverseRayFan, BlockedRaysAndUnreachableFieldsAreAbsent) {
  // The course's file (no Abbe numbers), so the fans are at the d line only.
  const auto lens = testing::loadLens(testing::referenceLensDir() / "dgauss.50mm.dat", 36.77);
  ASSERT_TRUE(lens);
  AnalysisSetup setup = fanFieldsAt({1.0, 5.0}, 21.6);
  const TransverseRayFans fans = computeTransverseRayFans(*lens, setup);
  ASSERT_EQ(fans.fields.size(), 2u);
  const TransverseFanField& corner = fans.fields[0];
  ASSERT_EQ(corner.wavelengths.size(), 1u);
  const auto field = FieldPoint::resolve(*lens, 21.6, std::nullopt);
  ASSERT_TRUE(field);
  int blocked = 0;
  for (const TransverseFanSample& s : corner.wavelengths[0].tangential) {
    const RayPath path = lens->traceFromScenePath(field->ray({0.0, s.pupil}));
    EXPECT_EQ(s.errorMm.has_value(), path.stop == RayStop::Passed) << s.pupil;
    blocked += s.errorMm ? 0 : 1;
  }
  EXPECT_GT(blocked, 10);
  EXPECT_TRUE(corner.whyNot.empty());

  const TransverseFanField& beyond = fans.fields[1];
  EXPECT_FALSE(beyond.fieldAngleDeg);
  EXPECT_TRUE(beyond.wavelengths.empty());
  EXPECT_NE(beyond.whyNot.find("stop"), std::string::npos) << beyond.whyNot;
}

}  // namespace
}  // namespace lenslab::optics
