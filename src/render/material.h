#pragma once
// pbrt's materials as RGB BSDFs: matte (Lambert), plastic (Lambert + rough dielectric
// reflection), mirror, glass (smooth dielectric) and metal (rough conductor). Rough lobes use
// the Trowbridge-Reitz (GGX) distribution with Smith shadowing (Walter et al. 2007).

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/sampling.h"
#include "render/texture.h"

namespace lenslab::render {

enum class MaterialKind { Matte, Plastic, Mirror, Glass, Metal, None };

struct Material {
  MaterialKind kind = MaterialKind::Matte;
  int kd = -1, ks = -1, kr = -1, kt = -1;  // colour textures
  int roughness = -1;                      // float texture (grey colour)
  bool remapRoughness = true;
  float eta = 1.5f;                       // glass
  glm::vec3 metalEta{0.2f, 0.92f, 1.1f};  // copper, roughly, as pbrt's default
  glm::vec3 metalK{3.9f, 2.45f, 2.14f};
  // Whether any texture above varies over the surface: only then do hits need their (u, v)
  // (which costs quadrics an atan2 and, for spheres, acos calls).
  bool usesUv = true;
};

bool materialUsesUv(const Material& material, const TextureSet& textures);

struct BsdfSample {
  glm::vec3 wi{0.0f};      // world space
  glm::vec3 weight{0.0f};  // f * |cos| / pdf
  float pdf = 0.0f;
  bool specular = false;
};

// A material evaluated at one surface point, in the shading frame around the shading normal.
class Bsdf {
 public:
  // `footprint`: the texture-space width the shading point stands for (0: point lookups).
  Bsdf(const Material& material, const TextureSet& textures, glm::vec2 uv, glm::vec3 normal,
       float footprint = 0.0f);

  // f(wo, wi) and the density sample() would have for wi (solid angle), world directions.
  glm::vec3 evaluate(glm::vec3 wo, glm::vec3 wi, float& pdf) const;
  bool sample(glm::vec3 wo, float uLobe, glm::vec2 u, BsdfSample& out) const;
  // The same from one 2D sample: u.x picks the lobe and is stretched back to [0, 1) within it,
  // so that a caller spends one dimension pair instead of one and a half.
  bool sample(glm::vec3 wo, glm::vec2 u, BsdfSample& out) const;
  // true when the BSDF is all delta lobes: light sampling cannot help.
  bool isSpecular() const {
    return kind_ == MaterialKind::Mirror || kind_ == MaterialKind::Glass ||
           kind_ == MaterialKind::None;
  }
  bool passThrough() const { return kind_ == MaterialKind::None; }

 private:
  glm::vec3 evaluateLocal(glm::vec3 wo, glm::vec3 wi, float& pdf) const;

  MaterialKind kind_;
  Frame frame_;
  glm::vec3 kd_{0.0f}, ks_{0.0f}, kr_{0.0f}, kt_{0.0f};
  float alpha_ = 0.0f;
  float eta_ = 1.5f;
  glm::vec3 metalEta_{1.0f}, metalK_{0.0f};
};

// Fresnel reflectance of a dielectric interface for unpolarised light; cosThetaI on the side of
// the normal where the index is etaOutside.
float fresnelDielectric(float cosThetaI, float etaInside, float etaOutside = 1.0f);
// Fresnel reflectance of a conductor (complex index eta + i k), per colour channel.
glm::vec3 fresnelConductor(float cosThetaI, glm::vec3 eta, glm::vec3 k);
// pbrt-v3's map from a perceptual "roughness" in [0, 1] to the GGX alpha.
float roughnessToAlpha(float roughness);

}  // namespace lenslab::render
