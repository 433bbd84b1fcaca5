#include "render/integrator.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <vector>

#include "render/material.h"
#include "render/sampling.h"

namespace lenslab::render {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Offsets a ray origin off the surface along the geometric normal, on the side of `direction`,
// so that the new ray does not hit the surface it starts on. The offset grows with the
// coordinates' magnitude because float spacing does.
glm::vec3 offsetOrigin(const SurfaceHit& hit, glm::vec3 direction) {
  const float magnitude =
      std::max({1.0f, std::abs(hit.point.x), std::abs(hit.point.y), std::abs(hit.point.z)});
  const float epsilon = 2e-5f * magnitude;
  const float side = glm::dot(hit.geometricNormal, direction) >= 0.0f ? 1.0f : -1.0f;
  return hit.point + side * epsilon * hit.geometricNormal;
}

// The texture-space width a camera sample covers at `hit`: the spread times the distance,
// stretched by the incidence angle (the geometric mean of the footprint ellipse's axes).
float cameraFootprint(const SurfaceHit& hit, glm::vec3 direction, float spreadRadians) {
  if (spreadRadians <= 0.0f || hit.uvPerWorldUnit <= 0.0f) return 0.0f;
  const float cosine = std::max(0.02f, std::abs(glm::dot(direction, hit.geometricNormal)));
  return hit.t * spreadRadians / std::sqrt(cosine) * hit.uvPerWorldUnit;
}

bool isBlack(glm::vec3 v) { return v.x <= 0.0f && v.y <= 0.0f && v.z <= 0.0f; }

// Radiance from the lights escaping rays see (infinite lights).
glm::vec3 escapedRadiance(const Scene& scene, glm::vec3 direction) {
  glm::vec3 sum(0.0f);
  for (int index : scene.infiniteLights()) {
    sum += infiniteRadiance(scene.lights()[static_cast<std::size_t>(index)], direction);
  }
  return sum;
}

// A direct-lighting term that counts only if its shadow ray is unblocked.
struct ShadowedTerm {
  ShadowRay ray;
  glm::vec3 value{0.0f};
};

// One light's direct-lighting terms at a hit, from one light sample and (for non-delta lights
// given `uBsdf`) one BSDF sample, combined with the power heuristic (pbrt-v2's
// EstimateDirect). Terms that need a shadow ray go to `shadowed`; a term decided without one (a
// BSDF sample that found a mesh emitter by a full intersection) is added to `decided`.
void directTerms(const Scene& scene, const SurfaceHit& hit, const Bsdf& bsdf, glm::vec3 wo,
                 int lightIndex, glm::vec2 uLight, std::optional<glm::vec2> uBsdf,
                 float selectionProbability, std::vector<ShadowedTerm>& shadowed,
                 glm::vec3& decided) {
  const Light& light = scene.lights()[static_cast<std::size_t>(lightIndex)];
  LightSample ls;
  if (sampleLight(light, hit.point, uLight, scene.radius(), ls) && !isBlack(ls.radiance)) {
    float bsdfPdf = 0.0f;
    const glm::vec3 f = bsdf.evaluate(wo, ls.wi, bsdfPdf);
    const float lightPdf = ls.pdf * selectionProbability;
    if (!isBlack(f) && lightPdf > 0.0f) {
      const float weight = light.isDelta() ? 1.0f : powerHeuristic(lightPdf, bsdfPdf);
      const glm::vec3 origin = offsetOrigin(hit, ls.wi);
      const float distance = shadowRayLength(light, ls, origin);
      if (distance > 0.0f) {
        shadowed.push_back(
            {{origin, ls.wi, distance},
             f * ls.radiance * (std::abs(glm::dot(ls.wi, hit.shadingNormal)) * weight / lightPdf)});
      }
    }
  }
  if (!uBsdf || light.isDelta()) return;
  BsdfSample bs;
  if (!bsdf.sample(wo, *uBsdf, bs) || bs.specular) return;
  const glm::vec3 origin = offsetOrigin(hit, bs.wi);
  if (light.kind == LightKind::Area) {
    // The sample counts only if the first thing it meets is this light. Most BSDF samples miss
    // a small emitter: for a quadric, testing it alone first skips the scene query for those,
    // and a hit needs only a shadow ray up to it.
    glm::vec3 lightNormal;
    float t = 0.0f;
    if (light.emitter->isQuadric) {
      if (!light.emitter->intersectQuadric(origin, bs.wi, t, lightNormal)) return;
      const float lightPdf = areaPdf(light, hit.point, origin + t * bs.wi, lightNormal);
      if (lightPdf <= 0.0f) return;
      const glm::vec3 value =
          bs.weight * areaRadiance(light, lightNormal, -bs.wi) * powerHeuristic(bs.pdf, lightPdf);
      if (!isBlack(value)) shadowed.push_back({{origin, bs.wi, t * (1.0f - 1e-4f)}, value});
      return;
    }
    SurfaceHit lightHit;
    if (!scene.intersect(origin, bs.wi, kInfinity, lightHit) || lightHit.light != lightIndex) {
      return;
    }
    const float lightPdf = areaPdf(light, hit.point, lightHit.point, lightHit.geometricNormal);
    if (lightPdf <= 0.0f) return;
    decided += bs.weight * areaRadiance(light, lightHit.geometricNormal, -bs.wi) *
               powerHeuristic(bs.pdf, lightPdf);
    return;
  }
  // Infinite light: whatever the ray escapes to.
  const float lightPdf = infinitePdf(light);
  if (lightPdf <= 0.0f) return;
  const glm::vec3 value =
      bs.weight * infiniteRadiance(light, bs.wi) * powerHeuristic(bs.pdf, lightPdf);
  if (!isBlack(value)) shadowed.push_back({{origin, bs.wi, kInfinity}, value});
}

// The sum of the terms whose shadow rays are unblocked (traced together), and clears `terms`.
glm::vec3 resolveShadowed(const Scene& scene, std::vector<ShadowedTerm>& terms) {
  thread_local std::vector<ShadowRay> rays;
  thread_local std::vector<std::uint8_t> blocked;
  rays.clear();
  for (const ShadowedTerm& term : terms) rays.push_back(term.ray);
  blocked.resize(rays.size());
  scene.occluded(rays.data(), rays.size(), blocked.data());
  glm::vec3 sum(0.0f);
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (!blocked[i]) sum += terms[i].value;
  }
  terms.clear();
  return sum;
}

// Next-event estimation: one light's contribution at a hit from one light sample (the path
// tracer's BSDF sample continues the path instead).
glm::vec3 sampleLightTerm(const Scene& scene, const SurfaceHit& hit, const Bsdf& bsdf, glm::vec3 wo,
                          int lightIndex, glm::vec2 uLight, float selectionProbability) {
  thread_local std::vector<ShadowedTerm> terms;
  glm::vec3 decided(0.0f);
  directTerms(scene, hit, bsdf, wo, lightIndex, uLight, std::nullopt, selectionProbability, terms,
              decided);
  return decided + resolveShadowed(scene, terms);
}

glm::vec3 directLighting(const Scene& scene, glm::vec3 origin, glm::vec3 direction,
                         PixelSampler& sampler, int maxDepth, float spread) {
  glm::vec3 radiance(0.0f), throughput(1.0f);
  for (int depth = 0;; ++depth) {
    SurfaceHit hit;
    if (!scene.intersect(origin, direction, kInfinity, hit)) {
      radiance += throughput * escapedRadiance(scene, direction);
      break;
    }
    const glm::vec3 wo = -direction;
    if (hit.light >= 0) {
      radiance += throughput * areaRadiance(scene.lights()[static_cast<std::size_t>(hit.light)],
                                            hit.geometricNormal, wo);
    }
    const float footprint = depth == 0 ? cameraFootprint(hit, direction, spread) : 0.0f;
    const Bsdf bsdf(scene.material(hit.material), scene.textures(), hit.uv, hit.shadingNormal,
                    footprint);
    if (!bsdf.isSpecular()) {
      // pbrt-v2's default strategy: every light, with its own number of samples, drawn as two
      // stratified arrays (light points, BSDF directions). All the shadow rays of one light go
      // to the scene together.
      thread_local std::vector<ShadowedTerm> terms;
      thread_local std::vector<glm::vec2> uLights, uBsdfs;
      const auto& lights = scene.lights();
      for (std::size_t l = 0; l < lights.size(); ++l) {
        const int count = lights[l].samples;
        uLights.resize(static_cast<std::size_t>(count));
        uBsdfs.resize(static_cast<std::size_t>(count));
        sampler.next2DArrays(static_cast<std::uint32_t>(count), uLights.data(), uBsdfs.data());
        glm::vec3 sum(0.0f);
        for (int s = 0; s < count; ++s) {
          directTerms(scene, hit, bsdf, wo, static_cast<int>(l), uLights[s], uBsdfs[s], 1.0f, terms,
                      sum);
        }
        sum += resolveShadowed(scene, terms);
        radiance += throughput * sum * (1.0f / static_cast<float>(count));
      }
      break;
    }
    // Follow perfect specular reflection and refraction up to maxDepth.
    if (depth + 1 >= maxDepth) break;
    BsdfSample bs;
    const glm::vec2 u = sampler.next2D();
    if (!bsdf.sample(wo, u.x, sampler.next2D(), bs)) break;
    throughput *= bs.weight;
    if (isBlack(throughput)) break;
    origin = offsetOrigin(hit, bs.wi);
    direction = bs.wi;
  }
  return radiance;
}

glm::vec3 pathTrace(const Scene& scene, glm::vec3 origin, glm::vec3 direction,
                    PixelSampler& sampler, int maxDepth, float spread) {
  glm::vec3 radiance(0.0f), throughput(1.0f);
  bool specularBounce = true;
  float previousPdf = 0.0f;
  glm::vec3 previousPoint(0.0f);
  const auto& lights = scene.lights();
  const LightSelection& selection = scene.lightSelection();
  // The choice of light at the last vertex that sampled one; read for the weight of a light that
  // the BSDF sample from there meets.
  thread_local LightSelection::AtPoint choice;
  for (int depth = 0;; ++depth) {
    SurfaceHit hit;
    if (!scene.intersect(origin, direction, kInfinity, hit)) {
      for (int index : scene.infiniteLights()) {
        const Light& light = lights[static_cast<std::size_t>(index)];
        const glm::vec3 le = infiniteRadiance(light, direction);
        const float weight =
            specularBounce
                ? 1.0f
                : powerHeuristic(previousPdf, infinitePdf(light) * choice.probability(index));
        radiance += throughput * le * weight;
      }
      break;
    }
    const glm::vec3 wo = -direction;
    if (hit.light >= 0) {
      const Light& light = lights[static_cast<std::size_t>(hit.light)];
      const glm::vec3 le = areaRadiance(light, hit.geometricNormal, wo);
      float weight = 1.0f;
      if (!specularBounce) {
        const float lightPdf = areaPdf(light, previousPoint, hit.point, hit.geometricNormal) *
                               choice.probability(hit.light);
        weight = powerHeuristic(previousPdf, lightPdf);
      }
      radiance += throughput * le * weight;
    }
    if (depth >= maxDepth) break;
    const float footprint = depth == 0 ? cameraFootprint(hit, direction, spread) : 0.0f;
    const Bsdf bsdf(scene.material(hit.material), scene.textures(), hit.uv, hit.shadingNormal,
                    footprint);
    glm::vec2 uChoose, uLight, uBsdf;
    sampler.next2DTriple(uChoose, uLight, uBsdf);
    if (!bsdf.isSpecular() && !lights.empty()) {
      // Next-event estimation toward one light (LightSelection says how it is chosen).
      selection.evaluate(hit.point, choice);
      float probability = 0.0f;
      const int index = choice.choose(uChoose.x, probability);
      radiance += throughput * sampleLightTerm(scene, hit, bsdf, wo, index, uLight, probability);
    }
    BsdfSample bs;
    if (!bsdf.sample(wo, uChoose.y, uBsdf, bs)) break;
    throughput *= bs.weight;
    specularBounce = bs.specular;
    previousPdf = bs.pdf;
    previousPoint = hit.point;
    if (isBlack(throughput)) break;
    // Russian roulette after a few bounces keeps long paths cheap without bias.
    if (depth >= 3) {
      const float survive = std::min(0.95f, std::max({throughput.x, throughput.y, throughput.z}));
      if (sampler.next1D() >= survive) break;
      throughput /= survive;
    }
    origin = offsetOrigin(hit, bs.wi);
    direction = bs.wi;
  }
  return radiance;
}

}  // namespace

glm::vec3 incomingRadiance(const Scene& scene, glm::vec3 origin, glm::vec3 direction,
                           PixelSampler& sampler, const IntegratorSettings& settings) {
  if (settings.kind == IntegratorKind::DirectLighting) {
    return directLighting(scene, origin, direction, sampler, settings.maxDepth,
                          settings.cameraSpreadRadians);
  }
  return pathTrace(scene, origin, direction, sampler, settings.maxDepth,
                   settings.cameraSpreadRadians);
}

}  // namespace lenslab::render
