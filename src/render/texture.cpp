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

bool TextureSet::dependsOnUv(int index) const {
  if (index < 0) return false;
  const Texture& texture = textures_[static_cast<std::size_t>(index)];
  switch (texture.kind) {
    case TextureKind::Constant:
      return false;
    case TextureKind::Scale:
      return dependsOnUv(texture.first) || dependsOnUv(texture.second);
    case TextureKind::Checkerboard:
    case TextureKind::Image:
      return true;
  }
  return true;
}

glm::vec3 TextureSet::evaluate(int index, glm::vec2 uv, float footprint) const {
  const Texture& texture = textures_[static_cast<std::size_t>(index)];
  switch (texture.kind) {
    case TextureKind::Constant:
      return texture.value;
    case TextureKind::Scale:
      return evaluate(texture.first, uv, footprint) * evaluate(texture.second, uv, footprint);
    case TextureKind::Checkerboard: {
      const float s = texture.uScale * uv.x + texture.uDelta;
      const float t = texture.vScale * uv.y + texture.vDelta;
      const long cell = static_cast<long>(std::floor(s)) + static_cast<long>(std::floor(t));
      return evaluate((cell & 1) == 0 ? texture.first : texture.second, uv, footprint);
    }
    case TextureKind::Image: {
      const glm::vec2 st(texture.uScale * uv.x + texture.uDelta,
                         texture.vScale * uv.y + texture.vDelta);
      const auto& coarser = texture.coarserMipLevels;
      if (!coarser || coarser->empty() || footprint <= 0.0f) {
        return lookupImage(texture, *texture.image, st) * texture.imageScale;
      }
      // Trilinear: the level whose texel matches the footprint, blended with the next one.
      const float texels = footprint *
                           std::max(std::abs(texture.uScale), std::abs(texture.vScale)) *
                           static_cast<float>(texture.image->width);
      const float level =
          std::clamp(std::log2(std::max(texels, 1.0f)), 0.0f, static_cast<float>(coarser->size()));
      const auto lower = static_cast<std::size_t>(level);
      const std::size_t upper = std::min(lower + 1, coarser->size());
      const float blend = level - static_cast<float>(lower);
      const auto levelImage = [&](std::size_t levelIndex) -> const FloatImage& {
        return levelIndex == 0 ? *texture.image : (*coarser)[levelIndex - 1];
      };
      const glm::vec3 a = lookupImage(texture, levelImage(lower), st);
      const glm::vec3 b = blend > 0.0f ? lookupImage(texture, levelImage(upper), st) : a;
      return ((1.0f - blend) * a + blend * b) * texture.imageScale;
    }
  }
  return glm::vec3(0.0f);
}

// Bilinear lookup. t = 0 is the bottom row of the image (pbrt-v3 flips images on load so that
// texture space has its origin at the lower left).
glm::vec3 TextureSet::lookupImage(const Texture& texture, const FloatImage& image,
                                  glm::vec2 st) const {
  const float x = st.x * static_cast<float>(image.width) - 0.5f;
  const float y = (texture.flipT ? 1.0f - st.y : st.y) * static_cast<float>(image.height) - 0.5f;
  const int x0 = static_cast<int>(std::floor(x));
  const int y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0);
  const float fy = y - static_cast<float>(y0);
  auto texel = [&](int px, int py) -> glm::vec3 {
    if (texture.blackWrap && (px < 0 || py < 0 || px >= image.width || py >= image.height)) {
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

namespace lenslab::render {

std::shared_ptr<const std::vector<FloatImage>> buildCoarserMipLevels(const FloatImage& image) {
  const int size = image.width;
  if (size != image.height || size <= 0 || (size & (size - 1)) != 0) return nullptr;
  auto levels = std::make_shared<std::vector<FloatImage>>();
  while ((levels->empty() ? image : levels->back()).width > 1) {
    const FloatImage& fine = levels->empty() ? image : levels->back();
    FloatImage coarse;
    coarse.width = coarse.height = fine.width / 2;
    coarse.rgb.resize(static_cast<std::size_t>(coarse.width) * coarse.height * 3);
    for (int y = 0; y < coarse.height; ++y) {
      for (int x = 0; x < coarse.width; ++x) {
        for (int c = 0; c < 3; ++c) {
          auto at = [&](int fx, int fy) {
            return fine.rgb[(static_cast<std::size_t>(fy) * fine.width + fx) * 3 + c];
          };
          coarse.rgb[(static_cast<std::size_t>(y) * coarse.width + x) * 3 + c] =
              0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                       at(2 * x + 1, 2 * y + 1));
        }
      }
    }
    levels->push_back(std::move(coarse));
  }
  return levels;
}

}  // namespace lenslab::render
