#pragma once
// Which light the path tracer's next-event estimation samples at a shading point (one light per
// bounce).
//
// A uniform choice spends a scene's shadow rays evenly: with nine small lamps beside a sun and a
// sky, nine in eleven went to lamps that light almost nothing, and the sunlit ground grew
// several times noisier. Instead each light is chosen in proportion to a bound of the
// irradiance it can give at the point, as pbrt-v4's light samplers weigh lights by their power
// and distance (Pharr, Jakob and Humphreys, Physically Based Rendering, 4th ed., sec. 12.6):
// - a distant light: its irradiance L;
// - an infinite light: pi times its mean radiance (a whole sky above a surface);
// - a point or spot light: I / d^2;
// - an area light: L times its projected area over d^2 (at most pi L), with d the distance to its
//   bounding sphere's centre, no less than that sphere's radius;
// all in luminance (Rec. 709 weights of linear RGB). The surface's orientation and occlusion are
// left out: they would need the normal, and a bound that is too small where a light matters
// costs far more noise than one that is too large. A tenth of the probability is spread
// uniformly, so every light keeps at least 0.1 / N (the choice stays unbiased with any bound,
// and no light's variance grows by more than 10 N).
//
// The probabilities are computed for the point at each call: O(N) per bounce, which at the
// dozens of lights of the scenes here costs far less than the bounce's rays. A scene of
// thousands of emitters would need a light tree (pbrt-v4's BVHLightSampler).

#include <glm/vec3.hpp>
#include <vector>

#include "render/light.h"

namespace lenslab::render {

class LightSelection {
 public:
  LightSelection() = default;
  explicit LightSelection(const std::vector<Light>& lights);

  std::size_t size() const { return bounds_.size(); }
  // The light for u in [0, 1) at `point`, and the probability with which it was chosen.
  int choose(glm::vec3 point, float u, float& probability) const;
  // The probability with which choose(point, ...) picks light `index`.
  float probability(glm::vec3 point, int index) const;

 private:
  struct Bound {
    bool positional = false;  // the bound falls off with the distance to `center`
    glm::vec3 center{0.0f};
    float scale = 0.0f;  // luminance times projected area (area lights), or I, or the constant
    float minDistance2 = 0.0f;
    float maxIrradiance = 0.0f;  // area lights: pi L
  };
  // The bound of each light's irradiance at `point` into `weights`; returns their sum.
  float weigh(glm::vec3 point, std::vector<float>& weights) const;

  std::vector<Bound> bounds_;
};

}  // namespace lenslab::render
