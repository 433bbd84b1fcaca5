#pragma once
// Textures evaluated at a surface's (u, v): constant, scale (product of two), 2D checkerboard
// and image maps. Float textures are stored as grey colours.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "render/image_io.h"

namespace lenslab::render {

enum class TextureKind { Constant, Scale, Checkerboard, Image };

struct Texture {
  TextureKind kind = TextureKind::Constant;
  glm::vec3 value{0.5f};
  int first = -1;   // Scale: tex1, Checkerboard: tex1
  int second = -1;  // Scale: tex2, Checkerboard: tex2
  // The (u, v) mapping: s = uScale * u + uDelta, t = vScale * v + vDelta.
  float uScale = 1.0f, vScale = 1.0f, uDelta = 0.0f, vDelta = 0.0f;
  std::shared_ptr<const FloatImage> image;
  // Box-filtered mip levels 1, 2, ... of `image` (level 0 is `image` itself, not copied), for
  // footprint-sized lookups; only built for power-of-two square images.
  std::shared_ptr<const std::vector<FloatImage>> coarserMipLevels;
  float imageScale = 1.0f;
  bool clampWrap = false;
  bool blackWrap = false;
  // pbrt-v3 puts t = 0 at the bottom row of an image; pbrt-v2 at the top row.
  bool flipT = true;
};

// Halves a power-of-two square image repeatedly (2x2 box filter) down to 1x1: levels 1, 2, ...
// of its pyramid (none for a 1x1 image); null for any other shape.
std::shared_ptr<const std::vector<FloatImage>> buildCoarserMipLevels(const FloatImage& image);

class TextureSet {
 public:
  int add(Texture texture);
  int constant(glm::vec3 value);
  // `footprint`: the width in (u, v) units of the area the lookup stands for (0: a point).
  glm::vec3 evaluate(int index, glm::vec2 uv, float footprint = 0.0f) const;
  // Whether texture `index` varies with (u, v) (false for constants and products of them).
  bool dependsOnUv(int index) const;
  std::size_t size() const { return textures_.size(); }

 private:
  glm::vec3 lookupImage(const Texture& texture, const FloatImage& image, glm::vec2 st) const;
  std::vector<Texture> textures_;
};

}  // namespace lenslab::render
