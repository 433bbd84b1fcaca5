// LightSelection: the path tracer's choice of light, against hand-computed irradiance bounds.
#include "render/light_selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace lenslab::render {
namespace {

constexpr float kPiF = 3.14159265f;

Light distant(glm::vec3 irradiance) {
  Light light;
  light.kind = LightKind::Distant;
  light.intensity = irradiance;
  return light;
}

Light sky(glm::vec3 radiance) {
  Light light;
  light.kind = LightKind::Infinite;
  light.intensity = radiance;
  return light;
}

Light sphereLamp(glm::vec3 center, float radius, glm::vec3 radiance) {
  auto emitter = std::make_shared<Emitter>();
  emitter->isQuadric = true;
  emitter->isSphere = true;
  emitter->sphereCenter = glm::dvec3(center);
  emitter->sphereRadius = radius;
  emitter->area = 4.0f * kPiF * radius * radius;
  Light light;
  light.kind = LightKind::Area;
  light.intensity = radiance;
  light.emitter = std::move(emitter);
  return light;
}

Light pointLight(glm::vec3 position, glm::vec3 intensity) {
  Light light;
  light.kind = LightKind::Point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

// The default scene's lights: its sun, its sky and its nine lamps (scenes/default.pbrt).
std::vector<Light> defaultSceneLights() {
  std::vector<Light> lights = {distant(glm::vec3(4.0f, 3.8f, 3.4f)),
                               sky(glm::vec3(0.75f, 0.8f, 0.9f))};
  for (int i = 0; i < 9; ++i) {
    lights.push_back(sphereLamp({-0.16f + 0.04f * i, 0.65f, 3.05f}, 0.002f, {30.0f, 24.0f, 15.0f}));
  }
  return lights;
}

// The probability of light `index` at `point`.
float probabilityAt(const LightSelection& selection, glm::vec3 point, int index) {
  LightSelection::AtPoint choice;
  selection.evaluate(point, choice);
  return choice.probability(index);
}

// What the choice of each light should be: 0.1 / N plus 0.9 of its share of the bounds.
std::vector<double> expectedProbabilities(const std::vector<double>& bounds) {
  double total = 0.0;
  for (double b : bounds) total += b;
  std::vector<double> p;
  for (double b : bounds) p.push_back(0.1 / bounds.size() + 0.9 * b / total);
  return p;
}

TEST(LightSelection, ProbabilitiesFollowHandComputedIrradianceBounds) {
  // Grey lights: luminance = the channel value (the Rec. 709 weights sum to 1).
  const std::vector<Light> lights = {
      distant(glm::vec3(3.0f)),                                 // E = 3
      sky(glm::vec3(0.5f)),                                     // pi * 0.5
      sphereLamp({0.0f, 2.0f, 0.0f}, 0.1f, glm::vec3(100.0f)),  // 100 * pi 0.01 / 4
      sphereLamp({0.0f, 0.0f, 4.0f}, 0.1f, glm::vec3(100.0f)),  // 100 * pi 0.01 / 16
      pointLight({3.0f, 4.0f, 0.0f}, glm::vec3(50.0f)),         // 50 / 25
  };
  const LightSelection selection(lights);
  const std::vector<double> bounds = {3.0, M_PI * 0.5, 100.0 * M_PI * 0.01 / 4.0,
                                      100.0 * M_PI * 0.01 / 16.0, 2.0};
  const std::vector<double> expected = expectedProbabilities(bounds);
  const glm::vec3 point(0.0f);
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) {
    const float p = probabilityAt(selection, point, i);
    EXPECT_NEAR(p, expected[static_cast<std::size_t>(i)], 1e-6) << "light " << i;
    EXPECT_GE(p, 0.1 / 5.0 - 1e-7);
    sum += p;
  }
  EXPECT_NEAR(sum, 1.0, 1e-6);
}

TEST(LightSelection, AnAreaLightsBoundStopsAtPiL) {
  // A closed box of side 2 around the origin as a mesh emitter: area 24, bounding radius sqrt 3.
  // From its centre, 2 L 24 / 3 = 16 L would exceed what any emitter can give, pi L (a whole
  // sphere of directions' worth of projected solid angle is pi), and is capped there. (The
  // triangles only give the bounds: two spanning the box's diagonal.)
  auto emitter = std::make_shared<Emitter>();
  emitter->triangles = {{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f},   {1.0f, -1.0f, 1.0f},
                        {-1.0f, -1.0f, -1.0f}, {-1.0f, 1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}};
  emitter->area = 24.0f;
  Light box;
  box.kind = LightKind::Area;
  box.intensity = glm::vec3(2.0f);
  box.emitter = std::move(emitter);
  const LightSelection selection({distant(glm::vec3(1.0f)), box});
  const std::vector<double> expected = expectedProbabilities({1.0, M_PI * 2.0});
  EXPECT_NEAR(probabilityAt(selection, {0.0f, 0.0f, 0.0f}, 1), expected[1], 1e-6);
  // Far away the bound is 2 * 24 / d^2: at 100, 0.0048.
  const std::vector<double> far = expectedProbabilities({1.0, 2.0 * 24.0 / (100.0 * 100.0)});
  EXPECT_NEAR(probabilityAt(selection, {100.0f, 0.0f, 0.0f}, 1), far[1], 1e-6);
}

TEST(LightSelection, ChooseFollowsProbabilityAtEveryPoint) {
  const std::vector<Light> lights = defaultSceneLights();
  const LightSelection selection(lights);
  for (const glm::vec3 point :
       {glm::vec3(0.0f), glm::vec3(0.0f, 0.6f, 3.0f), glm::vec3(-0.1f, 0.65f, 3.05f)}) {
    LightSelection::AtPoint choice;
    selection.evaluate(point, choice);
    // u on a fine grid: the share of it that picks each light is that light's probability.
    constexpr int kSteps = 200000;
    std::vector<int> picked(lights.size(), 0);
    for (int step = 0; step < kSteps; ++step) {
      float p = 0.0f;
      const int index = choice.choose((step + 0.5f) / kSteps, p);
      ASSERT_GE(index, 0);
      ASSERT_LT(index, static_cast<int>(lights.size()));
      EXPECT_FLOAT_EQ(p, choice.probability(index));
      ++picked[static_cast<std::size_t>(index)];
    }
    for (std::size_t i = 0; i < lights.size(); ++i) {
      EXPECT_NEAR(static_cast<double>(picked[i]) / kSteps, choice.probability(static_cast<int>(i)),
                  2.0 / kSteps)
          << "light " << i;
    }
  }
}

TEST(LightSelection, TinyLampsTakeLittleOfASunlitScenesChoice) {
  // The default scene's lights, seen from the ground 3 m from the lamps.
  const std::vector<Light> lights = defaultSceneLights();
  const LightSelection selection(lights);
  const glm::vec3 ground(0.0f, 0.0f, 0.0f);
  // By hand: luminances 3.8137 (sun), 0.79659 (sky, times pi), 24.627 (lamps); a lamp's bound is
  // 24.627 pi (0.002)^2 / d^2 with d^2 = x^2 + 0.65^2 + 3.05^2.
  auto y = [](double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; };
  std::vector<double> bounds = {y(4.0, 3.8, 3.4), M_PI * y(0.75, 0.8, 0.9)};
  for (int i = 0; i < 9; ++i) {
    const double x = -0.16 + 0.04 * i;
    bounds.push_back(y(30, 24, 15) * M_PI * 0.002 * 0.002 / (x * x + 0.65 * 0.65 + 3.05 * 3.05));
  }
  const std::vector<double> expected = expectedProbabilities(bounds);
  double lamps = 0.0, expectedLamps = 0.0;
  for (int i = 2; i < 11; ++i) {
    lamps += probabilityAt(selection, ground, i);
    expectedLamps += expected[static_cast<std::size_t>(i)];
  }
  // 0.0819: the uniform tenth and 4e-5; a uniform choice gave the lamps 9 / 11.
  EXPECT_NEAR(lamps, expectedLamps, 1e-5);
  EXPECT_LT(lamps, 0.083);
  EXPECT_NEAR(probabilityAt(selection, ground, 0), expected[0], 1e-5);  // the sun: 0.552
}

TEST(LightSelection, WithoutAnyBoundEveryLightIsEquallyLikely) {
  const std::vector<Light> lights = {distant(glm::vec3(0.0f)), sky(glm::vec3(0.0f)),
                                     pointLight({1.0f, 0.0f, 0.0f}, glm::vec3(0.0f))};
  const LightSelection selection(lights);
  for (int i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(probabilityAt(selection, glm::vec3(0.0f), i), 1.0f / 3.0f);
  }
}

TEST(LightSelection, APointLightAtThePointItselfKeepsTheProbabilitiesFinite) {
  const std::vector<Light> lights = {distant(glm::vec3(1.0f)),
                                     pointLight({0.0f, 0.0f, 0.0f}, glm::vec3(1e6f))};
  const LightSelection selection(lights);
  const float sun = probabilityAt(selection, glm::vec3(0.0f), 0);
  const float point = probabilityAt(selection, glm::vec3(0.0f), 1);
  EXPECT_TRUE(std::isfinite(sun) && std::isfinite(point));
  EXPECT_NEAR(sun + point, 1.0f, 1e-6f);
  EXPECT_NEAR(sun, 0.05f, 1e-6f);  // the uniform share alone
}

}  // namespace
}  // namespace lenslab::render
