// The cost of the scene's ray queries (render/scene.h) on the default scene, with rays shaped like
// a preview pass's: camera rays from the eye across the field, bounce rays leaving the first
// hits in cosine-distributed directions, and shadow rays from the first hits toward the sun.
//
// BM_SceneIntersect/camera, /bounce: Scene::intersect, nearest hit with shading data.
// BM_SceneOccluded/sun: Scene::occluded, one ray at a time (the path tracer's shadow rays).
// items_per_second is rays per second. The /embree variants query through Embree's BVH instead
// of render::FlatPrimitives, which the default scene is small enough to use.
// BM_ScatteredSpheres/<spheres>/<embree>: Scene::intersect on that many spheres scattered in a
// cube, rays from outside toward its middle: where the flat path stops paying
// (FlatPrimitives::kMaxPrimitives).

#include <benchmark/benchmark.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "render/pbrt_parser.h"
#include "render/scene_builder.h"

namespace {

namespace render = lenslab::render;

struct BenchRay {
  glm::vec3 origin, direction;
};

struct SceneRays {
  std::shared_ptr<const render::Scene> scene, embreeScene;
  std::vector<BenchRay> camera, bounce, shadow;
};

// The default scene's view: LookAt 0 0.6 3.6 toward 0 0.45 0; the 50 mm lens on a 36 x 24 mm
// film sees about +-20 degrees across, +-13.5 up and down.
glm::vec3 cameraDirection(float x, float y) {
  const glm::vec3 eye(0.0f, 0.6f, 3.6f), target(0.0f, 0.45f, 0.0f);
  const glm::vec3 forward = glm::normalize(target - eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  return glm::normalize(forward + (0.36f * x) * right + (0.24f * y) * up);
}

// A cosine-distributed direction about `normal`.
glm::vec3 cosineDirection(glm::vec3 normal, float u1, float u2) {
  const glm::vec3 helper = std::abs(normal.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, normal));
  const glm::vec3 b = glm::cross(normal, t);
  const float r = std::sqrt(u1), phi = 6.2831853f * u2;
  return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b +
                        std::sqrt(std::max(0.0f, 1.0f - u1)) * normal);
}

const SceneRays& sceneRays() {
  static const SceneRays rays = [] {
    SceneRays out;
    render::ParseResult parsed =
        render::parsePbrtFile(std::string(LENSLAB_SOURCE_DIR) + "/scenes/default.pbrt");
    if (!parsed.scene) return out;
    render::BuildResult built = render::buildScene(*parsed.scene);
    if (!built.scene) return out;
    out.scene = std::move(built.scene);
    out.embreeScene = render::buildScene(*parsed.scene, {.flatPrimitiveLimit = 0}).scene;
    const glm::vec3 eye(0.0f, 0.6f, 3.6f);
    const glm::vec3 toSun = glm::normalize(glm::vec3(-3.0f, 6.0f, 5.0f));
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    constexpr int kRays = 4096;
    while (static_cast<int>(out.camera.size()) < kRays) {
      const glm::vec3 direction =
          cameraDirection(2.0f * unit(random) - 1.0f, 2.0f * unit(random) - 1.0f);
      out.camera.push_back({eye, direction});
      render::SurfaceHit hit;
      if (!out.scene->intersect(eye, direction, INFINITY, hit)) continue;
      // Leave the surface on the side the ray came from, as the integrator does.
      const glm::vec3 normal = glm::dot(hit.geometricNormal, direction) < 0.0f
                                   ? hit.geometricNormal
                                   : -hit.geometricNormal;
      const glm::vec3 origin = hit.point + 1e-4f * normal;
      out.bounce.push_back({origin, cosineDirection(normal, unit(random), unit(random))});
      out.shadow.push_back({origin, toSun});
    }
    return out;
  }();
  return rays;
}

using RayList = const std::vector<BenchRay> SceneRays::*;

// Scene::intersect for the rays, one per iteration, round and round.
void intersectOneByOne(benchmark::State& state, const render::Scene& scene,
                       const std::vector<BenchRay>& rays) {
  std::size_t next = 0;
  for (auto _ : state) {
    const BenchRay& ray = rays[next];
    next = next + 1 == rays.size() ? 0 : next + 1;
    render::SurfaceHit hit;
    benchmark::DoNotOptimize(scene.intersect(ray.origin, ray.direction, INFINITY, hit));
    benchmark::DoNotOptimize(hit);
  }
  state.SetItemsProcessed(state.iterations());
}

// The default scene, queried flat or through Embree; null (the benchmark skipped) when it cannot
// be loaded.
const render::Scene* defaultScene(benchmark::State& state, bool embree) {
  const SceneRays& rays = sceneRays();
  if (!rays.scene || !rays.embreeScene) {
    state.SkipWithError("cannot load scenes/default.pbrt");
    return nullptr;
  }
  return embree ? rays.embreeScene.get() : rays.scene.get();
}

void BM_SceneIntersect(benchmark::State& state, RayList which, bool embree) {
  if (const render::Scene* scene = defaultScene(state, embree)) {
    intersectOneByOne(state, *scene, sceneRays().*which);
  }
}
BENCHMARK_CAPTURE(BM_SceneIntersect, camera, &SceneRays::camera, false);
BENCHMARK_CAPTURE(BM_SceneIntersect, camera / embree, &SceneRays::camera, true);
BENCHMARK_CAPTURE(BM_SceneIntersect, bounce, &SceneRays::bounce, false);
BENCHMARK_CAPTURE(BM_SceneIntersect, bounce / embree, &SceneRays::bounce, true);

void BM_SceneOccluded(benchmark::State& state, RayList which, bool embree) {
  const render::Scene* scene = defaultScene(state, embree);
  if (!scene) return;
  const std::vector<BenchRay>& rays = sceneRays().*which;
  std::size_t next = 0;
  for (auto _ : state) {
    const BenchRay& ray = rays[next];
    next = next + 1 == rays.size() ? 0 : next + 1;
    benchmark::DoNotOptimize(scene->occluded(ray.origin, ray.direction, INFINITY));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(BM_SceneOccluded, sun, &SceneRays::shadow, false);
BENCHMARK_CAPTURE(BM_SceneOccluded, sun / embree, &SceneRays::shadow, true);

void BM_ScatteredSpheres(benchmark::State& state) {
  const auto spheres = static_cast<int>(state.range(0));
  const bool embree = state.range(1) != 0;
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::ostringstream text;
  text << "Camera \"perspective\"\nWorldBegin\n";
  for (int i = 0; i < spheres; ++i) {
    text << "AttributeBegin\nTranslate " << 10.0f * unit(random) - 5.0f << ' '
         << 10.0f * unit(random) - 5.0f << ' ' << 10.0f * unit(random) - 5.0f
         << "\nShape \"sphere\" \"float radius\" [" << 0.3f + 0.7f * unit(random)
         << "]\nAttributeEnd\n";
  }
  render::ParseResult parsed = render::parsePbrtText(text.str(), "spheres.pbrt", ".");
  if (!parsed.scene) return state.SkipWithError("cannot parse the spheres");
  render::BuildOptions options;
  if (embree) options.flatPrimitiveLimit = 0;
  const auto scene = render::buildScene(*parsed.scene, options).scene;
  if (!scene || scene->queriesWithoutBvh() == embree) return state.SkipWithError("not built");
  std::vector<BenchRay> rays;
  for (int i = 0; i < 4096; ++i) {
    const glm::vec3 origin =
        12.0f * cosineDirection(glm::vec3(0, 0, 1), unit(random), unit(random));
    const glm::vec3 target(4.0f * unit(random) - 2.0f, 4.0f * unit(random) - 2.0f,
                           4.0f * unit(random) - 2.0f);
    rays.push_back({origin, glm::normalize(target - origin)});
  }
  intersectOneByOne(state, *scene, rays);
}
BENCHMARK(BM_ScatteredSpheres)
    ->ArgsProduct({{8, 16, 32, 64}, {0, 1}})
    ->ArgNames({"spheres", "embree"});

}  // namespace
