// The single-precision disk emitter (PlanarDisk) against the double-precision quadric it is made
// from: the same surface, the same hits, the exact area, under a transform that rotates,
// translates and stretches the disk unevenly.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <random>

#include "render/light.h"

namespace lenslab::render {
namespace {

PlacedQuadric stretchedAnnulus(double phiMax) {
  PlacedQuadric placed;
  placed.quadric.kind = QuadricKind::Disk;
  placed.quadric.radius = 2.0;
  placed.quadric.innerRadius = 0.5;
  placed.quadric.height = 0.25;
  placed.quadric.phiMax = phiMax;
  glm::dmat4 transform = glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, -2.0, 3.0));
  transform = glm::rotate(transform, 0.7, glm::normalize(glm::dvec3(1.0, 2.0, 0.5)));
  transform = glm::scale(transform, glm::dvec3(3.0, 0.5, 2.0));
  placed.place(transform, false);
  return placed;
}

// Object-space (x, y, z) of a world point.
glm::dvec3 toObject(const PlacedQuadric& placed, glm::vec3 p) {
  return glm::dvec3(placed.objectFromParent * glm::dvec4(glm::dvec3(p), 1.0));
}

TEST(PlanarDisk, SamplesLieOnTheAnnulusAndCoverIt) {
  const PlacedQuadric placed = stretchedAnnulus(2.0 * 3.14159265358979323846);
  const PlanarDisk disk = PlanarDisk::fromPlaced(placed, false);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  int outerHalf = 0;
  const int count = 20000;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 p = toObject(placed, disk.sample({uniform(random), uniform(random)}));
    EXPECT_NEAR(p.z, 0.25, 1e-5);
    const double r = std::hypot(p.x, p.y);
    EXPECT_GE(r, 0.5 - 1e-5);
    EXPECT_LE(r, 2.0 + 1e-5);
    // Uniform over the area: the ring beyond r^2 = (0.25 + 4) / 2 holds half of it.
    if (r * r > 0.5 * (0.25 + 4.0)) ++outerHalf;
  }
  EXPECT_NEAR(static_cast<double>(outerHalf) / count, 0.5, 0.015);
}

TEST(PlanarDisk, AreaIsExactUnderAnUnevenStretch) {
  const PlacedQuadric placed = stretchedAnnulus(2.0 * 3.14159265358979323846);
  const PlanarDisk disk = PlanarDisk::fromPlaced(placed, false);
  // The object x and y axes are stretched by 3 and 0.5: area scales by 1.5.
  const double expected = 3.14159265358979323846 * (4.0 - 0.25) * 1.5;
  EXPECT_NEAR(disk.area, expected, 1e-4 * expected);
}

TEST(PlanarDisk, HitsWhereTheDoublePrecisionQuadricDoes) {
  for (double phiMax : {2.0 * 3.14159265358979323846, 4.0}) {
    const PlacedQuadric placed = stretchedAnnulus(phiMax);
    const PlanarDisk disk = PlanarDisk::fromPlaced(placed, false);
    std::mt19937 random(11);
    std::uniform_real_distribution<float> coordinate(-8.0f, 8.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int hits = 0, disagreements = 0;
    for (int i = 0; i < 20000; ++i) {
      const glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random));
      // Aim near the disk so that about half the rays hit it.
      const glm::vec3 target = disk.sample({unit(random), unit(random)}) +
                               glm::vec3(coordinate(random), coordinate(random), 0.0f) * 0.2f;
      const glm::vec3 direction = glm::normalize(target - origin);
      float t = 0.0f;
      const bool hit = disk.intersect(origin, direction, t);
      const glm::dvec3 o = toObject(placed, origin);
      const glm::dvec3 d(placed.objectFromParent * glm::dvec4(glm::dvec3(direction), 0.0));
      const auto expected =
          placed.quadric.intersect(o, d, 0.0, std::numeric_limits<double>::infinity(), false);
      if (hit != expected.has_value()) {
        ++disagreements;  // only rays that graze an edge, within float rounding of it
        continue;
      }
      if (!hit) continue;
      ++hits;
      EXPECT_NEAR(t, expected->t, 1e-4 * (1.0 + expected->t));
    }
    EXPECT_GT(hits, 4000) << "phiMax " << phiMax;
    EXPECT_LE(disagreements, 5) << "phiMax " << phiMax;
  }
}

TEST(PlanarDisk, NormalFollowsTheQuadricAndItsReversal) {
  const PlacedQuadric placed = stretchedAnnulus(2.0 * 3.14159265358979323846);
  const glm::vec3 expected(glm::normalize(placed.normalToParent * glm::dvec3(0.0, 0.0, 1.0)));
  const PlanarDisk disk = PlanarDisk::fromPlaced(placed, false);
  const PlanarDisk flipped = PlanarDisk::fromPlaced(placed, true);
  EXPECT_NEAR(glm::dot(disk.normal, expected), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(flipped.normal, expected), -1.0f, 1e-6f);
  // The normal is perpendicular to the disk's plane.
  EXPECT_NEAR(glm::dot(disk.normal, glm::normalize(disk.axisX)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(disk.normal, glm::normalize(disk.axisY)), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace lenslab::render
