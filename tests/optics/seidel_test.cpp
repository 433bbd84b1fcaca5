// Seidel sums (optics/analysis/seidel.h) against independent computations: Welford's surface
// formulas worked by hand for a thick singlet (each step written out, no loop, and S_V in its
// original form (A_bar / A)(S_III + S_IV), not the production's division-free one); Welford's
// thin-lens formulas in shape and conjugate factors (a different derivation altogether); and
// the real rays they predict (spherical aberration and coma of a slow lens, the F - C focus).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/analysis/chromatic.h"
#include "optics/analysis/field_point.h"
#include "optics/analysis/seidel.h"
#include "optics/glass.h"
#include "optics/unclipped_trace.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

std::shared_ptr<const LensSystem> buildSeidelLens(const Prescription& p) {
  BuildResult built = LensSystem::build(p);
  EXPECT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().toString());
  return built.system;
}

// Where a ray from the object side meets the film plane z = 0 (clear apertures ignored).
glm::dvec2 onFilm(const LensSystem& lens, const LensRay& ray) {
  const auto out = traceFromSceneUnclipped(lens, ray, lens.surfaces().size() - 1);
  EXPECT_TRUE(out.has_value());
  if (!out) return glm::dvec2(NAN);
  const glm::dvec3 p = out->origin + out->direction * (-out->origin.z / out->direction.z);
  return {p.x, p.y};
}

// A 10 mm stop 20 mm in front of a thick BK7 singlet (R1 60, R2 -300, 6 mm), object at infinity,
// the chief ray scaled to a 10 mm image. Welford's paraxial trace and sums, by hand.
TEST(SeidelSums, ThickSingletMatchesWelfordsFormulasWorkedByHand) {
  const double n = 1.5168, V = 64.17, r1 = 60.0, r2 = -300.0, t = 6.0, gap = 20.0;
  const double c1 = 1.0 / r1, c2 = 1.0 / r2, dn = (n - 1.0) / V;  // n_F - n_C, V_d's definition
  const double field = 10.0;

  // Marginal ray: height 5 at the stop (the stop limits the beam), parallel to the axis.
  const double h1 = 5.0, u1 = 0.0;  // at surface 1 (after the 20 mm gap at slope 0)
  const double u1p = (1.0 * u1 - h1 * c1 * (n - 1.0)) / n;
  const double h2 = h1 + t * u1p;
  const double u2p = (n * u1p - h2 * c2 * (1.0 - n)) / 1.0;
  const double film = -h2 / u2p;  // paraxial image behind surface 2

  // Chief ray through the stop's centre with unit slope; H = n (u h_bar - u_bar h) at the stop.
  const double unitH = 1.0 * (0.0 * 0.0 - 1.0 * 5.0);
  const double unitImage = unitH / (1.0 * u2p);
  const double ub = field / unitImage;  // the slope giving a 10 mm image
  const double H = unitH * field / unitImage;
  const double hb1 = 0.0 + gap * ub;
  const double ub1p = (ub - hb1 * c1 * (n - 1.0)) / n;
  const double hb2 = hb1 + t * ub1p;

  // Surface 1: air to glass.
  const double A1 = 1.0 * (h1 * c1 + u1), Ab1 = 1.0 * (hb1 * c1 + ub);
  const double dUn1 = u1p / n - u1 / 1.0, P1 = c1 * (1.0 / n - 1.0), dDn1 = dn / n - 0.0;
  const double S1_1 = -A1 * A1 * h1 * dUn1, S2_1 = -A1 * Ab1 * h1 * dUn1,
               S3_1 = -Ab1 * Ab1 * h1 * dUn1, S4_1 = -H * H * P1, S5_1 = Ab1 / A1 * (S3_1 + S4_1),
               CL_1 = A1 * h1 * dDn1, CT_1 = Ab1 * h1 * dDn1;
  // Surface 2: glass to air.
  const double A2 = n * (h2 * c2 + u1p), Ab2 = n * (hb2 * c2 + ub1p);
  const double dUn2 = u2p / 1.0 - u1p / n, P2 = c2 * (1.0 - 1.0 / n), dDn2 = 0.0 - dn / n;
  const double S1_2 = -A2 * A2 * h2 * dUn2, S2_2 = -A2 * Ab2 * h2 * dUn2,
               S3_2 = -Ab2 * Ab2 * h2 * dUn2, S4_2 = -H * H * P2, S5_2 = Ab2 / A2 * (S3_2 + S4_2),
               CL_2 = A2 * h2 * dDn2, CT_2 = Ab2 * h2 * dDn2;

  Prescription p;
  p.surfaces = {{0.0, gap, 1.0, std::nullopt, 10.0},
                {r1, t, n, V, 30.0},
                {r2, film, 1.0, std::nullopt, 30.0}};
  const auto lens = buildSeidelLens(p);
  ASSERT_TRUE(lens);
  std::string whyNot;
  const auto sums = computeSeidelSums(*lens, std::nullopt, field, &whyNot);
  ASSERT_TRUE(sums) << whyNot;
  ASSERT_EQ(sums->surfaces.size(), 3u);
  EXPECT_TRUE(sums->chromatic);
  EXPECT_NEAR(sums->entrancePupilRadiusMm, 5.0, 1e-12);
  EXPECT_NEAR(sums->lagrangeInvariant, H, 1e-12);
  EXPECT_NEAR(sums->marginalImageSlope, u2p, 1e-15);
  EXPECT_NEAR(sums->gaussianImageFromFilmMm, 0.0, 1e-9);
  // The stop contributes nothing.
  const SeidelTerms& s0 = sums->surfaces[0];
  for (double v : {s0.s1, s0.s2, s0.s3, s0.s4, s0.s5, s0.cl, s0.ct}) EXPECT_EQ(v, 0.0);
  auto expectTerms = [](const SeidelTerms& got, double s1, double s2, double s3, double s4,
                        double s5, double cl, double ct, const char* where) {
    const double tolerance = 1e-12;
    EXPECT_NEAR(got.s1, s1, tolerance + 1e-10 * std::abs(s1)) << where;
    EXPECT_NEAR(got.s2, s2, tolerance + 1e-10 * std::abs(s2)) << where;
    EXPECT_NEAR(got.s3, s3, tolerance + 1e-10 * std::abs(s3)) << where;
    EXPECT_NEAR(got.s4, s4, tolerance + 1e-10 * std::abs(s4)) << where;
    EXPECT_NEAR(got.s5, s5, tolerance + 1e-10 * std::abs(s5)) << where;
    EXPECT_NEAR(got.cl, cl, tolerance + 1e-10 * std::abs(cl)) << where;
    EXPECT_NEAR(got.ct, ct, tolerance + 1e-10 * std::abs(ct)) << where;
  };
  expectTerms(sums->surfaces[1], S1_1, S2_1, S3_1, S4_1, S5_1, CL_1, CT_1, "surface 2");
  expectTerms(sums->surfaces[2], S1_2, S2_2, S3_2, S4_2, S5_2, CL_2, CT_2, "surface 3");
  expectTerms(sums->total, S1_1 + S1_2, S2_1 + S2_2, S3_1 + S3_2, S4_1 + S4_2, S5_1 + S5_2,
              CL_1 + CL_2, CT_1 + CT_2, "total");
  // A positive crown lens: undercorrected spherical aberration and axial colour, inward Petzval.
  EXPECT_GT(sums->total.s1, 0.0);
  EXPECT_GT(sums->total.s4, 0.0);
  EXPECT_GT(sums->total.cl, 0.0);
  EXPECT_NEAR(sums->transverse.sphericalMm, sums->total.s1 / (2.0 * u2p), 1e-15);
}

// Welford's thin-lens sums (Aberrations of Optical Systems, sec. 7.4) with the stop at the lens,
// in the shape factor B = (c1 + c2)/(c1 - c2) and conjugate factor C = (u + u')/(u - u') (-1
// for an object at infinity):
//   S_I = h^4 phi^3 / 4 [ (n/(n-1))^2 + (n+2)/(n(n-1)^2) B^2 + 4(n+1)/(n(n-1)) B C
//         + (3n+2)/n C^2 ],  S_III = H^2 phi,  S_IV = H^2 phi / n,  S_V = 0,  C_L = h^2 phi / V,
//   C_T = 0.
// A 0.05 mm thick lens of 4 mm aperture is thin to about 1e-3 of these.
TEST(SeidelSums, NearlyThinLensWithTheStopAtItMatchesWelfordsThinLensFormulas) {
  const double n = 1.6, V = 40.0, r1 = 80.0, r2 = -200.0, field = 5.0;
  Prescription p;
  p.surfaces = {{0.0, 0.0, 1.0, std::nullopt, 4.0},
                {r1, 0.05, n, V, 4.2},
                {r2, 100.0, 1.0, std::nullopt, 4.2}};
  const auto lens = buildSeidelLens(p);
  ASSERT_TRUE(lens);
  std::string whyNot;
  const auto sums = computeSeidelSums(*lens, std::nullopt, field, &whyNot);
  ASSERT_TRUE(sums) << whyNot;
  const double c1 = 1.0 / r1, c2 = 1.0 / r2, phi = (n - 1.0) * (c1 - c2), h = 2.0;
  const double B = (c1 + c2) / (c1 - c2), C = -1.0;
  const double S1 = std::pow(h, 4) * std::pow(phi, 3) / 4.0 *
                    (std::pow(n / (n - 1.0), 2) + (n + 2.0) / (n * (n - 1.0) * (n - 1.0)) * B * B +
                     4.0 * (n + 1.0) / (n * (n - 1.0)) * B * C + (3.0 * n + 2.0) / n * C * C);
  // The image height of a thin lens at infinity is f u_bar, and H = -h u_bar (at the lens).
  const double H = -h * field * phi;
  EXPECT_NEAR(sums->lagrangeInvariant, H, 2e-3 * std::abs(H));
  EXPECT_NEAR(sums->total.s1, S1, 2e-3 * std::abs(S1));
  EXPECT_NEAR(sums->total.s3, H * H * phi, 2e-3 * H * H * phi);
  EXPECT_NEAR(sums->total.s4, H * H * phi / n, 2e-3 * H * H * phi / n);
  EXPECT_NEAR(sums->total.s5, 0.0, 2e-3 * H * H * phi);
  EXPECT_NEAR(sums->total.cl, h * h * phi / V, 2e-3 * h * h * phi / V);
  EXPECT_NEAR(sums->total.ct, 0.0, 2e-3 * h * h * phi / V);
}

// A slow plano-convex lens (f about 100 mm, f/20), film at the paraxial focus: the third-order
// predictions against real rays, where the fifth order is a fraction of a per cent.
std::shared_ptr<const LensSystem> slowPlanoConvex(double stopGapMm, double filmMm) {
  Prescription p;
  p.surfaces = {{0.0, stopGapMm, 1.0, std::nullopt, 5.0},
                {51.68, 4.0, 1.5168, 64.17, 30.0},
                {kFlatRadius, filmMm, 1.0, std::nullopt, 30.0}};
  return buildSeidelLens(p);
}

TEST(SeidelSums, PredictRealMarginalRaySphericalAberrationOfASlowLens) {
  auto lens = slowPlanoConvex(2.0, 100.0);
  ASSERT_TRUE(lens);
  lens = lens->withFilmDistance(lens->firstOrder().bflMm);
  const auto sums = computeSeidelSums(*lens, std::nullopt, 1.0);
  ASSERT_TRUE(sums);
  const auto axis = FieldPoint::resolve(*lens, 0.0, std::nullopt);
  ASSERT_TRUE(axis);
  const double real = onFilm(*lens, axis->ray({0.0, 1.0})).y;
  EXPECT_LT(real, 0.0);  // undercorrected: the marginal ray has crossed the axis
  EXPECT_NEAR(sums->transverse.sphericalMm, real, 0.02 * std::abs(real));
  // Half the aperture: an eighth of the transverse error (rho^3).
  const double half = onFilm(*lens, axis->ray({0.0, 0.5})).y;
  EXPECT_NEAR(sums->transverse.sphericalMm / 8.0, half, 0.02 * std::abs(half));
}

TEST(SeidelSums, PredictRealTangentialAndSagittalComaOfASlowLens) {
  // The stop 30 mm in front: coma, field 3 mm (about 1.7 degrees).
  auto lens = slowPlanoConvex(30.0, 100.0);
  ASSERT_TRUE(lens);
  lens = lens->withFilmDistance(lens->firstOrder().bflMm);
  const double fieldMm = 3.0;
  const auto sums = computeSeidelSums(*lens, std::nullopt, fieldMm);
  ASSERT_TRUE(sums);
  const auto field = FieldPoint::resolve(*lens, fieldMm, std::nullopt);
  ASSERT_TRUE(field);
  const double chief = onFilm(*lens, field->chiefRay()).y;
  const double upper = onFilm(*lens, field->ray({0.0, 1.0})).y;
  const double lower = onFilm(*lens, field->ray({0.0, -1.0})).y;
  const double tangential = 0.5 * (upper + lower) - chief;
  const double sagittal = onFilm(*lens, field->ray({1.0, 0.0})).y - chief;
  ASSERT_GT(std::abs(tangential), 1e-4);
  EXPECT_NEAR(sums->transverse.comaTangentialMm, tangential, 0.03 * std::abs(tangential));
  EXPECT_NEAR(sums->transverse.comaSagittalMm, sagittal, 0.03 * std::abs(sagittal));
  // Distortion: the real chief ray lands at fieldMm by construction; the paraxial image of its
  // object direction is f tan(angle).
  EXPECT_NEAR(chief, fieldMm, 1e-9);
  const double paraxial =
      lens->firstOrder().eflMm * std::tan(field->fieldAngleDeg() * std::numbers::pi / 180.0);
  ASSERT_GT(std::abs(fieldMm - paraxial), 1e-4);
  EXPECT_NEAR(sums->transverse.distortionMm, fieldMm - paraxial,
              0.03 * std::abs(fieldMm - paraxial));
}

TEST(SeidelSums, AxialColourPredictsTheParaxialFocusShiftBetweenFAndC) {
  auto lens = slowPlanoConvex(2.0, 100.0);
  ASSERT_TRUE(lens);
  const auto sums = computeSeidelSums(*lens, std::nullopt, 1.0);
  ASSERT_TRUE(sums);
  const double bflF = lens->firstOrderAt(kWavelengthFNm)->bflMm;
  const double bflC = lens->firstOrderAt(kWavelengthCNm)->bflMm;
  EXPECT_LT(bflF - bflC, 0.0);  // blue focuses nearer the lens
  EXPECT_NEAR(sums->transverse.axialColourLongMm, bflF - bflC, 0.03 * std::abs(bflF - bflC));
}

// The symmetry principle: a system symmetric about its stop, imaging at magnification -1, has no
// coma, distortion or lateral colour, surface by surface the contributions cancel in pairs; the
// even aberrations add up. Tests the finite-object rays.
TEST(SeidelSums, SymmetricSystemAtUnitMagnificationHasNoOddAberrations) {
  Prescription p;
  p.surfaces = {{40.0, 5.0, 1.62, 36.0, 24.0},
                {kFlatRadius, 6.0, 1.0, std::nullopt, 24.0},
                {0.0, 6.0, 1.0, std::nullopt, 10.0},
                {kFlatRadius, 5.0, 1.62, 36.0, 24.0},
                {-40.0, 50.0, 1.0, std::nullopt, 24.0}};
  auto lens = buildSeidelLens(p);
  ASSERT_TRUE(lens);
  const FirstOrderData& first = lens->firstOrder();
  const double f = first.eflMm;
  const double film = 2.0 * f + first.rearPrincipalPlaneMm;
  const double objectFromFrontVertex = 2.0 * f - first.frontPrincipalPlaneMm;
  lens = lens->withFilmDistance(film);
  ASSERT_TRUE(lens);
  const double objectFromFilm = lens->frontVertexZ() + objectFromFrontVertex;
  std::string whyNot;
  const auto sums = computeSeidelSums(*lens, objectFromFilm, 8.0, &whyNot);
  ASSERT_TRUE(sums) << whyNot;
  EXPECT_NEAR(sums->gaussianImageFromFilmMm, 0.0, 1e-9);
  const double scale = std::abs(sums->surfaces[0].s2) + std::abs(sums->surfaces[0].s5);
  ASSERT_GT(scale, 1e-4);
  EXPECT_NEAR(sums->total.s2, 0.0, 1e-10 * scale);
  EXPECT_NEAR(sums->total.s5, 0.0, 1e-10 * scale);
  EXPECT_NEAR(sums->total.ct, 0.0, 1e-10 * scale);
  EXPECT_NEAR(sums->surfaces[0].s2, -sums->surfaces[4].s2, 1e-10 * scale);
  EXPECT_GT(sums->total.s1, 0.0);
  EXPECT_GT(sums->total.s4, 0.0);
  EXPECT_GT(sums->total.cl, 0.0);
}

// --- Aspheric surfaces (seidel.h: the paraxial curvature c + 2 A_2 and the r^4 departure) ---

AsphericProfile profileOf(double conic, std::initializer_list<std::pair<int, double>> terms) {
  AsphericProfile profile;
  profile.setConic(conic);
  for (const auto& [power, value] : terms) profile.setCoefficient(power, value);
  return profile;
}

// Parallel light from air into glass of index n through one surface of radius R, the stop at the
// surface, the film in the glass at the paraxial focus n R / (n - 1). Worked by hand with u = 0:
// A = h c, n u' = -h c (n - 1), Delta(u/n) = -h c (n - 1) / n^2, so the sphere has
//   S_I = -A^2 h Delta(u/n) = h^4 c^3 (n - 1) / n^2.
// The ellipsoid k = -1/n^2 (eccentricity 1/n) focuses that light to one point exactly (Descartes's
// oval; Born and Wolf, sec. 4.2.3): no spherical aberration of any order, so S_I = 0. (k = -n^2,
// the hyperboloid, is the oval for the other way through: parallel light in the glass leaving
// into air, the second case below.)
TEST(SeidelSums, TheCartesianOvalFromAirIntoGlassHasNoSphericalAberration) {
  const double n = 1.5, radius = 20.0, h = 2.0, c = 1.0 / radius;
  auto lensWith = [&](const AsphericProfile& profile) {
    Prescription p;
    p.surfaces = {{0.0, 0.0, 1.0, std::nullopt, 2.0 * h},
                  {radius, n * radius / (n - 1.0), n, std::nullopt, 30.0}};
    p.surfaces[1].profile = profile;
    return buildSeidelLens(p);
  };
  const auto sphere = lensWith({});
  const auto oval = lensWith(profileOf(-1.0 / (n * n), {}));
  ASSERT_TRUE(sphere && oval);
  const auto sphereSums = computeSeidelSums(*sphere, std::nullopt, 1.0);
  const auto ovalSums = computeSeidelSums(*oval, std::nullopt, 1.0);
  ASSERT_TRUE(sphereSums && ovalSums);
  const double sphereS1 = std::pow(h, 4) * std::pow(c, 3) * (n - 1.0) / (n * n);
  EXPECT_NEAR(sphereSums->total.s1, sphereS1, 1e-12 * sphereS1);
  EXPECT_NEAR(ovalSums->total.s1, 0.0, 1e-12 * sphereS1);
  // The conic changes nothing paraxial, and nothing in the Petzval sum.
  EXPECT_EQ(ovalSums->marginalImageSlope, sphereSums->marginalImageSlope);
  EXPECT_EQ(ovalSums->total.s4, sphereSums->total.s4);
  // The real rays agree: the oval's marginal ray meets the axis on the film; the sphere's falls
  // short by what S_I / (2 n' u') predicts at this small aperture (u' = -1/30; 0.6% off).
  const LensRay marginal{{0.0, h, sphere->frontVertexZ() + 10.0}, {0.0, 0.0, -1.0}};
  EXPECT_NEAR(onFilm(*oval, marginal).y, 0.0, 1e-12);
  const double real = onFilm(*sphere, marginal).y;
  ASSERT_LT(real, -1e-4);
  EXPECT_NEAR(sphereSums->transverse.sphericalMm, real, 0.02 * std::abs(real));
}

// The other way through: parallel light in glass (behind a flat face, which adds nothing: A = 0
// there) leaving through a surface of radius R < 0 into air. By hand, A = n h c, u' = h c (n - 1),
// Delta(u/n) = h c (n - 1), so the sphere has S_I = -n^2 h^4 c^3 (n - 1) (> 0, c < 0), and the
// hyperboloid k = -n^2 focuses the light exactly (Fermat: n z + |PF| = const gives r^2 -
// 2 R z + (1 - n^2) z^2 = 0 about the vertex).
TEST(SeidelSums, TheCartesianOvalFromGlassIntoAirHasNoSphericalAberration) {
  const double n = 1.6, radius = -24.0, h = 2.5, c = 1.0 / radius;
  auto lensWith = [&](const AsphericProfile& profile) {
    Prescription p;
    p.surfaces = {{0.0, 1.0, 1.0, std::nullopt, 2.0 * h},
                  {kFlatRadius, 5.0, n, std::nullopt, 12.0},
                  {radius, -radius / (n - 1.0), 1.0, std::nullopt, 12.0}};
    p.surfaces[2].profile = profile;
    return buildSeidelLens(p);
  };
  const auto sphere = lensWith({});
  const auto oval = lensWith(profileOf(-n * n, {}));
  ASSERT_TRUE(sphere && oval);
  const auto sphereSums = computeSeidelSums(*sphere, std::nullopt, 1.0);
  const auto ovalSums = computeSeidelSums(*oval, std::nullopt, 1.0);
  ASSERT_TRUE(sphereSums && ovalSums);
  const double sphereS1 = -n * n * std::pow(h, 4) * std::pow(c, 3) * (n - 1.0);
  ASSERT_GT(sphereS1, 0.0);
  EXPECT_NEAR(sphereSums->total.s1, sphereS1, 1e-12 * sphereS1);
  EXPECT_NEAR(ovalSums->total.s1, 0.0, 1e-12 * sphereS1);
  const LensRay marginal{{0.0, h, oval->frontVertexZ() + 10.0}, {0.0, 0.0, -1.0}};
  EXPECT_NEAR(onFilm(*oval, marginal).y, 0.0, 1e-12);
  EXPECT_LT(onFilm(*sphere, marginal).y, -1e-2);  // the sphere: tens of micrometres short
}

// The slow plano-convex lens above with its front surface made aspheric in every way that acts
// at third order: a base radius of 60 mm bent by A_2 to the paraxial radius 51.68 (the spherical
// lens's), a paraboloid (k = -1) and an r^4 term. By hand (seidel.h), the r^4 departure from the
// paraxial sphere is delta = (1 + k) c^3 / 8 + A_4 - c_p^3 / 8 = -1.06e-6 /mm^3, which adds
// 8 delta (n - 1) h^4 = -1.7e-4 mm to S_I, twice the sphere's +8.5e-5: the asphere turns the lens's
// undercorrected spherical aberration into as much overcorrection. Real rays must show it.
std::shared_ptr<const LensSystem> slowAsphericPlanoConvex(double stopGapMm) {
  const double base = 1.0 / 60.0, paraxial = 1.0 / 51.68;
  Prescription p;
  p.surfaces = {{0.0, stopGapMm, 1.0, std::nullopt, 5.0},
                {60.0, 4.0, 1.5168, 64.17, 30.0},
                {kFlatRadius, 100.0, 1.0, std::nullopt, 30.0}};
  p.surfaces[1].profile = profileOf(-1.0, {{2, (paraxial - base) / 2.0}, {4, -1.5e-7}});
  auto lens = buildSeidelLens(p);
  return lens ? lens->withFilmDistance(lens->firstOrder().bflMm) : nullptr;
}

TEST(SeidelSums, AnAsphereThatReversesSphericalAberrationPredictsTheRealRays) {
  const auto lens = slowAsphericPlanoConvex(2.0);
  auto sphere = slowPlanoConvex(2.0, 100.0);
  ASSERT_TRUE(lens && sphere);
  sphere = sphere->withFilmDistance(sphere->firstOrder().bflMm);
  const auto sums = computeSeidelSums(*lens, std::nullopt, 1.0);
  const auto sphereSums = computeSeidelSums(*sphere, std::nullopt, 1.0);
  ASSERT_TRUE(sums && sphereSums);
  // The hand figure for the change: the stop 2 mm in front of the surface, parallel light, so
  // h = 2.5 there.
  const double n = 1.5168, h = 2.5, c = 1.0 / 60.0, cp = 1.0 / 51.68;
  const double delta = (1.0 - 1.0) * c * c * c / 8.0 - 1.5e-7 - cp * cp * cp / 8.0;
  const double change = 8.0 * delta * (n - 1.0) * std::pow(h, 4);
  EXPECT_NEAR(sums->total.s1 - sphereSums->total.s1, change, 1e-9 * std::abs(change));
  ASSERT_LT(sums->total.s1, -0.5 * sphereSums->total.s1);

  const auto axis = FieldPoint::resolve(*lens, 0.0, std::nullopt);
  ASSERT_TRUE(axis);
  const double real = onFilm(*lens, axis->ray({0.0, 1.0})).y;
  EXPECT_GT(real, 0.0);  // overcorrected: the marginal ray has not yet reached the axis
  // Measured 0.05% (full aperture) and 0.01% (half) off: fifth order is small at f/20.
  EXPECT_NEAR(sums->transverse.sphericalMm, real, 0.005 * std::abs(real));
  const double half = onFilm(*lens, axis->ray({0.0, 0.5})).y;
  EXPECT_NEAR(sums->transverse.sphericalMm / 8.0, half, 0.005 * std::abs(half));
}

// Away from the stop the chief ray meets the asphere at h_bar != 0, and the departure adds coma
// (dS_II = dS_I h_bar / h) and distortion (dS_V = dS_I (h_bar / h)^3). Against real rays, as the
// spherical lens's coma test above.
TEST(SeidelSums, AnAsphereAwayFromTheStopPredictsTheRealComaAndDistortion) {
  const auto lens = slowAsphericPlanoConvex(30.0);
  auto sphere = slowPlanoConvex(30.0, 100.0);
  ASSERT_TRUE(lens && sphere);
  sphere = sphere->withFilmDistance(sphere->firstOrder().bflMm);
  const double fieldMm = 3.0;
  const auto sums = computeSeidelSums(*lens, std::nullopt, fieldMm);
  const auto sphereSums = computeSeidelSums(*sphere, std::nullopt, fieldMm);
  ASSERT_TRUE(sums && sphereSums);
  const auto field = FieldPoint::resolve(*lens, fieldMm, std::nullopt);
  ASSERT_TRUE(field);
  const double chief = onFilm(*lens, field->chiefRay()).y;
  const double upper = onFilm(*lens, field->ray({0.0, 1.0})).y;
  const double lower = onFilm(*lens, field->ray({0.0, -1.0})).y;
  const double tangential = 0.5 * (upper + lower) - chief;
  const double sagittal = onFilm(*lens, field->ray({1.0, 0.0})).y - chief;
  // The asphere's share is large: it turns the coma around (-2.65 um with the sphere) and moves
  // the distortion by 10% (-1.67 um), several times the tolerances (measured: 0.7%, 0.03% and
  // 0.2% off).
  ASSERT_GT(std::abs(sphereSums->transverse.comaTangentialMm - tangential),
            0.3 * std::abs(tangential));
  EXPECT_NEAR(sums->transverse.comaTangentialMm, tangential, 0.02 * std::abs(tangential));
  EXPECT_NEAR(sums->transverse.comaSagittalMm, sagittal, 0.01 * std::abs(sagittal));
  EXPECT_NEAR(chief, fieldMm, 1e-9);
  const double paraxial =
      lens->firstOrder().eflMm * std::tan(field->fieldAngleDeg() * std::numbers::pi / 180.0);
  ASSERT_GT(std::abs(sphereSums->transverse.distortionMm - (fieldMm - paraxial)),
            0.05 * std::abs(fieldMm - paraxial));
  EXPECT_NEAR(sums->transverse.distortionMm, fieldMm - paraxial,
              0.01 * std::abs(fieldMm - paraxial));
}

// An r^2 term bends the paraxial curvature to c_p = c + 2 A_2 but adds no r^4 sag, so the surface
// is the sphere c_p plus the departure (c^3 - c_p^3) / 8 at r^4. Three ways to write one surface
// to fourth order must give the same sums: base sphere c with A_2; the sphere c_p with
// A_4 = (c^3 - c_p^3) / 8; and, for c = 0, a flat with A_2 = c_p / 2 is the paraboloid c_p,
// k = -1. And against the sphere c_p alone, the difference is Welford's aspheric term worked by
// hand: the stop 10 mm in front, parallel light, so h = 5 and h_bar = 10 u_bar at the surface,
// u_bar = image height / f.
TEST(SeidelSums, AnR2TermIsTheParaxialSphereWithItsFourthOrderDeparture) {
  const double n = 1.5168, cBase = 1.0 / 80.0, cp = 1.0 / 40.0, r2 = -60.0, d = 6.0;
  const double field = 4.0, h = 5.0, gap = 10.0;
  auto sumsFor = [&](double frontRadius, const AsphericProfile& profile) {
    Prescription p;
    p.surfaces = {{0.0, gap, 1.0, std::nullopt, 2.0 * h},
                  {frontRadius, d, n, std::nullopt, 16.0},
                  {r2, 60.0, 1.0, std::nullopt, 16.0}};
    p.surfaces[1].profile = profile;
    const auto lens = buildSeidelLens(p);
    EXPECT_TRUE(lens);
    std::string whyNot;
    auto sums = lens ? computeSeidelSums(*lens, std::nullopt, field, &whyNot) : std::nullopt;
    EXPECT_TRUE(sums) << whyNot;
    return sums.value_or(SeidelSums{});
  };
  const SeidelSums withA2 = sumsFor(80.0, profileOf(0.0, {{2, (cp - cBase) / 2.0}}));
  const SeidelSums withA4 =
      sumsFor(40.0, profileOf(0.0, {{4, (std::pow(cBase, 3) - std::pow(cp, 3)) / 8.0}}));
  const SeidelSums sphere = sumsFor(40.0, {});
  ASSERT_EQ(withA2.surfaces.size(), 3u);
  ASSERT_EQ(withA4.surfaces.size(), 3u);
  ASSERT_EQ(sphere.surfaces.size(), 3u);
  auto expectSame = [](const SeidelTerms& a, const SeidelTerms& b, double tolerance,
                       const char* what) {
    EXPECT_NEAR(a.s1, b.s1, tolerance) << what;
    EXPECT_NEAR(a.s2, b.s2, tolerance) << what;
    EXPECT_NEAR(a.s3, b.s3, tolerance) << what;
    EXPECT_NEAR(a.s4, b.s4, tolerance) << what;
    EXPECT_NEAR(a.s5, b.s5, tolerance) << what;
  };
  const double scale = std::abs(sphere.total.s1) + std::abs(sphere.total.s3);
  ASSERT_GT(scale, 1e-6);
  expectSame(withA2.surfaces[1], withA4.surfaces[1], 1e-12 * scale, "A2 vs A4");
  expectSame(withA2.surfaces[2], sphere.surfaces[2], 1e-12 * scale, "rear surface");

  // Welford's aspheric term by hand, with f from the thick lensmaker's formula.
  const double power = (n - 1.0) * (cp - 1.0 / r2 + (n - 1.0) * d * cp / (n * r2));
  const double hBar = gap * field * power;
  const double aspheric = (std::pow(cBase, 3) - std::pow(cp, 3)) * (n - 1.0);  // 8 delta Dn
  const SeidelTerms& got = withA2.surfaces[1];
  const SeidelTerms& base = sphere.surfaces[1];
  const double tolerance = 1e-10 * scale;
  EXPECT_NEAR(got.s1 - base.s1, aspheric * std::pow(h, 4), tolerance);
  EXPECT_NEAR(got.s2 - base.s2, aspheric * std::pow(h, 3) * hBar, tolerance);
  EXPECT_NEAR(got.s3 - base.s3, aspheric * h * h * hBar * hBar, tolerance);
  EXPECT_NEAR(got.s4 - base.s4, 0.0, tolerance);
  EXPECT_NEAR(got.s5 - base.s5, aspheric * h * std::pow(hBar, 3), tolerance);
  // The departure is not small: r^2 alone is far from the sphere c_p at third order.
  ASSERT_GT(std::abs(aspheric * std::pow(h, 4)), 0.5 * std::abs(base.s1));

  // A flat with A_2 = c_p / 2 is the paraboloid of curvature c_p.
  const SeidelSums flatWithA2 = sumsFor(kFlatRadius, profileOf(0.0, {{2, cp / 2.0}}));
  const SeidelSums paraboloid = sumsFor(40.0, profileOf(-1.0, {}));
  ASSERT_EQ(flatWithA2.surfaces.size(), 3u);
  ASSERT_EQ(paraboloid.surfaces.size(), 3u);
  expectSame(flatWithA2.total, paraboloid.total, 1e-12 * scale, "flat with A2 vs paraboloid");
  EXPECT_NEAR(paraboloid.surfaces[1].s1 - base.s1, -std::pow(cp, 3) * (n - 1.0) * std::pow(h, 4),
              tolerance);
}

// Odd powers are outside the Seidel scheme: left out of the sums, and the surface is named.
// Even powers from r^6 on act only at fifth order and beyond: left out without a word.
TEST(SeidelSums, OddPowerTermsAreLeftOutAndNamed) {
  auto sumsFor = [&](const AsphericProfile& front, const AsphericProfile& rear) {
    Prescription p = testing::singlet(50.0, -50.0, 5.0, 1.5, 45.0);
    p.surfaces[0].profile = front;
    p.surfaces[1].profile = rear;
    const auto lens = buildSeidelLens(p);
    EXPECT_TRUE(lens);
    auto sums = lens ? computeSeidelSums(*lens, std::nullopt, 5.0) : std::nullopt;
    EXPECT_TRUE(sums);
    return sums.value_or(SeidelSums{});
  };
  const SeidelSums sphere = sumsFor({}, {});
  const SeidelSums odd = sumsFor(profileOf(0.0, {{3, 1e-5}}), profileOf(0.0, {{5, -1e-7}}));
  const SeidelSums even = sumsFor(profileOf(0.0, {{6, 1e-8}, {20, 1e-30}}), {});
  EXPECT_TRUE(sphere.surfacesWithOddTerms.empty());
  EXPECT_TRUE(even.surfacesWithOddTerms.empty());
  EXPECT_EQ(seidelOddTermsNote(even), "");
  EXPECT_EQ(odd.total.s1, sphere.total.s1);
  EXPECT_EQ(odd.total.s2, sphere.total.s2);
  EXPECT_EQ(even.total.s1, sphere.total.s1);
  EXPECT_EQ(even.total.s5, sphere.total.s5);
  ASSERT_FALSE(odd.surfaces.empty());
  const std::size_t front = 0, rear = 1;  // testing::singlet's rows before its stop
  EXPECT_EQ(odd.surfacesWithOddTerms, (std::vector<std::size_t>{front, rear}));
  EXPECT_NE(seidelOddTermsNote(odd).find("surfaces 1 and 2 have odd-power aspheric terms"),
            std::string::npos)
      << seidelOddTermsNote(odd);
}

TEST(SeidelSums, LensWithoutAbbeNumbersHasNoChromaticSums) {
  const auto lens = buildSeidelLens(testing::singlet(50.0, -50.0, 5.0, 1.5, 45.0));
  ASSERT_TRUE(lens);
  const auto sums = computeSeidelSums(*lens, std::nullopt, 5.0);
  ASSERT_TRUE(sums);
  EXPECT_FALSE(sums->chromatic);
  EXPECT_EQ(sums->total.cl, 0.0);
  EXPECT_EQ(sums->total.ct, 0.0);
  EXPECT_NE(sums->total.s1, 0.0);
}

TEST(SeidelSums, RefusesAnAfocalLensAndAZeroField) {
  // Two equal and opposite thin-ish lenses in contact: a window, practically afocal.
  Prescription window;
  window.surfaces = {{kFlatRadius, 5.0, 1.5, std::nullopt, 20.0},
                     {kFlatRadius, 1.0, 1.0, std::nullopt, 20.0},
                     {0.0, 50.0, 1.0, std::nullopt, 10.0}};
  const auto lens = buildSeidelLens(window);
  ASSERT_TRUE(lens);
  std::string whyNot;
  EXPECT_FALSE(computeSeidelSums(*lens, std::nullopt, 5.0, &whyNot));
  EXPECT_NE(whyNot.find("afocal"), std::string::npos) << whyNot;
  const auto singlet = buildSeidelLens(testing::singlet(50.0, -50.0, 5.0, 1.5, 45.0));
  EXPECT_FALSE(computeSeidelSums(*singlet, std::nullopt, 0.0, &whyNot));
  EXPECT_FALSE(computeSeidelSums(*singlet, 10.0, 5.0, &whyNot));  // object inside the lens
}

}  // namespace
}  // namespace lenslab::optics
