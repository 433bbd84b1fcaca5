#pragma once
// Radiance along a camera ray: pbrt-v2-style direct lighting, or a path tracer with next-event
// estimation and multiple importance sampling (Veach 1997, ch. 9).

#include <glm/vec3.hpp>

#include "render/sampler.h"
#include "render/scene.h"
#include "render/scene_description.h"

namespace lenslab::render {

struct IntegratorSettings {
  IntegratorKind kind = IntegratorKind::Path;
  int maxDepth = 5;
  // Angular width of one camera sample's footprint, for filtering textures at the first hit
  // (pbrt: a pixel's ray differentials scaled by 1/sqrt(samples per pixel)). 0: point lookups.
  float cameraSpreadRadians = 0.0f;
};

glm::vec3 incomingRadiance(const Scene& scene, glm::vec3 origin, glm::vec3 direction,
                           PixelSampler& sampler, const IntegratorSettings& settings);

}  // namespace lenslab::render
