// The plastic BSDF alone under uniform white illumination (radiance 1 from every direction of
// the hemisphere): the radiance it reflects toward wo is its directional albedo
// rho(wo) = integral of f(wo, wi) cos(theta_i) over the hemisphere. The reference here is a
// brute-force quadrature of pbrt-v3's plastic model written out from the PBR book (3rd ed.),
// independent of src/render/material.cpp:
// - Lambertian Kd / pi (8.3);
// - a Torrance-Sparrow lobe Ks D G Fr / (4 cos(theta_o) cos(theta_i)) (8.4.4) with the
//   Trowbridge-Reitz D in its tan^2 form (8.4.2), Smith's G = 1 / (1 + Lambda(wo) + Lambda(wi))
//   (8.4.3), roughness remapped to alpha by the book's polynomial in log(roughness) (8.4.2);
// - the Fresnel term of PlasticMaterial, FresnelDielectric(1.5, 1) (9.2.2): etaI = 1.5 on the
//   side of the incident direction and etaT = 1, the dielectric Fresnel equations of 8.2.1
//   evaluated as given, so reflection is total beyond the critical angle asin(1 / 1.5).
// The material's own estimate is the mean of its sampled weights f |cos| / pdf, which also
// checks that its sampling and its pdf agree with its f.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "render/material.h"
#include "render/texture.h"

namespace lenslab::render {
namespace {

constexpr double kPiD = std::numbers::pi;

struct PlasticParameters {
  glm::dvec3 kd, ks;
  double alpha;  // Trowbridge-Reitz alpha after any remapping
};

// The PBR book's (8.4.2) map from pbrt's "roughness" to alpha.
double bookRoughnessToAlpha(double roughness) {
  const double x = std::log(std::max(roughness, 1e-3));
  return 1.62142 + 0.819955 * x + 0.1734 * x * x + 0.0171201 * x * x * x +
         0.000640711 * x * x * x * x;
}

// Dielectric Fresnel reflectance (8.2.1) for light arriving at cosThetaI > 0 in a medium of
// index etaI toward one of index etaT.
double bookFresnel(double cosThetaI, double etaI, double etaT) {
  const double sinThetaI = std::sqrt(std::max(0.0, 1.0 - cosThetaI * cosThetaI));
  const double sinThetaT = etaI / etaT * sinThetaI;
  if (sinThetaT >= 1.0) return 1.0;
  const double cosThetaT = std::sqrt(1.0 - sinThetaT * sinThetaT);
  const double rParallel =
      (etaT * cosThetaI - etaI * cosThetaT) / (etaT * cosThetaI + etaI * cosThetaT);
  const double rPerpendicular =
      (etaI * cosThetaI - etaT * cosThetaT) / (etaI * cosThetaI + etaT * cosThetaT);
  return 0.5 * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

double tan2Theta(glm::dvec3 w) { return (1.0 - w.z * w.z) / (w.z * w.z); }

double trowbridgeReitzD(glm::dvec3 h, double alpha) {
  const double cos4 = h.z * h.z * h.z * h.z;
  const double e = 1.0 + tan2Theta(h) / (alpha * alpha);
  return 1.0 / (kPiD * alpha * alpha * cos4 * e * e);
}

double smithLambda(glm::dvec3 w, double alpha) {
  return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2Theta(w)));
}

glm::dvec3 bookPlasticF(const PlasticParameters& p, glm::dvec3 wo, glm::dvec3 wi) {
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double g = 1.0 / (1.0 + smithLambda(wo, p.alpha) + smithLambda(wi, p.alpha));
  const double specular = trowbridgeReitzD(h, p.alpha) * g *
                          bookFresnel(glm::dot(wi, h), 1.5, 1.0) / (4.0 * wo.z * wi.z);
  return p.kd / kPiD + p.ks * specular;
}

// Midpoint quadrature over the hemisphere in (theta, phi); wo lies in the xz plane, so the
// integrand is even in phi and only phi in [0, pi] is visited.
template <typename F>
glm::dvec3 hemisphereIntegral(F&& integrand) {
  constexpr int kTheta = 1200, kPhi = 1200;
  const double dTheta = 0.5 * kPiD / kTheta, dPhi = kPiD / kPhi;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * dTheta;
    const double weight = std::sin(theta) * std::cos(theta) * dTheta * dPhi * 2.0;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const glm::dvec3 wi(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                          std::cos(theta));
      sum += integrand(wi) * weight;
    }
  }
  return sum;
}

// The mean weight of the material's samples over a stratified grid (failed samples count 0).
glm::dvec3 sampledAlbedo(const Bsdf& bsdf, glm::vec3 wo) {
  constexpr int kGrid = 1024;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const glm::vec2 u((i + 0.5f) / kGrid, (j + 0.5f) / kGrid);
      BsdfSample sample;
      if (bsdf.sample(wo, u, sample)) sum += glm::dvec3(sample.weight);
    }
  }
  return sum / double(kGrid * kGrid);
}

struct ReflectanceCase {
  float roughness;
  bool remap;
  float cosThetaO;
};

class PlasticReflectance : public ::testing::TestWithParam<ReflectanceCase> {};

TEST_P(PlasticReflectance, MatchesQuadratureOfTheBookModel) {
  const ReflectanceCase c = GetParam();
  // The benchmark scene's red plastic (bench-world.pbrt).
  const glm::vec3 kd(0.6f, 0.08f, 0.06f), ks(0.35f, 0.35f, 0.35f);
  TextureSet textures;
  Material material;
  material.kind = MaterialKind::Plastic;
  material.kd = textures.constant(kd);
  material.ks = textures.constant(ks);
  material.roughness = textures.constant(glm::vec3(c.roughness));
  material.remapRoughness = c.remap;
  material.usesUv = false;
  const Bsdf bsdf(material, textures, glm::vec2(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));

  const PlasticParameters book{glm::dvec3(kd), glm::dvec3(ks),
                               c.remap ? bookRoughnessToAlpha(c.roughness) : c.roughness};
  const double sinThetaO = std::sqrt(1.0 - double(c.cosThetaO) * c.cosThetaO);
  const glm::dvec3 woD(sinThetaO, 0.0, c.cosThetaO);
  const glm::vec3 wo(woD);

  const glm::dvec3 expected =
      hemisphereIntegral([&](glm::dvec3 wi) { return bookPlasticF(book, woD, wi); });
  // f itself, integrated the same way, and the material's sampled estimate.
  const glm::dvec3 integratedF = hemisphereIntegral([&](glm::dvec3 wi) {
    float pdf = 0.0f;
    return glm::dvec3(bsdf.evaluate(wo, glm::vec3(wi), pdf));
  });
  const glm::dvec3 sampled = sampledAlbedo(bsdf, wo);
  for (int channel = 0; channel < 3; ++channel) {
    SCOPED_TRACE("channel " + std::to_string(channel));
    EXPECT_NEAR(integratedF[channel], expected[channel], 2e-3 * expected[channel]);
    EXPECT_NEAR(sampled[channel], expected[channel], 5e-3 * expected[channel]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    BenchAndRougher, PlasticReflectance,
    ::testing::Values(ReflectanceCase{0.02f, true, 0.95f}, ReflectanceCase{0.02f, true, 0.7f},
                      ReflectanceCase{0.02f, true, 0.4f}, ReflectanceCase{0.3f, true, 0.8f},
                      ReflectanceCase{0.3f, true, 0.5f}, ReflectanceCase{0.4f, false, 0.6f}),
    [](const ::testing::TestParamInfo<ReflectanceCase>& param) {
      const ReflectanceCase& c = param.param;
      return "roughness" + std::to_string(int(c.roughness * 100 + 0.5f)) +
             (c.remap ? "remapped" : "asAlpha") + "_cos" +
             std::to_string(int(c.cosThetaO * 100 + 0.5f));
    });

// The Fresnel term alone: at normal incidence both orders of the indices give
// ((1.5 - 1) / (1.5 + 1))^2 = 0.04, and beyond the critical angle asin(1 / 1.5) = 41.8 degrees
// pbrt-v3's plastic reflects totally.
TEST(PlasticFresnel, IsPbrtV3sFresnelDielectricFromInside) {
  EXPECT_NEAR(bookFresnel(1.0, 1.5, 1.0), 0.04, 1e-12);
  TextureSet textures;
  Material material;
  material.kind = MaterialKind::Plastic;
  material.kd = textures.constant(glm::vec3(0.0f));
  material.ks = textures.constant(glm::vec3(1.0f));
  material.roughness = textures.constant(glm::vec3(0.5f));
  material.remapRoughness = false;
  const Bsdf bsdf(material, textures, glm::vec2(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  // Mirror directions at 60 degrees: h is the normal, so Fr(cos 60) = 1, and f = D(n) G / (4
  // cos^2 60) with D(n) = 1 / (pi alpha^2).
  const float s = std::sqrt(0.75f);
  const glm::vec3 wo(s, 0.0f, 0.5f), wi(-s, 0.0f, 0.5f);
  float pdf = 0.0f;
  const double f = bsdf.evaluate(wo, wi, pdf).x;
  const double lambda = smithLambda(glm::dvec3(wo), 0.5);
  const double expected = 1.0 / (kPiD * 0.25) / (1.0 + 2.0 * lambda) / (4.0 * 0.25);
  EXPECT_NEAR(f, expected, 1e-5 * expected);
}

}  // namespace
}  // namespace lenslab::render
