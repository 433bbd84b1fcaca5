// LensFrame: lens millimetres to scene units and back, for pbrt-v3's framing (scene in metres,
// film at the camera origin) and the course's (scene in mm, front vertex at the origin).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "render/lens_frame.h"

namespace lenslab::render {
namespace {

void expectNear(glm::dvec3 actual, glm::dvec3 expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// A camera at (1, 2, 3) with its axes along the world's.
const glm::dmat4 kCameraAt123 = glm::translate(glm::dmat4(1.0), glm::dvec3(-1.0, -2.0, -3.0));

TEST(LensFrame, PbrtV3MetresWithTheFilmAtTheCameraOrigin) {
  const LensFrame frame(kCameraAt123, 0.001, 0.0);
  // 4 mm right, 2 mm down and 50 mm in front of the film centre: metres from the camera.
  expectNear(frame.sceneFromLensMm({4.0, -2.0, 50.0}), {1.004, 1.998, 3.05}, 1e-12);
  expectNear(frame.lensMmFromScene({1.004, 1.998, 3.05}), {4.0, -2.0, 50.0}, 1e-9);
  expectNear(frame.sceneDirectionFromLensMm({0.0, 0.0, 1.0}), {0.0, 0.0, 0.001}, 1e-15);
  EXPECT_NEAR(frame.filmDistanceMmOf({0.0, 0.0, 5.0}), 2000.0, 1e-9);
}

TEST(LensFrame, CourseMillimetresWithTheFrontVertexAtTheCameraOrigin) {
  const double frontVertexZMm = 68.81;
  const LensFrame frame(kCameraAt123, 1.0, frontVertexZMm);
  // The front vertex is the camera's position; the film lies 68.81 mm behind it.
  expectNear(frame.sceneFromLensMm({0.0, 0.0, frontVertexZMm}), {1.0, 2.0, 3.0}, 1e-12);
  expectNear(frame.sceneFromLensMm({0.0, 0.0, 0.0}), {1.0, 2.0, 3.0 - frontVertexZMm}, 1e-12);
  expectNear(frame.lensMmFromScene({1.0, 2.0, 1003.0}), {0.0, 0.0, 1000.0 + frontVertexZMm}, 1e-9);
  expectNear(frame.lensMmFromCamera({5.0, 6.0, 0.0}), {5.0, 6.0, frontVertexZMm}, 1e-12);
}

TEST(LensFrame, FollowsTheCameraRotation) {
  // The camera looks down world +x: its +z turns a quarter about +y.
  const glm::dmat4 worldFromCamera =
      glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0.0, 1.0, 0.0));
  const LensFrame frame(glm::inverse(worldFromCamera), 0.001, 0.0);
  expectNear(frame.sceneFromLensMm({0.0, 0.0, 2000.0}), {2.0, 0.0, 0.0}, 1e-12);
  expectNear(frame.sceneDirectionFromLensMm({0.0, 0.0, 1.0}), {0.001, 0.0, 0.0}, 1e-15);
  EXPECT_NEAR(frame.filmDistanceMmOf({3.0, 0.5, 0.0}), 3000.0, 1e-9);
}

TEST(LensFrame, WorldFromLensMatrixAgreesWithThePointConversionBothWays) {
  const LensFrame frame(kCameraAt123, 0.001, 12.5);
  const glm::dvec3 lensPoint(-3.0, 7.0, 123.0);
  const glm::dvec3 world(frame.worldFromLensMm() * glm::dvec4(lensPoint, 1.0));
  expectNear(world, frame.sceneFromLensMm(lensPoint), 1e-12);
  expectNear(frame.lensMmFromScene(world), lensPoint, 1e-9);
}

}  // namespace
}  // namespace lenslab::render
