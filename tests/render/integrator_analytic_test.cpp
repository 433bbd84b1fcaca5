// Both integrators against closed-form radiance: a matte ground point under a lamp (a sphere or a
// disk), a sun and a uniform sky, at maxdepth 1 (direct light only). The references are the
// irradiance formulas of a uniformly bright sphere and disk, not either integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render/integrator.h"
#include "render/pbrt_parser.h"
#include "render/scene_builder.h"

namespace lenslab::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Estimate {
  double mean = 0.0, standardError = 0.0;
};

// The green channel of incomingRadiance along one ray, averaged over `pixels` independent
// scramblings of `samples` samples each; the standard error comes from the spread of the
// per-pixel means.
Estimate estimate(const Scene& scene, glm::vec3 origin, glm::vec3 direction,
                  const IntegratorSettings& settings, int pixels, int samples) {
  double sum = 0.0, sumSquares = 0.0;
  for (int pixel = 0; pixel < pixels; ++pixel) {
    double pixelSum = 0.0;
    for (int s = 0; s < samples; ++s) {
      PixelSampler sampler(static_cast<std::uint32_t>(pixel), static_cast<std::uint32_t>(s), 7u);
      pixelSum += incomingRadiance(scene, origin, direction, sampler, settings).y;
    }
    const double pixelMean = pixelSum / samples;
    sum += pixelMean;
    sumSquares += pixelMean * pixelMean;
  }
  Estimate result;
  result.mean = sum / pixels;
  const double variance = std::max(0.0, sumSquares / pixels - result.mean * result.mean);
  result.standardError = std::sqrt(variance / (pixels - 1));
  return result;
}

enum class LampShape { Sphere, DiskFacingDown };

// A lamp centred at (x, y, 0); a disk faces down (-y).
struct Lamp {
  LampShape shape;
  double radius, x, y, radiance;
};

struct LampScene {
  std::vector<Lamp> lamps;
  double skyRadiance = 0.0, sunRadiance = 0.0;
  glm::dvec3 sunFrom{0.0, 1.0, 1.0};
  double albedo = 0.5;
};

std::string sceneText(const LampScene& s) {
  auto number = [](double v) { return std::to_string(v); };
  auto rgb = [&](double v) { return "[" + number(v) + " " + number(v) + " " + number(v) + "]"; };
  std::string text =
      "LookAt 0 3 3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [10]\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "WorldBegin\n";
  if (s.skyRadiance > 0) text += "LightSource \"infinite\" \"rgb L\" " + rgb(s.skyRadiance) + "\n";
  if (s.sunRadiance > 0) {
    text += "LightSource \"distant\" \"point from\" [" + number(s.sunFrom.x) + " " +
            number(s.sunFrom.y) + " " + number(s.sunFrom.z) + "] \"point to\" [0 0 0] \"rgb L\" " +
            rgb(s.sunRadiance) + "\n";
  }
  for (const Lamp& lamp : s.lamps) {
    text += "AttributeBegin\n AreaLightSource \"diffuse\" \"rgb L\" " + rgb(lamp.radiance) +
            "\n Translate " + number(lamp.x) + " " + number(lamp.y) + " 0\n" +
            (lamp.shape == LampShape::Sphere ? " Shape \"sphere\""
                                             : " Rotate 90 1 0 0 Shape \"disk\"") +
            " \"float radius\" [" + number(lamp.radius) + "]\nAttributeEnd\n";
  }
  text += "AttributeBegin\n Material \"matte\" \"rgb Kd\" " + rgb(s.albedo) +
          "\n Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]"
          " \"point P\" [-50 0 -50  50 0 -50  50 0 50  -50 0 50]\nAttributeEnd\nWorldEnd\n";
  return text;
}

// Radiance leaving the ground at the origin toward the camera. A lamp gives pi L times its
// projected solid angle, and hides as much of the sky (the lamps here do not hide one another):
// - a sphere of radius r whose centre is at distance d, at angle theta from the normal and wholly
//   above the horizon: (r/d)^2 cos(theta) (Lambert's result for a sphere; Howell, "A Catalog of
//   Radiation Heat Transfer Configuration Factors", B-13), for any d and theta;
// - a disk of radius r facing the point from height h on its axis: r^2 / (h^2 + r^2) (Howell,
//   B-12).
// The sun gives E cos(theta_sun).
double analyticRadiance(const LampScene& s) {
  double irradiance = s.skyRadiance * kPi;
  for (const Lamp& lamp : s.lamps) {
    const double d2 = lamp.x * lamp.x + lamp.y * lamp.y;
    const double r2 = lamp.radius * lamp.radius;
    const double projected = lamp.shape == LampShape::Sphere
                                 ? kPi * (r2 / d2) * (lamp.y / std::sqrt(d2))
                                 : kPi * r2 / (lamp.y * lamp.y + r2);
    irradiance += (lamp.radiance - s.skyRadiance) * projected;
  }
  irradiance += s.sunRadiance * std::max(0.0, s.sunFrom.y / glm::length(s.sunFrom));
  return s.albedo / kPi * irradiance;
}

class IntegratorAnalytic : public ::testing::TestWithParam<IntegratorKind> {};

void expectAnalytic(const LampScene& lamps, IntegratorKind kind) {
  ParseResult parsed = parsePbrtText(sceneText(lamps), "lamps.pbrt", ".");
  ASSERT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  BuildResult built = buildScene(*parsed.scene);
  ASSERT_TRUE(built.scene) << built.diagnostics.formatAll();
  IntegratorSettings settings;
  settings.kind = kind;
  settings.maxDepth = 1;
  const glm::vec3 origin(0.0f, 3.0f, 3.0f);
  const Estimate e = estimate(*built.scene, origin, glm::normalize(-origin), settings, 64, 1024);
  const double expected = analyticRadiance(lamps);
  EXPECT_NEAR(e.mean, expected, 4.0 * e.standardError + 1e-3 * expected);
}

// Until spheres were sampled by their cone, both integrators gave 0.9947 of the first.
TEST_P(IntegratorAnalytic, SphereLampAlone) {
  expectAnalytic({{{LampShape::Sphere, 0.1, 0.3, 0.8, 100.0}}}, GetParam());
}
TEST_P(IntegratorAnalytic, SphereLampSunAndSky) {
  expectAnalytic({{{LampShape::Sphere, 0.1, 0.3, 0.8, 100.0}}, 0.5, 1.0}, GetParam());
}
TEST_P(IntegratorAnalytic, SkyAroundADarkSphere) {
  expectAnalytic({{{LampShape::Sphere, 0.1, 0.3, 0.8, 0.0}}, 0.5}, GetParam());
}
TEST_P(IntegratorAnalytic, SmallBrightSphereAndWeakSun) {
  expectAnalytic({{{LampShape::Sphere, 0.01, 0.5, 1.5, 3000.0}}, 0.0, 0.2, {1, 2, 1}}, GetParam());
}
// Several lights: the path tracer picks one per bounce, the direct-lighting integrator takes
// every one.
TEST_P(IntegratorAnalytic, ThreeSmallSpheresAWeakSunAndSky) {
  expectAnalytic({{{LampShape::Sphere, 0.02, -0.4, 0.5, 400.0},
                   {LampShape::Sphere, 0.02, 0.0, 0.6, 400.0},
                   {LampShape::Sphere, 0.02, 0.4, 0.5, 400.0}},
                  0.05,
                  0.3,
                  {-1, 2, 2}},
                 GetParam());
}
// The path tracer's choice of light then varies from point to point (LightSelection).
TEST_P(IntegratorAnalytic, NineTinyLampsBesideASunAndSky) {
  LampScene scene{{}, 0.3, 1.0, {-1, 2, 2}};
  for (int i = 0; i < 9; ++i) {
    scene.lamps.push_back({LampShape::Sphere, 0.005, -0.4 + 0.1 * i, 0.5 + 0.05 * (i % 3), 2000.0});
  }
  expectAnalytic(scene, GetParam());
}
// A lamp large and near enough that light and BSDF sampling find it about equally often: the
// combination's weights then depend on the probability of the light's choice.
TEST_P(IntegratorAnalytic, BigNearLampASunAndSky) {
  expectAnalytic({{{LampShape::Sphere, 0.4, 0.2, 0.7, 5.0}}, 0.3, 1.0}, GetParam());
}
TEST_P(IntegratorAnalytic, DiskLampAndSky) {
  expectAnalytic({{{LampShape::DiskFacingDown, 0.3, 0.0, 1.0, 20.0}}, 0.5}, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Kinds, IntegratorAnalytic,
                         ::testing::Values(IntegratorKind::Path, IntegratorKind::DirectLighting));

}  // namespace
}  // namespace lenslab::render
