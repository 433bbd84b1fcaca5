#include "render/light_selection.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "render/sampling.h"

namespace lenslab::render {

namespace {

constexpr float kUniformShare = 0.1f;

// Rec. 709 luminance of linear sRGB.
float luminance(glm::vec3 rgb) {
  return std::max(0.0f, 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z);
}

// The mean luminance of an infinite light's radiance over the sphere of directions: its map's
// rows weighted by the solid angle they cover (sin theta), times its scale.
float meanLuminance(const Light& light) {
  if (!light.map || light.map->width <= 0 || light.map->height <= 0) {
    return luminance(light.intensity);
  }
  const FloatImage& image = *light.map;
  double sum = 0.0, weightSum = 0.0;
  for (int y = 0; y < image.height; ++y) {
    const double weight = std::sin(kPi * (y + 0.5) / image.height);
    double row = 0.0;
    for (int x = 0; x < image.width; ++x) {
      const float* texel = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
      row += luminance(light.intensity * glm::vec3(texel[0], texel[1], texel[2]));
    }
    sum += weight * row / image.width;
    weightSum += weight;
  }
  return weightSum > 0.0 ? static_cast<float>(sum / weightSum) : 0.0f;
}

// The centre and radius of a sphere around an area light's emitter.
void emitterSphere(const Emitter& emitter, glm::vec3& center, float& radius) {
  if (emitter.isSphere) {
    center = glm::vec3(emitter.sphereCenter);
    radius = static_cast<float>(emitter.sphereRadius);
    return;
  }
  glm::dvec3 lower(std::numeric_limits<double>::infinity()), upper(-lower);
  if (emitter.isQuadric) {
    emitter.quadric.parentBounds(lower, upper);
  } else {
    for (const glm::vec3& vertex : emitter.triangles) {
      lower = glm::min(lower, glm::dvec3(vertex));
      upper = glm::max(upper, glm::dvec3(vertex));
    }
  }
  if (!(lower.x <= upper.x)) {
    center = glm::vec3(0.0f);
    radius = 0.0f;
    return;
  }
  center = glm::vec3(0.5 * (lower + upper));
  radius = static_cast<float>(0.5 * glm::length(upper - lower));
}

}  // namespace

LightSelection::LightSelection(const std::vector<Light>& lights) {
  bounds_.reserve(lights.size());
  for (const Light& light : lights) {
    Bound bound;
    switch (light.kind) {
      case LightKind::Distant:
        bound.scale = luminance(light.intensity);
        break;
      case LightKind::Infinite:
        bound.scale = kPi * meanLuminance(light);
        break;
      case LightKind::Point:
      case LightKind::Spot:
        bound.positional = true;
        bound.center = light.position;
        bound.scale = luminance(light.intensity);
        bound.maxIrradiance = std::numeric_limits<float>::infinity();
        break;
      case LightKind::Area: {
        bound.positional = true;
        float radius = 0.0f;
        emitterSphere(*light.emitter, bound.center, radius);
        bound.minDistance2 = radius * radius;
        // A sphere shows pi r^2 = area / 4 from anywhere; a flat emitter at most its area.
        const float projectedArea =
            light.emitter->isSphere ? 0.25f * light.emitter->area : light.emitter->area;
        bound.scale = luminance(light.intensity) * projectedArea;
        bound.maxIrradiance = kPi * luminance(light.intensity);
        break;
      }
    }
    if (!std::isfinite(bound.scale)) bound.scale = 0.0f;
    bounds_.push_back(bound);
  }
}

float LightSelection::weigh(glm::vec3 point, std::vector<float>& weights) const {
  weights.resize(bounds_.size());
  float total = 0.0f;
  for (std::size_t i = 0; i < bounds_.size(); ++i) {
    const Bound& bound = bounds_[i];
    float weight = bound.scale;
    if (bound.positional) {
      const glm::vec3 offset = bound.center - point;
      const float distance2 = std::max(glm::dot(offset, offset), bound.minDistance2);
      weight = distance2 > 0.0f ? std::min(bound.scale / distance2, bound.maxIrradiance)
                                : bound.maxIrradiance;
      if (!std::isfinite(weight)) weight = 0.0f;  // a point light at the point itself
    }
    weights[i] = weight;
    total += weight;
  }
  return total;
}

int LightSelection::choose(glm::vec3 point, float u, float& probability) const {
  thread_local std::vector<float> weights;
  const float total = weigh(point, weights);
  const float count = static_cast<float>(bounds_.size());
  const float uniform = total > 0.0f ? kUniformShare / count : 1.0f / count;
  const float byWeight = total > 0.0f ? (1.0f - kUniformShare) / total : 0.0f;
  // Walk the cumulative probabilities; the last light takes what rounding leaves over.
  float cumulative = 0.0f;
  const int last = static_cast<int>(bounds_.size()) - 1;
  for (int i = 0; i < last; ++i) {
    const float p = uniform + byWeight * weights[static_cast<std::size_t>(i)];
    cumulative += p;
    if (u < cumulative) {
      probability = p;
      return i;
    }
  }
  probability = uniform + byWeight * weights[static_cast<std::size_t>(last)];
  return last;
}

float LightSelection::probability(glm::vec3 point, int index) const {
  thread_local std::vector<float> weights;
  const float total = weigh(point, weights);
  const float count = static_cast<float>(bounds_.size());
  if (!(total > 0.0f)) return 1.0f / count;
  return kUniformShare / count +
         (1.0f - kUniformShare) * weights[static_cast<std::size_t>(index)] / total;
}

}  // namespace lenslab::render
