// The vignetting demo scene (scenes/vignetting.pbrt, a flat field of uniform radiance) rendered
// through the wide 22 mm: the render's brightness across the film follows the lens's relative
// illumination (optics/relative_illumination.h) within 3% from the axis to the corner, at full
// aperture and stopped down. Two independent computations of the same physics: the renderer's
// Monte Carlo estimate over exit-pupil samples, and the analysis's quadrature over the pass region.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "optics/lens_system.h"
#include "optics/relative_illumination.h"
#include "render_support.h"

namespace lenslab::render {
namespace {

using testing::loadJob;

std::filesystem::path vignettingDemoScene() {
  return std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "vignetting.pbrt";
}

// The scene's text with its lens file made absolute (so that a copy elsewhere still finds it) and
// its iris set to `stopDiameterMm`.
std::string demoSceneWithStop(double stopDiameterMm) {
  std::ifstream in(vignettingDemoScene());
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  const std::string lens =
      (vignettingDemoScene().parent_path() / ".." / "lenses").lexically_normal().string();
  scene = std::regex_replace(scene, std::regex("\"\\.\\./lenses"), "\"" + lens);
  return std::regex_replace(scene, std::regex("\"float aperturediameter\" \\[[0-9.]+\\]"),
                            "\"float aperturediameter\" [" + std::to_string(stopDiameterMm) + "]");
}

struct Ring {
  double rendered = 0.0, analysed = 0.0;
  int pixels = 0;
};

// Renders the demo at 300 x 200 and compares, in rings 1 mm wide on the film, the render's mean
// with the mean of the analysis's `total` over the same pixels (interpolated at each pixel's
// radius), both relative to the centre.
void compareRenderWithAnalysis(const std::filesystem::path& scenePath, double stopDiameterMm) {
  const int width = 300, height = 200, spp = 64;
  CameraOverrides overrides;
  overrides.width = width;
  overrides.height = height;
  RenderJob job = loadJob(scenePath, spp, overrides);
  ASSERT_TRUE(job.camera && job.scene);
  const auto snapshot = renderToCompletion(job);
  ASSERT_TRUE(snapshot);

  // The lens as the scene uses it.
  ParseResult parsed = parsePbrtFile(scenePath);
  ASSERT_TRUE(parsed.scene);
  Diagnostics diagnostics;
  const auto sceneLens = lensOfScene(*parsed.scene, diagnostics);
  ASSERT_TRUE(sceneLens) << diagnostics.formatAll();
  const optics::BuildResult lens = optics::LensSystem::build(sceneLens->prescription);
  ASSERT_TRUE(lens.ok());
  EXPECT_NEAR(lens.system->stopDiameterMm(), stopDiameterMm, 1e-9);

  const double diagonalMm = 43.27, pitchMm = diagonalMm / std::hypot(width, height);
  const auto curve = optics::relativeIllumination(*lens.system, 0.5 * diagonalMm, 256);
  ASSERT_TRUE(curve);
  auto totalAt = [&](double r) {
    const double step = curve->points[1].imageHeightMm;
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(r / step), 254);
    const double t = r / step - i;
    return curve->points[i].total * (1 - t) + curve->points[i + 1].total * t;
  };
  std::vector<Ring> rings(23);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double r =
          std::hypot((x + 0.5 - 0.5 * width) * pitchMm, (y + 0.5 - 0.5 * height) * pitchMm);
      Ring& ring = rings[static_cast<std::size_t>(r)];
      ring.rendered += snapshot->rgb[3 * (y * width + x) + 1];
      ring.analysed += totalAt(r);
      ++ring.pixels;
    }
  }
  // The centre's brightness from the rings within 2 mm, where the fall-off is under 3%: the
  // scale that makes the render a relative illumination.
  const double scale =
      (rings[0].analysed + rings[1].analysed) / (rings[0].rendered + rings[1].rendered);
  int compared = 0;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const Ring& ring = rings[k];
    if (ring.pixels < 50) continue;  // a corner's sliver: too noisy to mean much
    const double rendered = scale * ring.rendered / ring.pixels;
    const double analysed = ring.analysed / ring.pixels;
    std::printf("stop %.3g mm, %2zu-%2zu mm: render %.4f, analysis %.4f\n", stopDiameterMm, k,
                k + 1, rendered, analysed);
    EXPECT_NEAR(rendered, analysed, 0.03 * analysed + 0.002) << "ring " << k << " mm";
    ++compared;
  }
  EXPECT_GE(compared, 20);  // from the axis to the corner
}

TEST(VignettingDemo, RenderFollowsTheRelativeIlluminationAtFullAperture) {
  compareRenderWithAnalysis(vignettingDemoScene(), 8.756);
}

TEST(VignettingDemo, RenderFollowsTheRelativeIlluminationStoppedDown) {
  const auto directory = std::filesystem::temp_directory_path() /
                         ("lenslab-vignetting-demo-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  const auto scene = directory / "vignetting-f8.pbrt";
  std::ofstream(scene) << demoSceneWithStop(2.75);
  compareRenderWithAnalysis(scene, 2.75);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace lenslab::render
