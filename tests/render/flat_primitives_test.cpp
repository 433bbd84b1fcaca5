// Scenes of few primitives answer ray queries without a BVH (FlatPrimitives). Every answer must be
// Embree's: the same hits and misses, at the same distance, with the same shading data, for every
// kind of primitive, placed every way, and for rays leaving surfaces as the integrator's do.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "render/flat_primitives.h"
#include "render/pbrt_parser.h"
#include "render/scene_builder.h"

namespace lenslab::render {
namespace {

constexpr float kInfinity = INFINITY;

// `text` is a whole scene, or one up to the end of its world block (WorldEnd is then added).
std::shared_ptr<const Scene> build(const std::string& text, BuildOptions options = {}) {
  const std::string whole = text.find("WorldEnd") == std::string::npos ? text + "WorldEnd\n" : text;
  ParseResult parsed =
      parsePbrtText(whole, "flat.pbrt", std::string(LENSLAB_SOURCE_DIR) + "/scenes");
  if (!parsed.scene) {
    ADD_FAILURE() << parsed.diagnostics.formatAll();
    return nullptr;
  }
  BuildResult built = buildScene(*parsed.scene, options);
  if (!built.scene) ADD_FAILURE() << built.diagnostics.formatAll();
  return built.scene;
}

// Every kind of primitive the flat path handles, rotated, scaled (also mirrored) and partial:
// spheres with zmin/zmax/phimax, disks with an inner radius, cylinders, cones, a reversed
// orientation, and meshes with and without normals and uvs. 30 primitives in all, around
// `centres` (when given).
std::string mixedScene(std::vector<glm::vec3>* centres = nullptr) {
  std::ostringstream scene;
  scene << "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
           "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" [4] "
           "\"float vscale\" [4]\n";
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const char* shapes[] = {
      "Shape \"sphere\" \"float radius\" [0.6]",
      "Shape \"sphere\" \"float radius\" [0.5] \"float zmin\" [-0.2] \"float zmax\" [0.4] "
      "\"float phimax\" [250]",
      "Shape \"disk\" \"float radius\" [0.7] \"float innerradius\" [0.2] \"float height\" [0.1]",
      "Shape \"disk\" \"float radius\" [0.5] \"float phimax\" [200]",
      "Shape \"cylinder\" \"float radius\" [0.3] \"float zmin\" [-0.5] \"float zmax\" [0.6]",
      "Shape \"cylinder\" \"float radius\" [0.4] \"float zmin\" [0] \"float zmax\" [0.5] "
      "\"float phimax\" [180]",
      "Shape \"cone\" \"float radius\" [0.4] \"float height\" [0.8]",
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
      "\"point P\" [-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0] "
      "\"float uv\" [0 0 1 0 1 1 0 1]",
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3 0 3 1] "
      "\"point P\" [0 0 0.6  0.6 0 -0.3  -0.3 0.5 -0.3  -0.3 -0.5 -0.3] "
      "\"normal N\" [0 0 1  1 0 0  0 1 0  0 -1 0]",
  };
  for (int i = 0; i < 24; ++i) {
    scene << "AttributeBegin\n";
    scene << (i % 2 ? "Material \"matte\" \"texture Kd\" \"checks\"\n"
                    : "Material \"plastic\" \"rgb Kd\" [0.5 0.2 0.1]\n");
    const glm::vec3 centre(6.0 * unit(random) - 3.0, 6.0 * unit(random) - 3.0,
                           6.0 * unit(random) - 3.0);
    if (centres) centres->push_back(centre);
    scene << "Translate " << centre.x << ' ' << centre.y << ' ' << centre.z << '\n';
    scene << "Rotate " << 360.0 * unit(random) << ' ' << unit(random) - 0.5 << ' '
          << unit(random) - 0.5 << ' ' << unit(random) + 0.1 << '\n';
    // Unequal scales, one in four mirrored.
    scene << "Scale " << (i % 4 == 3 ? -1.0 : 1.0) * (0.5 + unit(random)) << ' '
          << 0.5 + unit(random) << ' ' << 0.5 + unit(random) << '\n';
    if (i % 5 == 2) scene << "ReverseOrientation\n";
    scene << shapes[i % std::size(shapes)] << "\nAttributeEnd\n";
  }
  return scene.str();
}

std::string defaultScene() {
  std::ifstream file(std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

glm::vec3 randomDirection(std::mt19937& random) {
  std::normal_distribution<float> normal;
  for (;;) {
    const glm::vec3 d(normal(random), normal(random), normal(random));
    const float length = glm::length(d);
    if (length > 1e-3f) return d / length;
  }
}

struct Comparison {
  int rays = 0, hits = 0, surfaceRays = 0;
};

// Casts rays from random points in a box toward (near) random targets and, from each hit, rays
// leaving the surface as the integrator's do; checks that both scenes give the same answers.
Comparison compareQueries(const Scene& flat, const Scene& embree, float extent,
                          const std::vector<glm::vec3>& targets, int count) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> coordinate(-extent, extent);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<std::size_t> pick(0, targets.size() - 1);
  Comparison seen;
  for (int i = 0; i < count; ++i) {
    glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random));
    const glm::vec3 target = targets[pick(random)] + 0.5f * randomDirection(random);
    glm::vec3 direction = glm::normalize(target - origin);
    for (int bounce = 0; bounce < 3; ++bounce) {
      SCOPED_TRACE(::testing::Message() << "ray " << i << " bounce " << bounce);
      ++seen.rays;
      seen.surfaceRays += bounce > 0;
      SurfaceHit flatHit, embreeHit;
      const bool flatFound = flat.intersect(origin, direction, kInfinity, flatHit);
      const bool embreeFound = embree.intersect(origin, direction, kInfinity, embreeHit);
      EXPECT_EQ(flatFound, embreeFound);
      const float tMax = 0.1f + 10.0f * unit(random);
      EXPECT_EQ(flat.occluded(origin, direction, tMax), embree.occluded(origin, direction, tMax));
      if (!flatFound || !embreeFound) break;
      ++seen.hits;
      EXPECT_NEAR(flatHit.t, embreeHit.t, 1e-5f * (1.0f + embreeHit.t));
      EXPECT_EQ(flatHit.material, embreeHit.material);
      EXPECT_GT(glm::dot(flatHit.geometricNormal, embreeHit.geometricNormal), 0.9999f);
      EXPECT_GT(glm::dot(flatHit.shadingNormal, embreeHit.shadingNormal), 0.9999f);
      EXPECT_NEAR(flatHit.uv.x, embreeHit.uv.x, 1e-4f);
      EXPECT_NEAR(flatHit.uv.y, embreeHit.uv.y, 1e-4f);
      EXPECT_FLOAT_EQ(flatHit.uvPerWorldUnit, embreeHit.uvPerWorldUnit);
      if (::testing::Test::HasFailure()) return seen;
      // Leave the surface a little off it, on either side, in a new direction.
      direction = randomDirection(random);
      const float side = glm::dot(direction, embreeHit.geometricNormal) >= 0.0f ? 1.0f : -1.0f;
      origin = embreeHit.point + side * 2e-5f * std::max(1.0f, extent) * embreeHit.geometricNormal;
    }
  }
  return seen;
}

TEST(FlatPrimitives, SmallScenesGoWithoutABvhAndLargeOnesKeepIt) {
  const auto small = build(mixedScene());
  ASSERT_TRUE(small);
  EXPECT_TRUE(small->queriesWithoutBvh());
  const auto forced = build(mixedScene(), {.flatPrimitiveLimit = 0});
  ASSERT_TRUE(forced);
  EXPECT_FALSE(forced->queriesWithoutBvh());
  const auto tooMany = build(mixedScene(), {.flatPrimitiveLimit = 29});  // it has 30
  ASSERT_TRUE(tooMany);
  EXPECT_FALSE(tooMany->queriesWithoutBvh());
  const auto enough = build(mixedScene(), {.flatPrimitiveLimit = 30});
  ASSERT_TRUE(enough);
  EXPECT_TRUE(enough->queriesWithoutBvh());
}

TEST(FlatPrimitives, AnEmbreeInstanceKeepsTheBvh) {
  // An object of more than 64 primitives stays an Embree instance (SceneBuilder), and the top
  // level then holds an instance record.
  std::ostringstream strip;
  strip << "Shape \"trianglemesh\" \"integer indices\" [";
  for (int t = 0; t < 70; ++t) strip << 2 * t << ' ' << 2 * t + 1 << ' ' << 2 * t + 2 << ' ';
  strip << "] \"point P\" [";
  for (int v = 0; v < 142; ++v) strip << v * 0.01 << ' ' << (v % 2) * 0.1 << " 0 ";
  strip << "]\n";
  const auto scene = build("Camera \"perspective\"\nWorldBegin\nObjectBegin \"strip\"\n" +
                           strip.str() + "ObjectEnd\nObjectInstance \"strip\"\n");
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->embreeInstances(), 1u);
  EXPECT_FALSE(scene->queriesWithoutBvh());
}

TEST(FlatPrimitives, AnswersAsEmbreeDoesForEveryKindOfPrimitive) {
  std::vector<glm::vec3> centres;
  const auto flat = build(mixedScene(&centres));
  const auto embree = build(mixedScene(), {.flatPrimitiveLimit = 0});
  ASSERT_TRUE(flat && embree);
  ASSERT_TRUE(flat->queriesWithoutBvh());
  const Comparison seen = compareQueries(*flat, *embree, 4.0f, centres, 4000);
  // The comparison means something only if many rays hit, and many leave surfaces.
  EXPECT_GT(seen.hits, 2000);
  EXPECT_GT(seen.surfaceRays, 1500);
}

// The other kernels (box and triangle tests) than the CPU's fastest: AVX2 (where AVX-512 is the
// fastest) and the portable loops of CPUs without AVX2.
class FlatPrimitivesKernels : public ::testing::TestWithParam<FlatPrimitives::KernelKind> {
 protected:
  void TearDown() override { FlatPrimitives::useKernels(FlatPrimitives::KernelKind::Fastest); }
};

TEST_P(FlatPrimitivesKernels, AnswersAsEmbreeDoes) {
  if (!FlatPrimitives::useKernels(GetParam())) GTEST_SKIP() << "this CPU lacks AVX2";
  std::vector<glm::vec3> centres;
  const auto flat = build(mixedScene(&centres));
  const auto embree = build(mixedScene(), {.flatPrimitiveLimit = 0});
  ASSERT_TRUE(flat && embree);
  const Comparison seen = compareQueries(*flat, *embree, 4.0f, centres, 1000);
  EXPECT_GT(seen.hits, 500);
}

std::string kernelsName(const ::testing::TestParamInfo<FlatPrimitives::KernelKind>& kind) {
  return kind.param == FlatPrimitives::KernelKind::Avx2 ? "Avx2" : "Portable";
}

INSTANTIATE_TEST_SUITE_P(Kinds, FlatPrimitivesKernels,
                         ::testing::Values(FlatPrimitives::KernelKind::Avx2,
                                           FlatPrimitives::KernelKind::Portable),
                         kernelsName);

// The vector triangle test repeats the scalar one's operations lane by lane: its answers must be
// the same to the bit. A folded strip of 40 triangles fills three groups of sixteen lanes.
TEST(FlatPrimitives, VectorKernelsAnswerExactlyAsTheScalarLoopsDo) {
  std::ostringstream strip;
  strip << "Camera \"perspective\"\nWorldBegin\nShape \"trianglemesh\" \"integer indices\" [";
  for (int t = 0; t < 40; ++t) strip << t << ' ' << t + 1 << ' ' << t + 2 << ' ';
  strip << "] \"point P\" [";
  for (int v = 0; v < 42; ++v)
    strip << -2.0 + 0.1 * v << ' ' << (v % 2) * 0.8 << ' ' << (v % 3) * 0.3 << ' ';
  strip << "] \"float uv\" [";
  for (int v = 0; v < 42; ++v) strip << v / 41.0 << ' ' << v % 2 << ' ';
  strip << "]\nTranslate 0 0.4 1\nShape \"sphere\" \"float radius\" [0.3]\n";
  const auto scene = build(strip.str());
  ASSERT_TRUE(scene);
  ASSERT_TRUE(scene->queriesWithoutBvh());
  struct Answer {
    bool found = false, blocked = false;
    SurfaceHit hit;
  };
  const auto ask = [&](FlatPrimitives::KernelKind kind, glm::vec3 origin, glm::vec3 direction) {
    EXPECT_TRUE(FlatPrimitives::useKernels(kind));
    Answer answer;
    answer.found = scene->intersect(origin, direction, kInfinity, answer.hit);
    answer.blocked = scene->occluded(origin, direction, 2.5f);
    return answer;
  };
  std::mt19937 random(17);
  std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
  for (const auto kind : {FlatPrimitives::KernelKind::Fastest, FlatPrimitives::KernelKind::Avx2}) {
    if (kind == FlatPrimitives::KernelKind::Avx2 && !FlatPrimitives::useKernels(kind)) continue;
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
      SCOPED_TRACE(::testing::Message() << "ray " << i);
      const glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random));
      const glm::vec3 target(0.5f * coordinate(random), 0.4f + 0.2f * coordinate(random), 0.3f);
      const glm::vec3 direction = glm::normalize(target - origin);
      const Answer vector = ask(kind, origin, direction);
      const Answer scalar = ask(FlatPrimitives::KernelKind::Portable, origin, direction);
      ASSERT_EQ(vector.found, scalar.found);
      ASSERT_EQ(vector.blocked, scalar.blocked);
      if (!vector.found) continue;
      ++hits;
      ASSERT_EQ(vector.hit.t, scalar.hit.t);
      ASSERT_EQ(vector.hit.uv.x, scalar.hit.uv.x);
      ASSERT_EQ(vector.hit.uv.y, scalar.hit.uv.y);
      ASSERT_EQ(vector.hit.geometricNormal, scalar.hit.geometricNormal);
    }
    EXPECT_GT(hits, 1500);
  }
  FlatPrimitives::useKernels(FlatPrimitives::KernelKind::Fastest);
}

TEST(FlatPrimitives, AnswersAsEmbreeDoesForRaysAlongAndAcrossFlatBoxes) {
  // A flat axis-aligned quad and disk: their boxes have no thickness but their padding. Rays
  // along the axes (direction components exactly 0) and rays grazing the quad at 1e-3 and 1e-5.
  const std::string scene =
      "Camera \"perspective\"\nWorldBegin\n"
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
      "  \"point P\" [-20 0 -30  20 0 -30  20 0 10  -20 0 10]\n"
      "AttributeBegin\nTranslate 0 2 0\nShape \"disk\" \"float radius\" [1]\nAttributeEnd\n";
  const auto flat = build(scene);
  const auto embree = build(scene, {.flatPrimitiveLimit = 0});
  ASSERT_TRUE(flat && embree);
  ASSERT_TRUE(flat->queriesWithoutBvh());
  const glm::vec3 directions[] = {
      {1, 0, 0},
      {-1, 0, 0},
      {0, 1, 0},
      {0, -1, 0},
      {0, 0, 1},
      {0, 0, -1},
      glm::normalize(glm::vec3(1, -1e-3f, 0)),
      glm::normalize(glm::vec3(0, -1e-3f, -1)),
      glm::normalize(glm::vec3(1, -1e-5f, 0.3f)),
      glm::normalize(glm::vec3(-0.2f, -1e-5f, -1)),
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    // Origins just above the quad, and on the disk's plane, as well as anywhere.
    const float height = i % 3 == 0 ? 1e-3f : i % 3 == 1 ? 2.0f : coordinate(random);
    const glm::vec3 origin(coordinate(random), height, coordinate(random));
    for (const glm::vec3& direction : directions) {
      SCOPED_TRACE(::testing::Message() << "ray " << i);
      SurfaceHit flatHit, embreeHit;
      const bool found = embree->intersect(origin, direction, kInfinity, embreeHit);
      ASSERT_EQ(flat->intersect(origin, direction, kInfinity, flatHit), found);
      ASSERT_EQ(flat->occluded(origin, direction, 1e3f), embree->occluded(origin, direction, 1e3f));
      if (!found) continue;
      ++hits;
      EXPECT_NEAR(flatHit.t, embreeHit.t, 1e-5f * (1.0f + embreeHit.t));
    }
  }
  EXPECT_GT(hits, 3000);
}

TEST(FlatPrimitives, AnswersAsEmbreeDoesOnTheDefaultScene) {
  const auto flat = build(defaultScene());
  const auto embree = build(defaultScene(), {.flatPrimitiveLimit = 0});
  ASSERT_TRUE(flat && embree);
  EXPECT_TRUE(flat->queriesWithoutBvh());
  // Aimed at the spheres, the chart, the posts and the ground.
  const std::vector<glm::vec3> targets = {
      {0.32f, 0.42f, 2.4f}, {0.95f, 0.25f, 0.6f}, {-1.5f, 0.4f, -3.0f}, {2.5f, 0.6f, -9.0f},
      {0.0f, 0.5f, 0.0f},   {-2.2f, 0.6f, 1.6f},  {-2.2f, 1.2f, -2.4f}, {1.0f, 0.0f, 1.0f}};
  const Comparison seen = compareQueries(*flat, *embree, 3.0f, targets, 4000);
  EXPECT_GT(seen.hits, 2000);
}

}  // namespace
}  // namespace lenslab::render
