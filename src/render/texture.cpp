#include "render/texture.h"

#include <algorithm>
#include <cmath>

namespace lenslab::render {

int TextureSet::add(Texture texture) {
  textures_.push_back(std::move(texture));
  return static_cast<int>(textures_.size()) - 1;
}

int TextureSet::constant(glm::vec3 value) {
  Texture texture;
  texture.value = value;
  return add(texture);
}

glm::vec3 TextureSet::evaluate(int index, glm::vec2 uv) const {
  const Texture& texture = textures_[static_cast<std::size_t>(index)];
  switch (texture.kind) {
    case TextureKind::Constant:
      return texture.value;
    case TextureKind::Scale:
      return evaluate(texture.first, uv) * evaluate(texture.second, uv);
    case TextureKind::Checkerboard: {
      const float s = texture.uScale * uv.x + texture.uDelta;
      const float t = texture.vScale * uv.y + texture.vDelta;
      const long cell = static_cast<long>(std::floor(s)) + static_cast<long>(std::floor(t));
      return evaluate((cell & 1) == 0 ? texture.first : texture.second, uv);
    }
    case TextureKind::Image: {
      const glm::vec2 st(texture.uScale * uv.x + texture.uDelta,
                         texture.vScale * uv.y + texture.vDelta);
      return lookupImage(texture, st) * texture.imageScale;
    }
  }
  return glm::vec3(0.0f);
}

// Bilinear lookup. t = 0 is the bottom row of the image (pbrt-v3 flips images on load so that
// texture space has its origin at the lower left).
glm::vec3 TextureSet::lookupImage(const Texture& texture, glm::vec2 st) const {
  const FloatImage& image = *texture.image;
  const float x = st.x * static_cast<float>(image.width) - 0.5f;
  const float y = (texture.flipT ? 1.0f - st.y : st.y) * static_cast<float>(image.height) - 0.5f;
  const int x0 = static_cast<int>(std::floor(x));
  const int y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0);
  const float fy = y - static_cast<float>(y0);
  auto texel = [&](int px, int py) -> glm::vec3 {
    if (texture.blackWrap &&
        (px < 0 || py < 0 || px >= image.width || py >= image.height)) {
      return glm::vec3(0.0f);
    }
    if (texture.clampWrap) {
      px = std::clamp(px, 0, image.width - 1);
      py = std::clamp(py, 0, image.height - 1);
    } else {
      px = ((px % image.width) + image.width) % image.width;
      py = ((py % image.height) + image.height) % image.height;
    }
    const float* p = &image.rgb[(static_cast<std::size_t>(py) * image.width + px) * 3];
    return {p[0], p[1], p[2]};
  };
  return (1 - fx) * (1 - fy) * texel(x0, y0) + fx * (1 - fy) * texel(x0 + 1, y0) +
         (1 - fx) * fy * texel(x0, y0 + 1) + fx * fy * texel(x0 + 1, y0 + 1);
}

}  // namespace lenslab::render
