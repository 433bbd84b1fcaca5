// The spectral render (issue 23) against independent computations:
// - through a lens without V_d, forced spectral, the picture is the RGB render's within noise;
// - the colour fringe of a small white dot near the field edge, through the flint landscape lens
//   (V_d 23.78): the red and blue centroids in the render against the centroids of the optics
//   library's real rays from the dot, traced in double precision at each wavelength and weighted
//   by each channel's response.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "optics/lens_system.h"
#include "optics/native_lens_file.h"
#include "render/landing_filter.h"
#include "render/realistic_camera.h"
#include "render/spectral_film.h"
#include "render/spectral_mode.h"
#include "render_support.h"
#include "scene_files.h"
#include "support/bundled_glass.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::loadJob;
using render::testing::writeFile;

std::string lensPath(const char* name) {
  return (std::filesystem::path(LENSLAB_SOURCE_DIR) / "lenses" / name).string();
}

std::filesystem::path defaultScene() {
  return std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "default.pbrt";
}

// A scene's camera through the bundled lens `name`, at width x height.
CameraOverrides throughBundledLens(const char* name, int width, int height) {
  CameraOverrides overrides;
  overrides.lensPath = lensPath(name);
  overrides.width = width;
  overrides.height = height;
  return overrides;
}

// The picture below the default scene's lamps (the top 30% of its rows hold them). A lamp's disc
// is seen by few of its pixels' samples, so its noise would swamp what the tests below compare:
// the whole picture's mean through 1%. Nothing in these tests is special to the top rows.
std::shared_ptr<const RenderSnapshot> belowTheLamps(std::shared_ptr<const RenderSnapshot> image) {
  if (!image) return image;
  auto cropped = std::make_shared<RenderSnapshot>();
  const int firstRow = (image->height * 3 + 9) / 10;
  cropped->width = image->width;
  cropped->height = image->height - firstRow;
  cropped->rgb.assign(image->rgb.begin() + 3 * static_cast<std::ptrdiff_t>(firstRow) * image->width,
                      image->rgb.end());
  cropped->samplesPerPixel = image->samplesPerPixel;
  cropped->complete = image->complete;
  return cropped;
}

// Mean over blocks x blocks pixel squares of channel c.
std::vector<double> blockMeans(const RenderSnapshot& image, int block, int c) {
  std::vector<double> out;
  for (int by = 0; by + block <= image.height; by += block) {
    for (int bx = 0; bx + block <= image.width; bx += block) {
      double sum = 0.0;
      for (int y = by; y < by + block; ++y)
        for (int x = bx; x < bx + block; ++x)
          sum += image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x) + c];
      out.push_back(sum / (block * block));
    }
  }
  return out;
}

TEST(SpectralRender, ALensWithACatalogueGlassRendersSpectrallyUnlessItsGlassFallsShort) {
  // The spectral batch trace follows a catalogue glass by a series fitted to its formula
  // (optics::LensSystem::spectralTraceProblem); a glass whose formula stops short of 780 nm (CDGM's
  // end at 706.5 nm) is never extrapolated: that lens renders in RGB in every mode.
  auto singlet = [](const std::string& glass) {
    const optics::LensFileResult file = optics::parseNativeLensText(
        "lenslab-lens 1\n"
        "surface radius 50 thickness 5 glass " +
            glass +
            " diameter 20\n"
            "surface radius -50 thickness 1 diameter 20\n"
            "stop thickness 45 diameter 10\n",
        "singlet.lens");
    EXPECT_TRUE(file.ok()) << file.diagnostics.formatAll();
    return optics::LensSystem::build(file.lens->prescription);
  };
  const auto bk7 = singlet("N-BK7");
  ASSERT_TRUE(bk7.ok());
  ASSERT_TRUE(bk7.system->disperses());
  EXPECT_TRUE(rendersSpectrally(SpectralMode::Auto, *bk7.system));
  EXPECT_TRUE(rendersSpectrally(SpectralMode::On, *bk7.system));
  EXPECT_FALSE(rendersSpectrally(SpectralMode::Off, *bk7.system));
  const auto cdgm = singlet("H-LAK67 maker CDGM");
  ASSERT_TRUE(cdgm.ok());
  for (SpectralMode mode : {SpectralMode::On, SpectralMode::Auto, SpectralMode::Off})
    EXPECT_FALSE(rendersSpectrally(mode, *cdgm.system)) << toString(mode);
}

TEST(SpectralRender, WithoutDispersionItIsTheRgbRenderWithinNoise) {
  const auto scene = defaultScene();
  CameraOverrides overrides;
  // The course's double-Gauss 50 mm, as pbrt has it: no V_d (the bundled one carries the
  // course table's).
  overrides.lensPath =
      std::filesystem::path(LENSLAB_SOURCE_DIR) / "../shared/reference/lenses/dgauss.50mm.dat";
  overrides.width = 120;
  overrides.height = 80;
  overrides.falloff.spectral = SpectralMode::Off;
  RenderJob rgbJob = loadJob(scene, 32, overrides);
  overrides.falloff.spectral = SpectralMode::On;
  RenderJob spectralJob = loadJob(scene, 32, overrides);
  overrides.falloff.spectral = SpectralMode::Auto;
  RenderJob autoJob = loadJob(scene, 1, overrides);
  ASSERT_TRUE(rgbJob.camera && spectralJob.camera && autoJob.camera);
  EXPECT_FALSE(rgbJob.camera->spectral());
  EXPECT_TRUE(spectralJob.camera->spectral());
  EXPECT_FALSE(autoJob.camera->spectral()) << "the course's double-Gauss 50 mm file has no V_d";
  rgbJob.settings.seed = 1;
  const auto rgb = belowTheLamps(renderToCompletion(rgbJob));
  rgbJob.settings.seed = 2;
  const auto rgbAgain = belowTheLamps(renderToCompletion(rgbJob));
  spectralJob.settings.seed = 2;
  const auto spectral = belowTheLamps(renderToCompletion(spectralJob));
  ASSERT_TRUE(rgb && rgbAgain && spectral);
  for (int c = 0; c < 3; ++c) {
    const auto a = blockMeans(*rgb, 8, c), b = blockMeans(*rgbAgain, 8, c),
               s = blockMeans(*spectral, 8, c);
    double meanA = 0, meanDiff = 0, rgbNoise = 0, spectralNoise = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      meanA += a[k];
      meanDiff += s[k] - a[k];
      rgbNoise += (b[k] - a[k]) * (b[k] - a[k]);
      spectralNoise += (s[k] - a[k]) * (s[k] - a[k]);
    }
    const double n = static_cast<double>(a.size());
    meanA /= n;
    meanDiff /= n;
    rgbNoise = std::sqrt(rgbNoise / n);
    spectralNoise = std::sqrt(spectralNoise / n);
    // No bias: the image means agree to within 4 standard errors of the block differences, and
    // within 1%. Block by block the spectral picture differs from an RGB one by noise alone, and
    // little more of it: four wavelengths per sample (the lens does not disperse: all on the
    // same ray) leave little colour noise (measured 0.99 to 1.14 times the block noise of two
    // RGB renders at 32 spp; one wavelength per sample measured 1.4 to 2.7), bounded at 1.3.
    // The error against the truth, spectral over RGB: |S - A|^2 = e_S^2 + e_A^2, |B - A|^2 = 2
    // e_A^2.
    const double ratio = spectralNoise / rgbNoise;
    std::printf("channel %d: block noise spectral/rgb %.3f, error ratio %.3f\n", c, ratio,
                std::sqrt(std::max(0.0, 2.0 * ratio * ratio - 1.0)));
    EXPECT_LT(std::abs(meanDiff), 4.0 * spectralNoise / std::sqrt(n)) << "channel " << c;
    EXPECT_LT(std::abs(meanDiff), 0.01 * meanA) << "channel " << c;
    EXPECT_LT(spectralNoise, 1.3 * rgbNoise) << "channel " << c;
    EXPECT_GT(spectralNoise, 0.0);
  }
}

double rmsDifference(const RenderSnapshot& a, const RenderSnapshot& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i)
    sum += (a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
  return std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

// Hero wavelengths (four per camera sample, RealisticCamera::heroWavelengthWeights) through the
// bundled double-Gauss 50 mm, which carries the course table's V_d, against the simple estimator
// of one wavelength per path:
// - no bias: at 256 samples per pixel the two converge to the same picture, 8 x 8 block by
//   block, within their noise (up to the hero estimator's other wavelengths being shared across
//   pixel edges, render/landing_filter.h, which moves light between blocks only at their edges
//   and by a quarter pixel at most) (and the hero estimator sends other wavelengths to other pixels
//   wherever the lens's colour moves them, which this checks too: a wrong pixel or weight
//   shifts or dims the blocks);
// - less colour noise: at 16 samples per pixel, the error against the converged picture is
//   under 0.6 of one wavelength per path's (measured 0.37), and at most 1.27 times the RGB
//   render's against its own converged picture (issue 23 asks for 1.5; bench/spectral-error.sh).
//   Measured 1.22 with the other wavelengths shared across the pixel edges near where they land
//   (render/landing_filter.h); 1.32 when each goes wholly to the pixel it lands in.
// A camera as another, but saying it reads a sample's wavelengths before its ray is traced: the
// renderer then draws them all up front, as it does for a lens that disperses.
class EveryWavelengthFirst final : public Camera {
 public:
  explicit EveryWavelengthFirst(std::shared_ptr<const Camera> inner)
      : Camera(inner->width(), inner->height()), inner_(std::move(inner)) {}
  bool generateRay(glm::vec2 raster, glm::vec2 lens, CameraRay& ray) const override {
    return inner_->generateRay(raster, lens, ray);
  }
  void generateRays(std::size_t count, const glm::vec2* raster, const glm::vec2* lens,
                    CameraRay* rays, std::uint8_t* passed,
                    const SampleWavelengths* wavelengths) const override {
    inner_->generateRays(count, raster, lens, rays, passed, wavelengths);
  }
  bool maySeeScene(glm::vec2 a, glm::vec2 b) const override { return inner_->maySeeScene(a, b); }
  void prepare() const override { inner_->prepare(); }
  int lensPointsPerSample() const override { return inner_->lensPointsPerSample(); }
  bool spectral() const override { return inner_->spectral(); }
  bool readsWavelengths() const override { return true; }
  float pixelSpreadRadians() const override { return inner_->pixelSpreadRadians(); }

 private:
  std::shared_ptr<const Camera> inner_;
};

// Through a lens that does not disperse the camera reads no wavelength, and the renderer draws a
// sample's wavelengths after its ray, only if it left the lens (most samples of the
// course's scenes do not). The picture is the one with every wavelength drawn first, bit for
// bit; a lens that disperses reads them all.
TEST(SpectralRender, DrawingTheWavelengthsAfterTheRayChangesNothing) {
  CameraOverrides overrides;
  overrides.lensPath =
      std::filesystem::path(LENSLAB_SOURCE_DIR) / "../shared/reference/lenses/dgauss.50mm.dat";
  overrides.width = 90;
  overrides.height = 60;
  overrides.falloff.spectral = SpectralMode::On;
  RenderJob job = loadJob(defaultScene(), 8, overrides);
  ASSERT_TRUE(job.camera && job.camera->spectral());
  EXPECT_FALSE(job.camera->readsWavelengths());
  RenderJob eager = job;
  eager.camera = std::make_shared<EveryWavelengthFirst>(job.camera);
  const auto after = renderToCompletion(job);
  const auto first = renderToCompletion(eager);
  ASSERT_TRUE(after && first);
  double sum = 0.0;
  for (float v : after->rgb) sum += v;
  EXPECT_GT(sum, 0.0);
  EXPECT_EQ(after->rgb, first->rgb);

  RenderJob dispersive = loadJob(defaultScene(), 1, throughBundledLens("dgauss-50mm.dat", 30, 20));
  ASSERT_TRUE(dispersive.camera && dispersive.camera->spectral());
  EXPECT_TRUE(dispersive.camera->readsWavelengths());
}

// A spectral camera that sends every sample's second wavelength, and only it, to one pixel at
// one place in it (as a lens that disperses would report: SampleWavelengths::pixels and
// landing), so that the renderer's deposits can be read off the picture exactly.
class LandsEverythingAt final : public Camera {
 public:
  LandsEverythingAt(int width, int height, glm::ivec2 pixel, glm::vec2 fraction)
      : Camera(width, height), pixel_(pixel), fraction_(fraction) {}
  bool generateRay(glm::vec2, glm::vec2, CameraRay& ray) const override {
    ray = CameraRay{};
    return true;
  }
  void generateRays(std::size_t count, const glm::vec2*, const glm::vec2*, CameraRay* rays,
                    std::uint8_t* passed, const SampleWavelengths* wavelengths) const override {
    const auto k = static_cast<std::size_t>(wavelengths->perSample);
    for (std::size_t i = 0; i < count; ++i) {
      rays[i] = CameraRay{};
      passed[i] = 1;
      for (std::size_t j = 0; j < k; ++j) {
        wavelengths->weights[i * k + j] = j == 1 ? 1.0f : 0.0f;
        wavelengths->pixels[i * k + j] =
            j == 0 ? SampleWavelengths::kSamplePixel : pixel_.y * width() + pixel_.x;
        wavelengths->landing[2 * (i * k + j)] = fraction_.x;
        wavelengths->landing[2 * (i * k + j) + 1] = fraction_.y;
      }
    }
  }
  bool spectral() const override { return true; }
  bool readsWavelengths() const override { return true; }
  float pixelSpreadRadians() const override { return 0.0f; }

 private:
  glm::ivec2 pixel_;
  glm::vec2 fraction_;
};

// The renderer shares a wavelength that lands near a pixel's edge with the neighbour across it
// (render/landing_filter.h), by the landing place the camera gives: along x by its x, along y by
// its y, nothing across the image's edge, through and beyond the tiles' edges (16 pixels).
TEST(SpectralRender, ALandedWavelengthIsSharedAcrossTheNearPixelEdges) {
  const auto directory = lenslab::testing::makeTestDirectory("spectral-landing");
  const auto scene =
      writeFile(directory / "sky.pbrt",
                "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
                "Film \"image\" \"integer xresolution\" [40] \"integer yresolution\" [24]\n"
                "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                "Translate 0 0 -100\nShape \"sphere\" \"float radius\" [1]\nWorldEnd\n");
  constexpr int kWidth = 40, kHeight = 24;
  struct Case {
    glm::ivec2 pixel;
    glm::vec2 fraction;
    std::vector<std::pair<glm::ivec2, double>> expected;  // pixel, share of the light
  };
  const double a = kLandingRampPx;
  // The neighbour's share 0.1 and 0.05 from an edge: 0.3 and 0.4.
  const double lowX = 0.5 - 0.1 / (2 * a), highY = 0.5 - 0.05 / (2 * a);
  const std::vector<Case> cases = {
      // Inside, near its left (x 0.1) and lower-row (y 0.95) edges, across a tile's edge (x 16).
      {{16, 10},
       {0.1f, 0.95f},
       {{{16, 10}, (1 - lowX) * (1 - highY)},
        {{15, 10}, lowX * (1 - highY)},
        {{16, 11}, (1 - lowX) * highY},
        {{15, 11}, lowX * highY}}},
      // In the middle of a pixel: all of it there.
      {{7, 5}, {0.5f, 0.5f}, {{{7, 5}, 1.0}}},
      // At the image's left and bottom edges, near those edges: it stays.
      {{0, kHeight - 1}, {0.1f, 0.95f}, {{{0, kHeight - 1}, 1.0}}},
      // At the bottom edge, near the pixel's upper and right edges: shared up and right.
      // (x 0.9: 0.1 from the right edge, as x 0.1 was from the left; y 0.05 from the top.)
      {{20, kHeight - 1},
       {0.9f, 0.05f},
       {{{20, kHeight - 1}, (1 - lowX) * (1 - highY)},
        {{21, kHeight - 1}, lowX * (1 - highY)},
        {{20, kHeight - 2}, (1 - lowX) * highY},
        {{21, kHeight - 2}, lowX * highY}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << "pixel " << c.pixel.x << ", " << c.pixel.y);
    RenderJob job = loadJob(scene, 4);
    ASSERT_TRUE(job.camera && job.scene);
    job.camera = std::make_shared<LandsEverythingAt>(kWidth, kHeight, c.pixel, c.fraction);
    job.settings.wavelengthsPerSample = 4;
    const auto image = renderToCompletion(job);
    ASSERT_TRUE(image);
    ASSERT_EQ(image->width, kWidth);
    auto brightness = [&](glm::ivec2 at) {
      const std::size_t i = 3 * (static_cast<std::size_t>(at.y) * kWidth + at.x);
      return static_cast<double>(image->rgb[i]) + image->rgb[i + 1] + image->rgb[i + 2];
    };
    double total = 0.0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) total += brightness({x, y});
    ASSERT_GT(total, 0.0);
    double listed = 0.0;
    for (const auto& [at, share] : c.expected) {
      EXPECT_NEAR(brightness(at) / total, share, 1e-5) << "at " << at.x << ", " << at.y;
      listed += brightness(at);
    }
    EXPECT_NEAR(listed / total, 1.0, 1e-6) << "light elsewhere than the listed pixels";
  }
}

TEST(SpectralRender, HeroWavelengthsAreUnbiasedAndCutTheColourNoise) {
  const auto scene = defaultScene();
  CameraOverrides overrides = throughBundledLens("dgauss-50mm.dat", 120, 80);
  auto render = [&](SpectralMode mode, int spp, int wavelengths, std::uint32_t seed) {
    overrides.falloff.spectral = mode;
    RenderJob job = loadJob(scene, spp, overrides);
    EXPECT_TRUE(job.camera && job.scene);
    job.settings.wavelengthsPerSample = wavelengths;
    job.settings.seed = seed;
    return belowTheLamps(renderToCompletion(job));
  };
  const auto heroReference = render(SpectralMode::On, 256, 4, 7);
  const auto singleReference = render(SpectralMode::On, 256, 1, 8);
  const auto singleAgain = render(SpectralMode::On, 256, 1, 9);
  ASSERT_TRUE(heroReference && singleReference && singleAgain);
  for (int c = 0; c < 3; ++c) {
    const auto a = blockMeans(*heroReference, 8, c), b = blockMeans(*singleReference, 8, c),
               b2 = blockMeans(*singleAgain, 8, c);
    // Block by block: hero - single has the variance v_hero + v_single, two single pictures'
    // difference 2 v_single; a wavelength counted in a wrong pixel, or a wrong weight, adds its
    // bias to the first. The hero picture is the less noisy (v_hero about 0.2 v_single, below),
    // so the first should be about 0.6 of the second; bounded at 1.
    double heroSingle = 0.0, singleSingle = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      heroSingle += (a[k] - b[k]) * (a[k] - b[k]);
      singleSingle += (b2[k] - b[k]) * (b2[k] - b[k]);
    }
    std::printf("channel %d: block differences, hero - single %.3g, single - single %.3g\n", c,
                heroSingle, singleSingle);
    EXPECT_LT(heroSingle, singleSingle) << "channel " << c;
    // The single-wavelength picture's block noise dominates; its size from the blocks' spread
    // about the hero picture (a bias would add to it, and the check below catches that).
    double meanA = 0, meanDiff = 0, spread = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      meanA += a[k];
      meanDiff += b[k] - a[k];
      spread += (b[k] - a[k]) * (b[k] - a[k]);
    }
    const double n = static_cast<double>(a.size());
    meanA /= n;
    meanDiff /= n;
    spread = std::sqrt(spread / n);
    std::printf("channel %d: image mean %.5f, hero - single %.6f, block spread %.6f\n", c, meanA,
                meanDiff, spread);
    EXPECT_LT(std::abs(meanDiff), 4.0 * spread / std::sqrt(n)) << "channel " << c;
    EXPECT_LT(std::abs(meanDiff), 0.005 * meanA) << "channel " << c;
  }
  const auto hero = render(SpectralMode::On, 16, 4, 1);
  const auto single = render(SpectralMode::On, 16, 1, 1);
  const auto rgb = render(SpectralMode::Off, 16, 4, 1);
  const auto rgbReference = render(SpectralMode::Off, 256, 4, 7);
  ASSERT_TRUE(hero && single && rgb && rgbReference);
  const double heroError = rmsDifference(*hero, *heroReference);
  const double singleError = rmsDifference(*single, *heroReference);
  const double rgbError = rmsDifference(*rgb, *rgbReference);
  std::printf("RMS error at 16 spp: hero %.5f, one wavelength %.5f, RGB %.5f\n", heroError,
              singleError, rgbError);
  EXPECT_LT(heroError, 0.6 * singleError);
  EXPECT_LT(heroError, 1.27 * rgbError);
}

// The viewer's coarse first look of a spectral render through a lens that disperses: one sample
// per 4 x 4 block, whose other wavelengths land in the block's other pixels (or beyond). The look
// sums each block, so it is as bright as the first full pass (within its noise); a look of the
// centre pixels alone would lose the light those wavelengths carry away (most of three quarters,
// through the flint singlet).
// Through a lens that disperses, the other wavelengths' light lands in other pixels, often in
// another tile: the renderer collects what lands in and next to a tile in an apron and hands the
// rest to the wave's splat image. Where tiles end must not matter: tiles of 16 pixels on two
// threads and of 5 on one (different borders, a different order of the additions) give the same
// picture up to float rounding.
TEST(SpectralRender, WhereTilesEndDoesNotMoveTheLandedLight) {
  RenderJob job =
      loadJob(defaultScene(), 4, throughBundledLens("flint-landscape-50mm.dat", 90, 60));
  ASSERT_TRUE(job.camera && job.scene);
  ASSERT_TRUE(job.camera->readsWavelengths());
  job.settings.tileSize = 16;
  job.settings.threads = 2;
  RenderJob small = job;
  small.settings.tileSize = 5;
  small.settings.threads = 1;
  const auto a = renderToCompletion(job);
  const auto b = renderToCompletion(small);
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->rgb.size(), b->rgb.size());
  double sumA = 0.0, sumB = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < a->rgb.size(); ++i) {
    sumA += a->rgb[i];
    sumB += b->rgb[i];
    const double scale = std::abs(a->rgb[i]) + std::abs(b->rgb[i]) + 1e-3;
    worst = std::max(worst, std::abs(static_cast<double>(a->rgb[i]) - b->rgb[i]) / scale);
  }
  std::printf("largest relative difference %.3g, sums %.6f and %.6f\n", worst, sumA, sumB);
  EXPECT_GT(sumA, 0.0);
  EXPECT_LT(worst, 1e-4);
  EXPECT_NEAR(sumA, sumB, 1e-6 * sumA);
}

TEST(SpectralRender, TheCoarseLookKeepsTheLightOtherWavelengthsCarryToOtherPixels) {
  RenderJob job =
      loadJob(defaultScene(), 1, throughBundledLens("flint-landscape-50mm.dat", 240, 160));
  ASSERT_TRUE(job.camera && job.scene);
  ASSERT_TRUE(job.camera->spectral());
  job.settings.coarseDivisor = 4;
  const auto published = render::testing::publishedSnapshots(job, 60.0);
  ASSERT_TRUE(published);
  const auto& seen = *published;
  ASSERT_EQ(seen.size(), 2u);
  ASSERT_TRUE(seen[0]->coarse);
  auto mean = [](const RenderSnapshot& image) {
    double sum = 0.0;
    for (float v : image.rgb) sum += v;
    return sum / static_cast<double>(image.rgb.size());
  };
  const double coarse = mean(*seen[0]), full = mean(*seen[1]);
  std::printf("coarse look mean %.5f, first pass mean %.5f\n", coarse, full);
  EXPECT_NEAR(coarse, full, 0.1 * full);
}

// Where the light of the dot lands on the film at one wavelength: the mean of the real rays from
// the dot's centre spread uniformly over the stop (the lens's first surface, so the entrance
// pupil), and the share of them that pass.
struct Landing {
  double xMm = 0.0;
  double passing = 0.0;
};
Landing landingAt(const optics::LensSystem& lens, glm::dvec3 objectMm, double wavelengthNm) {
  const auto atWavelength = lens.withWavelength(wavelengthNm);
  const double stopRadius = 0.5 * lens.stopDiameterMm();
  const double stopZ = lens.surfaces()[lens.stopIndex()].vertexZMm;
  Landing out;
  double sum = 0.0;
  int passed = 0, traced = 0;
  const int rings = 40, perRing = 64;
  for (int i = 0; i < rings; ++i) {
    const double r = stopRadius * std::sqrt((i + 0.5) / rings);  // equal areas
    for (int j = 0; j < perRing; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5 * (i % 2)) / perRing;
      const glm::dvec3 target{r * std::cos(phi), r * std::sin(phi), stopZ};
      ++traced;
      const auto leaving =
          atWavelength->traceFromScene({objectMm, glm::normalize(target - objectMm)});
      if (!leaving) continue;
      ++passed;
      // Where it meets the film, z = 0.
      sum += leaving->origin.x - leaving->origin.z / leaving->direction.z * leaving->direction.x;
    }
  }
  out.passing = static_cast<double>(passed) / traced;
  out.xMm = passed > 0 ? sum / passed : 0.0;
  return out;
}

TEST(SpectralRender, WhiteDotFringeMatchesTheRealRaysLateralColour) {
  const auto directory = lenslab::testing::makeTestDirectory("spectral-fringe");
  const int width = 300, height = 200;
  const double diagonalMm = 43.27;
  const double dotX = 0.55, dotZ = 2.0;  // metres: about 15 degrees off axis
  const auto path = writeFile(
      directory / "dot.pbrt",
      "LookAt 0 0 0  0 0 1  0 1 0\n"
      "Camera \"realistic\" \"string lensfile\" \"" +
          lensPath("flint-landscape-50mm.dat") +
          "\" \"float aperturediameter\" [4] \"float focusdistance\" [2]\n"
          "Film \"image\" \"integer xresolution\" [" +
          std::to_string(width) + "] \"integer yresolution\" [" + std::to_string(height) +
          "] \"float diagonal\" [43.27]\n"
          "Integrator \"path\" \"integer maxdepth\" [1]\n"
          "WorldBegin\nAttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [100 100 100]\n"
          "  Translate " +
          std::to_string(dotX) + " 0 " + std::to_string(dotZ) +
          "\n  Shape \"sphere\" \"float radius\" [0.003]\nAttributeEnd\nWorldEnd\n");
  RenderJob job = loadJob(path, 256);
  ASSERT_TRUE(job.camera && job.scene);
  ASSERT_TRUE(job.camera->spectral()) << "the flint lens has V_d: auto is spectral";
  const auto& camera = dynamic_cast<const RealisticCamera&>(*job.camera);
  const optics::LensSystem& lens = camera.lens();

  // The dot's centre in the lens frame (pbrt-v3: film at the camera origin, millimetres), and the
  // raster column of a film x (RealisticCamera's mapping: raster x runs toward -x on the film).
  const ParseResult parsed = parsePbrtFile(path);
  ASSERT_TRUE(parsed.scene);
  const glm::dvec3 objectMm =
      framingOf(*parsed.scene).lensFrame(lens).lensMmFromCamera({dotX, 0.0, dotZ});
  const double filmWidthMm = diagonalMm * width / std::hypot(double(width), double(height));
  auto rasterX = [&](double filmXMm) {
    return (0.5 * filmWidthMm - filmXMm) * width / filmWidthMm;
  };

  // Expected centroid of each channel: the real rays' landing at each wavelength, weighted by
  // what the film makes of white light there (the channel's response to a line times white's
  // spectrum) and by the share that passes. 1 nm steps over the spectral range.
  const SpectralFilm& film = SpectralFilm::instance();
  double expected[3] = {}, weightSum[3] = {};
  for (double nm = 380.5; nm < 780.0; nm += 1.0) {
    const Landing landing = landingAt(lens, objectMm, nm);
    const glm::dvec3 response = film.srgbOfLine(nm);
    const glm::dvec3 basis = film.basis(nm);
    const double white = basis.x + basis.y + basis.z;
    for (int c = 0; c < 3; ++c) {
      const double w = response[c] * white * landing.passing;
      expected[c] += w * rasterX(landing.xMm);
      weightSum[c] += w;
    }
  }
  for (int c = 0; c < 3; ++c) expected[c] /= weightSum[c];
  const double expectedSeparation = expected[0] - expected[2];
  // The lens's lateral colour between F and C, for scale: the fringe is pixels wide.
  EXPECT_GT(std::abs(expectedSeparation), 1.0) << "red " << expected[0] << " blue " << expected[2];

  const auto image = renderToCompletion(job);
  ASSERT_TRUE(image);
  // Signed centroids (a channel is negative where the film's response to a line is) over a
  // window around the expected dot.
  const int cx = static_cast<int>(std::lround(expected[1])), cy = height / 2;
  double measured[3] = {};
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, moment = 0.0;
    for (int y = cy - 20; y < cy + 20; ++y) {
      for (int x = cx - 25; x < cx + 25; ++x) {
        const double v = image->rgb[3 * (static_cast<std::size_t>(y) * width + x) + c];
        sum += v;
        moment += v * (x + 0.5);
      }
    }
    ASSERT_GT(sum, 0.0) << c;
    measured[c] = moment / sum;
  }
  const double measuredSeparation = measured[0] - measured[2];
  EXPECT_NEAR(measuredSeparation, expectedSeparation, 0.1 * std::abs(expectedSeparation))
      << "red " << measured[0] << " (expected " << expected[0] << "), blue " << measured[2]
      << " (expected " << expected[2] << ")";
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(measured[c], expected[c], 0.5) << c;
}

}  // namespace
}  // namespace lenslab::render
