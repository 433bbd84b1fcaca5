#pragma once
// Which light the path tracer's next-event estimation samples at a shading point (one light per
// bounce).
//
// A uniform choice spends a scene's shadow rays evenly: with nine small lamps beside a sun and a
// sky, nine in eleven went to lamps that light almost nothing, and the sunlit picture below them
// had 2.3 times the error at equal samples per pixel (bench/light-choice-error.sh). Instead each
// light is chosen in proportion to a bound of the irradiance it can give at the point, as pbrt-v4's
// light samplers weigh lights by their power and distance (Pharr, Jakob and Humphreys, Physically
// Based Rendering, 4th ed., sec. 12.6):
// - a distant light: its irradiance L;
// - an infinite light: pi times its mean radiance (a whole sky above a surface);
// - a point or spot light: I / d^2;
// - an area light: L times its projected area over d^2 (at most pi L), with d the distance to its
//   bounding sphere's centre, no less than that sphere's radius;
// all in luminance (Rec. 709 weights of linear RGB). The surface's orientation and occlusion are
// left out: they would need the normal, and a bound that is too small where a light matters
// costs far more noise than one that is too large. A tenth of the probability is spread
// uniformly, so every light keeps at least 0.1 / N: the choice stays unbiased with any bound, and
// no light is sampled less than a tenth as often as a uniform choice would.
//
// The probabilities are computed at each vertex of a path (LightSelection::evaluate), O(N): on
// the default scene's 11 lights that and the choice took 6.5% of a preview pass (perf, stop 35).
// A scene of thousands of emitters would need a light tree (pbrt-v4's BVHLightSampler).

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "render/light.h"

namespace lenslab::render {

class LightSelection {
 public:
  // The choice at one point: each light's bound there. The path tracer keeps it after choosing
  // the light for next-event estimation, for the weight of the light its BSDF sample meets next.
  class AtPoint {
   public:
    // The light for u in [0, 1), and the probability with which it is chosen.
    int choose(float u, float& probability) const;
    float probability(int index) const {
      return uniform_ + byBound_ * bounds_[static_cast<std::size_t>(index)];
    }

   private:
    friend class LightSelection;
    std::vector<float> bounds_;
    float uniform_ = 0.0f, byBound_ = 0.0f;
  };

  LightSelection() = default;
  explicit LightSelection(const std::vector<Light>& lights);

  std::size_t size() const { return scale_.size(); }
  // The choice's probabilities at `point` into `out` (O(N)). The scene must have a light.
  void evaluate(glm::vec3 point, AtPoint& out) const;

 private:
  // Per light, as arrays that evaluate's loop reads without a branch: the bound is
  // min(scale / max(d^2, minDistance2), maxBound), d the distance to the centre, for positional
  // lights; min(scale, maxBound) for the others.
  std::vector<float> scale_, minDistance2_, maxBound_, centerX_, centerY_, centerZ_;
  std::vector<std::uint8_t> positional_;
};

}  // namespace lenslab::render
