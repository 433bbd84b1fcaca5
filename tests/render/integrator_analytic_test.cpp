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

enum class LampShape { Sphere, DiskFacingDown, CylinderAlongX };

// A lamp centred at (x, y, 0); a disk faces down (-y); a cylinder (open, emitting outward) lies
// along x, with length kCylinderLength.
struct Lamp {
  LampShape shape;
  double radius, x, y, radiance;
};
constexpr double kCylinderLength = 0.6;

struct LampScene {
  std::vector<Lamp> lamps;
  double skyRadiance = 0.0, sunRadiance = 0.0;
  glm::dvec3 sunFrom{0.0, 1.0, 1.0};
  double albedo = 0.5;
};

std::string shapeText(const Lamp& lamp) {
  const std::string radius = "\"float radius\" [" + std::to_string(lamp.radius) + "]";
  switch (lamp.shape) {
    case LampShape::Sphere:
      return " Shape \"sphere\" " + radius;
    case LampShape::DiskFacingDown:
      return " Rotate 90 1 0 0 Shape \"disk\" " + radius;
    case LampShape::CylinderAlongX:
      return " Rotate 90 0 1 0 Shape \"cylinder\" " + radius + " \"float zmin\" [" +
             std::to_string(-0.5 * kCylinderLength) + "] \"float zmax\" [" +
             std::to_string(0.5 * kCylinderLength) + "]";
  }
  return "";
}

// The projected solid angle of a cylinder lamp's lit outside seen from the origin (normal +y),
// by brute force: a 2048 x 2048 grid of cosine-distributed directions (Malley's method: a
// uniform disk lifted to the hemisphere), each cast against the cylinder by this function's own
// ray-cylinder test. A direction counts when its first hit is on the outside (the inside of the
// open tube faces away from the origin and does not emit toward it).
double cylinderProjectedSolidAngle(const Lamp& lamp) {
  constexpr int kGrid = 2048;
  long hits = 0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const double u = (i + 0.5) / kGrid, v = (j + 0.5) / kGrid;
      const double r = std::sqrt(u), phi = 2.0 * kPi * v;
      const glm::dvec3 w(r * std::cos(phi), std::sqrt(std::max(0.0, 1.0 - u)), r * std::sin(phi));
      // (y - cy)^2 + z^2 = R^2 along the ray t w from the origin.
      const double a = w.y * w.y + w.z * w.z;
      const double b = -2.0 * w.y * lamp.y;
      const double c = lamp.y * lamp.y - lamp.radius * lamp.radius;
      const double disc = b * b - 4.0 * a * c;
      if (a <= 0.0 || disc < 0.0) continue;
      for (const double t :
           {(-b - std::sqrt(disc)) / (2.0 * a), (-b + std::sqrt(disc)) / (2.0 * a)}) {
        if (t <= 0.0 || std::abs(t * w.x - lamp.x) > 0.5 * kCylinderLength) continue;
        // The first hit within the tube's length: outside when the outward normal faces the ray.
        const glm::dvec3 normal(0.0, t * w.y - lamp.y, t * w.z);
        if (glm::dot(normal, w) < 0.0) ++hits;
        break;
      }
    }
  }
  return kPi * static_cast<double>(hits) / (static_cast<double>(kGrid) * kGrid);
}

// "[v v v]", an RGB parameter's value.
std::string greyRgb(double v) {
  // (Appended rather than "[" + ...: GCC 12 warns falsely of an overlapping copy there.)
  std::string text = "[";
  for (int channel = 0; channel < 3; ++channel)
    text += std::to_string(v) + (channel < 2 ? " " : "]");
  return text;
}

std::string sceneText(const LampScene& s) {
  auto number = [](double v) { return std::to_string(v); };
  std::string text =
      "LookAt 0 3 3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [10]\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "WorldBegin\n";
  if (s.skyRadiance > 0)
    text += "LightSource \"infinite\" \"rgb L\" " + greyRgb(s.skyRadiance) + "\n";
  if (s.sunRadiance > 0) {
    text += "LightSource \"distant\" \"point from\" [" + number(s.sunFrom.x) + " " +
            number(s.sunFrom.y) + " " + number(s.sunFrom.z) + "] \"point to\" [0 0 0] \"rgb L\" " +
            greyRgb(s.sunRadiance) + "\n";
  }
  for (const Lamp& lamp : s.lamps) {
    text += "AttributeBegin\n AreaLightSource \"diffuse\" \"rgb L\" " + greyRgb(lamp.radiance) +
            "\n Translate " + number(lamp.x) + " " + number(lamp.y) + " 0\n" + shapeText(lamp) +
            "\nAttributeEnd\n";
  }
  text += "AttributeBegin\n Material \"matte\" \"rgb Kd\" " + greyRgb(s.albedo) +
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
    const double projected =
        lamp.shape == LampShape::Sphere           ? kPi * (r2 / d2) * (lamp.y / std::sqrt(d2))
        : lamp.shape == LampShape::DiskFacingDown ? kPi * r2 / (lamp.y * lamp.y + r2)
                                                  : cylinderProjectedSolidAngle(lamp);
    irradiance += (lamp.radiance - s.skyRadiance) * projected;
  }
  irradiance += s.sunRadiance * std::max(0.0, s.sunFrom.y / glm::length(s.sunFrom));
  return s.albedo / kPi * irradiance;
}

// The scene `text` parses and builds to; fails the test (and returns null) on errors.
std::shared_ptr<const Scene> builtScene(const std::string& text, const std::string& name) {
  ParseResult parsed = parsePbrtText(text, name, ".");
  EXPECT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  if (!parsed.scene) return nullptr;
  BuildResult built = buildScene(*parsed.scene);
  EXPECT_TRUE(built.scene) << built.diagnostics.formatAll();
  return built.scene;
}

class IntegratorAnalytic : public ::testing::TestWithParam<IntegratorKind> {};

void expectAnalytic(const LampScene& lamps, IntegratorKind kind) {
  const auto scene = builtScene(sceneText(lamps), "lamps.pbrt");
  ASSERT_TRUE(scene);
  IntegratorSettings settings;
  settings.kind = kind;
  settings.maxDepth = 1;
  const glm::vec3 origin(0.0f, 3.0f, 3.0f);
  const Estimate e = estimate(*scene, origin, glm::normalize(-origin), settings, 64, 1024);
  const double expected = analyticRadiance(lamps);
  std::printf("%s: %.6f of the closed form, standard error %.6f\n",
              kind == IntegratorKind::Path ? "path" : "direct", e.mean / expected,
              e.standardError / expected);
  // 1e-4 for the references' own error (the tube's grid) and float rounding. Each bias fixed so
  // far exceeded it: 5e-3 (a sphere's area samples near its outline), 5e-4 (nine small lamps'
  // shadow rays from the offset origin passing beside them), 3.6e-4 (the tube's area samples).
  EXPECT_NEAR(e.mean, expected, 4.0 * e.standardError + 1e-4 * expected);
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
// A tube: area sampled, as every curved emitter but a whole sphere. Its reference is the brute
// force above (which also shows the sky through the tube's open ends).
TEST_P(IntegratorAnalytic, TubeLampAlone) {
  expectAnalytic({{{LampShape::CylinderAlongX, 0.05, 0.1, 0.7, 50.0}}}, GetParam());
}
TEST_P(IntegratorAnalytic, DiskLampAndSky) {
  expectAnalytic({{{LampShape::DiskFacingDown, 0.3, 0.0, 1.0, 20.0}}, 0.5}, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Kinds, IntegratorAnalytic,
                         ::testing::Values(IntegratorKind::Path, IntegratorKind::DirectLighting));

// Paths of several bounces: a camera inside a sphere that emits Le (both sides) and reflects
// diffusely with albedo rho. By symmetry the radiance is the same everywhere and in every
// direction (the furnace), so each bounce adds rho times the last: a path tracer that follows
// up to m bounces sees Le (1 + rho + ... + rho^m), the infinite sum Le / (1 - rho). The
// direct-lighting integrator stops after one bounce: Le (1 + rho). This also lights every point
// from the inside of a sphere lamp: no cone to sample, the light's own surface all around.
// Measured: 0.99997-0.99998 of the sum at radius 1 m (and 100 m); 0.9984-0.9989 at radius 1 cm,
// where the rays' offset from the surface (offsetOrigin: 2e-5 of the larger of 1 and the point's
// coordinates, so 20 um here) is 2e-3 of the radius: light lost to the offset scales with it.
struct ReflectingFurnace {
  int maxDepth;
  IntegratorKind kind;
};
class IntegratorAnalyticFurnace : public ::testing::TestWithParam<ReflectingFurnace> {};

TEST_P(IntegratorAnalyticFurnace, EachBounceAddsRhoTimesTheLast) {
  constexpr double kEmitted = 1.0, kAlbedo = 0.6;
  const std::string text =
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [10]\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\nWorldBegin\n"
      "AttributeBegin\n Material \"matte\" \"rgb Kd\" " +
      greyRgb(kAlbedo) + "\n AreaLightSource \"diffuse\" \"rgb L\" " + greyRgb(kEmitted) +
      " \"bool twosided\" \"true\"\n Shape \"sphere\" \"float radius\" [1]\nAttributeEnd\n"
      "WorldEnd\n";
  const auto scene = builtScene(text, "furnace.pbrt");
  ASSERT_TRUE(scene);
  const ReflectingFurnace& furnace = GetParam();
  IntegratorSettings settings;
  settings.kind = furnace.kind;
  settings.maxDepth = furnace.maxDepth;
  const int bounces = furnace.kind == IntegratorKind::DirectLighting ? 1 : furnace.maxDepth;
  double expected = 0.0;
  for (int i = 0; i <= bounces; ++i) expected += kEmitted * std::pow(kAlbedo, i);
  // A direction off every axis, from off the centre.
  const glm::vec3 origin(0.1f, -0.2f, 0.15f);
  // (Enough samples that Russian roulette's noise at maxdepth 8 stays under rho^9's share.)
  const Estimate e =
      estimate(*scene, origin, glm::normalize(glm::vec3(0.3f, 0.5f, -0.8f)), settings, 64, 1024);
  std::printf("%s, maxdepth %d: %.6f of Le (1 + ... + rho^%d), standard error %.6f\n",
              furnace.kind == IntegratorKind::Path ? "path" : "direct", furnace.maxDepth,
              e.mean / expected, bounces, e.standardError / expected);
  EXPECT_NEAR(e.mean, expected, 4.0 * e.standardError + 1e-4 * expected);
}

INSTANTIATE_TEST_SUITE_P(
    Depths, IntegratorAnalyticFurnace,
    ::testing::Values(ReflectingFurnace{1, IntegratorKind::Path},
                      ReflectingFurnace{2, IntegratorKind::Path},
                      ReflectingFurnace{3, IntegratorKind::Path},
                      ReflectingFurnace{8, IntegratorKind::Path},  // Russian roulette from 3 on
                      ReflectingFurnace{5, IntegratorKind::DirectLighting}),
    [](const ::testing::TestParamInfo<ReflectingFurnace>& param) {
      return std::string(param.param.kind == IntegratorKind::Path ? "Path" : "Direct") +
             "MaxDepth" + std::to_string(param.param.maxDepth);
    });

// Exporters write Transform matrices with about seven digits: such a rotation is orthogonal only
// to about 1e-6, and the sphere under it must still be sampled by its cone (else area sampling,
// and 0.5% of its light lost as before).
TEST(IntegratorAnalytic, ASphereUnderARotationWrittenWithSevenDigitsIsSampledByItsCone) {
  const std::string text =
      "LookAt 0 3 3  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [10]\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\nWorldBegin\n"
      "AttributeBegin\n AreaLightSource \"diffuse\" \"rgb L\" [100 100 100]\n"
      " Transform [0.7071068 0.7071068 0 0  -0.7071068 0.7071068 0 0  0 0 1 0  0.3 0.8 0 1]\n"
      " Shape \"sphere\" \"float radius\" [0.1]\nAttributeEnd\n"
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]"
      " \"point P\" [-50 0 -50  50 0 -50  50 0 50  -50 0 50]\nWorldEnd\n";
  const auto scene = builtScene(text, "rotated.pbrt");
  ASSERT_TRUE(scene);
  ASSERT_EQ(scene->lights().size(), 1u);
  const Emitter& emitter = *scene->lights()[0].emitter;
  EXPECT_TRUE(emitter.isSphere);
  EXPECT_NEAR(emitter.sphereRadius, 0.1, 1e-6);
  EXPECT_NEAR(emitter.sphereCenter.x, 0.3, 1e-6);
  EXPECT_NEAR(emitter.sphereCenter.y, 0.8, 1e-6);
  // A sphere stretched by 1% is an ellipsoid: area sampling.
  std::string stretched = text;
  stretched.replace(stretched.find("0 0 1 0  0.3"), 7, "0 0 1.01 0");
  const auto stretchedScene = builtScene(stretched, "stretched.pbrt");
  ASSERT_TRUE(stretchedScene);
  EXPECT_FALSE(stretchedScene->lights()[0].emitter->isSphere);
}

}  // namespace
}  // namespace lenslab::render
