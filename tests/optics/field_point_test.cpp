// FieldPoint (optics/analysis/field_point.h): the fields and pupil rays the aberration analyses
// share, against a bare opening (where every quantity has a closed form), against the real-ray
// field of view (optics/field.h, an independent search), and against its own definition traced
// afresh (the chief ray lands at the requested height; the pupil's edge lies on the stop's
// limited circle).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/analysis/field_point.h"
#include "optics/field.h"
#include "optics/glass.h"
#include "optics/unclipped_trace.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

constexpr double kFieldPointDegrees = 180.0 / std::numbers::pi;

std::shared_ptr<const LensSystem> buildFieldPointLens(const std::string& text) {
  const auto file = parseLensText(text, "opening.dat");
  EXPECT_TRUE(file.ok());
  return LensSystem::build(file.lens->prescription).system;
}

// Where a ray from the object side crosses the stop (clear apertures ignored).
glm::dvec2 onStop(const LensSystem& lens, const LensRay& ray) {
  const auto at = traceFromSceneUnclipped(lens, ray, lens.stopIndex());
  EXPECT_TRUE(at.has_value());
  return at ? glm::dvec2(at->origin.x, at->origin.y) : glm::dvec2(NAN);
}

// Where a ray from the object side meets the film plane z = 0 (clear apertures ignored).
glm::dvec2 fieldPointOnFilm(const LensSystem& lens, const LensRay& ray) {
  const auto out = traceFromSceneUnclipped(lens, ray, lens.surfaces().size() - 1);
  EXPECT_TRUE(out.has_value());
  if (!out) return glm::dvec2(NAN);
  const glm::dvec3 p = out->origin + out->direction * (-out->origin.z / out->direction.z);
  return {p.x, p.y};
}

// A bare 20 mm opening 30 mm from the film: the chief ray of image height h runs straight
// through the opening's centre at atan(h / 30), and the pupil maps linearly onto the opening.
TEST(FieldPoint, BareOpeningHasTheClosedForm) {
  const auto lens = buildFieldPointLens("0 30 0 20\n");
  ASSERT_TRUE(lens);
  for (double h : {0.0, 5.0, 15.0}) {
    const auto field = FieldPoint::resolve(*lens, h, std::nullopt);
    ASSERT_TRUE(field) << h;
    EXPECT_NEAR(field->fieldAngleDeg(), std::atan(h / 30.0) * kFieldPointDegrees, 1e-7);
    for (glm::dvec2 pupil :
         {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, -1), glm::dvec2(0.6, 0.8)}) {
      const glm::dvec2 stop = onStop(*lens, field->ray(pupil));
      EXPECT_NEAR(stop.x, 10.0 * pupil.x, 1e-6) << h;
      EXPECT_NEAR(stop.y, 10.0 * pupil.y, 1e-6) << h;
    }
  }
}

// The double-Gauss: each field's object-space angle is half the real-ray field of view of a film
// whose diagonal reaches it (field.h finds that by its own search), and the chief ray from the
// object, traced afresh, lands at the requested height, from infinity and from 2 m.
TEST(FieldPoint, ChiefRayLandsAtTheRequestedHeight) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  for (double h : {0.0, 7.0, 15.1, 21.6}) {
    const auto field = FieldPoint::resolve(*lens, h, std::nullopt);
    ASSERT_TRUE(field) << h;
    if (h > 0) {
      const auto fov = realFieldOfViewDeg(*lens, 2.0 * h);
      ASSERT_TRUE(fov);
      EXPECT_NEAR(field->fieldAngleDeg(), 0.5 * *fov, 1e-6) << h;
    }
    EXPECT_TRUE(field->objectAtInfinity());
    const glm::dvec2 film = fieldPointOnFilm(*lens, field->chiefRay());
    EXPECT_NEAR(film.y, h, 1e-6);
    EXPECT_NEAR(film.x, 0.0, 1e-9);

    const auto near = FieldPoint::resolve(*lens, h, 2000.0);
    ASSERT_TRUE(near);
    ASSERT_TRUE(near->objectPoint());
    EXPECT_NEAR(near->objectPoint()->z, 2000.0, 1e-9);
    EXPECT_NEAR(fieldPointOnFilm(*lens, near->chiefRay()).y, h, 1e-6);
  }
}

// The pupil's edge lies on the stop's circle scaled by the limited pupil over the iris's, to
// first order in the pupil aberrations (a few % at 0.7 field), and on the axis the edge ray
// enters at the limited entrance pupil's radius.
TEST(FieldPoint, PupilEdgeFollowsTheLimitedStop) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  const double stopRadius = lens->surfaces()[lens->stopIndex()].semiApertureMm;
  const auto axis = FieldPoint::resolve(*lens, 0.0, std::nullopt);
  ASSERT_TRUE(axis);
  // 24.287 mm limited pupil against 24.805 mm for the iris (limiting_aperture_test.cpp).
  EXPECT_NEAR(axis->entrancePupilRadiusMm(), 0.5 * 24.287, 0.01);
  EXPECT_NEAR(axis->ray({0.0, 1.0}).origin.y, 0.5 * 24.287, 0.01);
  const double target = stopRadius * 24.287 / 24.805;
  const auto field = FieldPoint::resolve(*lens, 15.0, std::nullopt);
  ASSERT_TRUE(field);
  for (double angle = 0; angle < 6.28; angle += 0.5) {
    const glm::dvec2 pupil(std::cos(angle), std::sin(angle));
    const double radius = glm::length(onStop(*lens, field->ray(pupil)));
    EXPECT_NEAR(radius, target, 0.05 * target) << angle;
  }
}

TEST(FieldPoint, SaysWhyAFieldCannotBeResolved) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_TRUE(lens);
  std::string why;
  EXPECT_FALSE(FieldPoint::resolve(*lens, 5.0, 50.0, &why));  // object inside the lens
  EXPECT_NE(why.find("in front of the lens"), std::string::npos) << why;
  // A close object just ahead of the front element's rim is fine: the ray from it lands at h.
  double maxSemiAperture = 0.0;
  for (const SurfaceGeometry& s : lens->surfaces())
    maxSemiAperture = std::max(maxSemiAperture, s.semiApertureMm);
  const double close = lens->frontVertexZ() + maxSemiAperture + 1.0;
  const auto near = FieldPoint::resolve(*lens, 5.0, close, &why);
  ASSERT_TRUE(near) << why;
  EXPECT_NEAR(fieldPointOnFilm(*lens, near->chiefRay()).y, 5.0, 1e-6);
  EXPECT_FALSE(FieldPoint::resolve(*lens, NAN, std::nullopt, &why));
  EXPECT_FALSE(why.empty());
}

// chiefRayAt: the same object through the stop's centre at another wavelength. At the field's
// own wavelength it is the field's chief ray again; at F it keeps the object direction and still
// crosses the stop at its centre.
TEST(FieldPoint, ChiefRayAtAnotherWavelengthKeepsTheObjectAndCrossesTheStopCentre) {
  const auto lens = testing::loadLens(testing::bundledLensDir() / "cooke-triplet-100mm.dat");
  ASSERT_TRUE(lens);
  const auto field = FieldPoint::resolve(*lens, 15.0, std::nullopt);
  ASSERT_TRUE(field);
  const auto again = field->chiefRayAt(*lens);
  ASSERT_TRUE(again);
  const auto onStop = traceFromSceneUnclipped(*lens, *again, lens->stopIndex());
  ASSERT_TRUE(onStop);
  EXPECT_NEAR(onStop->origin.y, 0.0, 1e-9);
  EXPECT_NEAR(glm::length(again->direction - field->chiefRay().direction), 0.0, 1e-9);
  // At F the object direction is the same and the ray still passes the stop's centre.
  const auto atF = lens->withWavelength(kWavelengthFNm);
  const auto blue = field->chiefRayAt(*atF);
  ASSERT_TRUE(blue);
  EXPECT_NEAR(glm::length(blue->direction - field->chiefRay().direction), 0.0, 1e-12);
  const auto blueOnStop = traceFromSceneUnclipped(*atF, *blue, atF->stopIndex());
  ASSERT_TRUE(blueOnStop);
  EXPECT_NEAR(blueOnStop->origin.y, 0.0, 1e-9);
  EXPECT_NEAR(blueOnStop->origin.x, 0.0, 1e-12);
}

}  // namespace
}  // namespace lenslab::optics
