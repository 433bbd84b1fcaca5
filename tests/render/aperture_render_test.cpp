// Shaped stops in renders: a uniform sky through a square or pentagonal stop is as bright as the
// shape's area against the circle's; an out-of-focus point light's bokeh has the blades' corners
// on the axis and turns into a narrower cat's eye toward the corner; pbrt-v4's "string aperture"
// is read, and an unusable one keeps the circle with a warning.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "furnace.h"
#include "render/auto_exposure.h"
#include "render/image_io.h"
#include "render/realistic_camera.h"
#include "render_support.h"
#include "scene_files.h"
#include "support/run_process.h"

namespace lenslab::render {
namespace {

using render::testing::furnaceWorld;
using render::testing::loadJob;
using render::testing::writeFile;

constexpr double kApertureRenderPi = std::numbers::pi;

std::string realisticCamera(double stopMm, double focusDistance, const std::string& aperture) {
  return "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"realistic\" \"string lensfile\" \"dgauss.dat\" "
         "\"float aperturediameter\" [" +
         std::to_string(stopMm) + "] \"float focusdistance\" [" + std::to_string(focusDistance) +
         "]" + (aperture.empty() ? "" : " \"string aperture\" \"" + aperture + "\"") + "\n";
}

// A 16 x 16 furnace scene through directory/dgauss.dat at f/8 (no rim cuts the beam near the
// axis), with pbrt-v4's "string aperture" when not empty.
std::filesystem::path writeFurnaceScene(const std::filesystem::path& directory,
                                        const std::string& aperture) {
  return writeFile(directory / "furnace.pbrt",
                   realisticCamera(6.0, 3.0, aperture) +
                       "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16] "
                       "\"float diagonal\" [10]\nIntegrator \"path\"\n" +
                       furnaceWorld(1.0));
}

// Mean red of the central 6 x 6 pixels of such a 16 x 16 render.
double centralBlockMean(const RenderSnapshot& image) {
  double sum = 0.0;
  for (int y = 5; y < 11; ++y)
    for (int x = 5; x < 11; ++x) sum += image.rgb[3 * static_cast<std::size_t>(y * 16 + x)];
  return sum / 36.0;
}

// The central block's mean of that furnace render.
double centralFurnaceMean(const std::filesystem::path& directory, const std::string& aperture) {
  RenderJob job = loadJob(writeFurnaceScene(directory, aperture), 1024);
  if (!job.camera || !job.scene) return 0.0;
  const auto image = renderToCompletion(job);
  return image ? centralBlockMean(*image) : 0.0;
}

TEST(ApertureRender, UniformSkyBrightnessFollowsTheStopArea) {
  const auto directory = lenslab::testing::makeTestDirectory("aperture-furnace");
  writeFile(directory / "dgauss.dat", render::testing::kDoubleGauss50);
  const double circle = centralFurnaceMean(directory, "");
  ASSERT_GT(circle, 0.0);
  // pbrt-v4's "square" is, in lenslab, the square inscribed in the stop circle: area 2 R^2; its
  // "pentagon" likewise the inscribed regular pentagon, (5/2) sin 72 R^2.
  const double square = centralFurnaceMean(directory, "square");
  const double pentagon = centralFurnaceMean(directory, "pentagon");
  // pbrt-v4's "gaussian", T(r) = exp(-r^2) - exp(-1): its integral over the disk over the
  // circle's area, 1 - 2/e.
  const double gaussian = centralFurnaceMean(directory, "gaussian");
  // 36 pixels x 1024 samples, each passing with p ~ 0.6: 0.4% standard error; the pupil's own
  // distortion at f/8 is far smaller.
  std::printf(
      "uniform sky, centre: square / circle %.4f (2/pi %.4f), pentagon / circle %.4f (%.4f)\n",
      square / circle, 2.0 / kApertureRenderPi, pentagon / circle,
      2.5 * std::sin(0.4 * kApertureRenderPi) / kApertureRenderPi);
  EXPECT_NEAR(square / circle, 2.0 / kApertureRenderPi, 0.015);
  EXPECT_NEAR(pentagon / circle, 2.5 * std::sin(0.4 * kApertureRenderPi) / kApertureRenderPi,
              0.015);
  std::printf("uniform sky, centre: gaussian / circle %.4f (1 - 2/e %.4f)\n", gaussian / circle,
              1.0 - 2.0 / std::numbers::e);
  EXPECT_NEAR(gaussian / circle, 1.0 - 2.0 / std::numbers::e, 0.015);
}

TEST(ApertureRender, SceneApertureNamesAndRefusals) {
  const auto directory = lenslab::testing::makeTestDirectory("aperture-scene");
  writeFile(directory / "dgauss.dat", render::testing::kDoubleGauss50);
  struct Case {
    const char* aperture;
    optics::ApertureShape::Kind kind;
    const char* warning;  // empty: none
  };
  for (const Case& c : {Case{"pentagon", optics::ApertureShape::Kind::Blades, ""},
                        Case{"star", optics::ApertureShape::Kind::Image, ""},
                        Case{"gaussian", optics::ApertureShape::Kind::Image, ""},
                        Case{"nowhere.png", optics::ApertureShape::Kind::Circle,
                             "not found; the lens's own stop is kept"}}) {
    const auto path = writeFile(directory / "scene.pbrt",
                                realisticCamera(8.0, 3.0, c.aperture) + furnaceWorld(1.0));
    ParseResult parsed = parsePbrtFile(path);
    ASSERT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
    Diagnostics diagnostics;
    const auto camera = makeCamera(*parsed.scene, {}, diagnostics);
    const auto* realistic = dynamic_cast<const RealisticCamera*>(camera.get());
    ASSERT_NE(realistic, nullptr) << diagnostics.formatAll();
    EXPECT_EQ(realistic->lens().stopShape().kind, c.kind) << c.aperture;
    const std::string all = diagnostics.formatAll();
    if (*c.warning) {
      EXPECT_NE(all.find(c.warning), std::string::npos) << all;
      EXPECT_NE(all.find("scene.pbrt:2:"), std::string::npos) << all;  // at the parameter
    } else {
      EXPECT_EQ(all.find("aperture"), std::string::npos) << all;
    }
  }
}

// A bokeh blob: the lit pixels (the world is black but for the light), with its centroid, the
// boundary radius in angular wedges around it and the principal axes of its second moments.
struct Blob {
  double cx = 0, cy = 0, total = 0;
  std::vector<double> radiusByWedge;
  double minorOverMajor = 0;
  double minorAxisAngle = 0;  // of the narrower principal direction, radians
};

Blob measureBlob(const RenderSnapshot& image, double fromX, double fromY, double withinPx,
                 int wedges) {
  Blob b;
  auto value = [&](int x, int y) {
    return image.rgb[3 * static_cast<std::size_t>(y * image.width + x)];
  };
  auto inside = [&](int x, int y) {
    return std::hypot(x + 0.5 - fromX, y + 0.5 - fromY) <= withinPx;
  };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (inside(x, y)) {
        b.total += value(x, y);
        b.cx += value(x, y) * (x + 0.5);
        b.cy += value(x, y) * (y + 0.5);
      }
  if (b.total <= 0) return b;
  b.cx /= b.total;
  b.cy /= b.total;
  // In a wedge of a uniformly lit region out to R(theta): sum I r^2 / sum I = R^2 / 2.
  std::vector<double> weight(wedges, 0.0), moment(wedges, 0.0);
  double sxx = 0, syy = 0, sxy = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      if (!inside(x, y)) continue;
      const double v = value(x, y), dx = x + 0.5 - b.cx, dy = y + 0.5 - b.cy;
      double angle = std::atan2(dy, dx);
      if (angle < 0) angle += 2 * kApertureRenderPi;
      const int w =
          std::min(wedges - 1, static_cast<int>(angle / (2 * kApertureRenderPi) * wedges));
      weight[w] += v;
      moment[w] += v * (dx * dx + dy * dy);
      sxx += v * dx * dx;
      syy += v * dy * dy;
      sxy += v * dx * dy;
    }
  for (int w = 0; w < wedges; ++w)
    b.radiusByWedge.push_back(weight[w] > 0 ? std::sqrt(2.0 * moment[w] / weight[w]) : 0.0);
  const double trace = sxx + syy, det = sxx * syy - sxy * sxy;
  const double disc = std::sqrt(std::max(0.0, trace * trace / 4 - det));
  const double major = trace / 2 + disc, minor = trace / 2 - disc;
  b.minorOverMajor = std::sqrt(minor / major);
  b.minorAxisAngle = std::atan2(minor - sxx, sxy);  // eigenvector (sxy, minor - sxx)
  return b;
}

// The exit-pupil table follows blades far from their circle (optics/stop_cells.h; this lens has
// no V_d, so the render is RGB and its table has cells): three blades, 41% of the circle, take
// one lens point per pixel sample and still bring most of a ray into the scene per sample
// (measured below: rays that left the lens per pixel sample, 0.72; with the circle's table, one
// point brought 0.4). pbrt's gaussian, a halftone that fills its circle at 26%, takes 4
// lens points per sample (RealisticCamera::lensPointsPerSample), each counted 1/4. The picture
// keeps the shape's brightness (the triangle's area against the circle's, as the square's
// above; the gaussian's in the test above goes through the same path).
TEST(ApertureRender, TheSamplerFollowsAShapeOrTakesSeveralLensPointsPerSample) {
  const auto directory = lenslab::testing::makeTestDirectory("aperture-points");
  auto furnace = [&](const std::string& lensText, const std::string& aperture) {
    writeFile(directory / "dgauss.dat", lensText);
    RenderJob job = loadJob(writeFurnaceScene(directory, aperture), 256);
    EXPECT_TRUE(job.camera && job.scene);
    const int points = job.camera ? job.camera->lensPointsPerSample() : 0;
    auto image = job.camera ? renderToCompletion(job) : nullptr;
    return std::make_pair(points, image);
  };
  const auto [circlePoints, circle] = furnace(render::testing::kDoubleGauss50, "");
  const auto [trianglePoints, triangle] = furnace(
      std::string("# lenslab aperture: blades 3 rotation 0\n") + render::testing::kDoubleGauss50,
      "");
  const auto [gaussianPoints, gaussian] = furnace(render::testing::kDoubleGauss50, "gaussian");
  ASSERT_TRUE(circle && triangle && gaussian);
  EXPECT_EQ(circlePoints, 1);
  EXPECT_EQ(trianglePoints, 1);
  EXPECT_EQ(gaussianPoints, 4);
  auto raysPerSample = [](const RenderSnapshot& image) {
    return static_cast<double>(image.statistics.lensPassed) /
           (static_cast<double>(image.width) * image.height * image.samplesPerPixel);
  };
  std::printf("rays into the scene per pixel sample: circle %.3f, triangle %.3f, gaussian %.3f\n",
              raysPerSample(*circle), raysPerSample(*triangle), raysPerSample(*gaussian));
  EXPECT_GT(raysPerSample(*triangle), 0.65);  // 0.72 measured
  EXPECT_GT(raysPerSample(*gaussian), 0.9);
  const double ratio = centralBlockMean(*triangle) / centralBlockMean(*circle);
  std::printf("uniform sky, centre: triangle / circle %.4f (3 sqrt 3 / (4 pi) %.4f)\n", ratio,
              3.0 * std::sqrt(3.0) / (4.0 * kApertureRenderPi));
  EXPECT_NEAR(ratio, 3.0 * std::sqrt(3.0) / (4.0 * kApertureRenderPi), 0.015);
}

// Magnitude of the k-th angular harmonic of the boundary radius, over its mean.
double harmonic(const std::vector<double>& r, int k) {
  std::complex<double> sum = 0.0;
  double mean = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double a = 2 * kApertureRenderPi * (i + 0.5) / r.size();
    sum += r[i] * std::polar(1.0, -k * a);
    mean += r[i];
  }
  return std::abs(sum) / mean;
}

TEST(ApertureRender, BokehShowsTheBladesOnAxisAndACatsEyeInTheCorner) {
  const auto directory = lenslab::testing::makeTestDirectory("aperture-bokeh");
  writeFile(directory / "dgauss.dat", std::string("# lenslab aperture: blades 6 rotation 0\n") +
                                          render::testing::kDoubleGauss50);
  writeFile(directory / "round.dat", render::testing::kDoubleGauss50);
  // Focused at 0.3 m; two small lights 20 m away, on the axis and toward the image's corner
  // (12 degrees, where the double-Gauss wide open vignettes; the blob stays inside the frame).
  constexpr int kSize = 240;
  const double t = std::tan(12.0 * kApertureRenderPi / 180.0) / std::sqrt(2.0) * 20.0;
  auto render = [&](const char* lens) {
    const auto path = writeFile(
        directory / "bokeh.pbrt",
        std::string("LookAt 0 0 0  0 0 1  0 1 0\nCamera \"realistic\" \"string lensfile\" \"") +
            lens +
            "\" \"float aperturediameter\" [17.1] \"float focusdistance\" [0.3]\n"
            "Film \"image\" \"integer xresolution\" [240] \"integer yresolution\" [240] "
            "\"float diagonal\" [35]\nIntegrator \"directlighting\"\nWorldBegin\n"
            "AttributeBegin\nTranslate 0 0 20\nAreaLightSource \"diffuse\" \"rgb L\" [50 50 50]\n"
            "Shape \"sphere\" \"float radius\" [0.08]\nAttributeEnd\n"
            "AttributeBegin\nTranslate " +
            std::to_string(t) + " " + std::to_string(t) +
            " 20\nAreaLightSource \"diffuse\" \"rgb L\" [50 50 50]\n"
            "Shape \"sphere\" \"float radius\" [0.08]\nAttributeEnd\nWorldEnd\n");
    RenderJob job = loadJob(path, 384);
    EXPECT_TRUE(job.camera && job.scene);
    return renderToCompletion(job);
  };
  const auto hexagon = render("dgauss.dat");
  const auto round = render("round.dat");
  ASSERT_TRUE(hexagon && round);
  constexpr int kWedges = 48;
  const double half = kSize / 2.0;
  const Blob centre = measureBlob(*hexagon, half, half, 50, kWedges);
  const Blob roundCentre = measureBlob(*round, half, half, 50, kWedges);
  ASSERT_GT(centre.total, 0.0);
  EXPECT_NEAR(centre.cx, half, 2.0);
  EXPECT_NEAR(centre.cy, half, 2.0);
  // A hexagon's boundary radius swings between corner and edge (1 : cos 30) six times round:
  // its sixth harmonic stands out above the others, and the circle has none.
  const double h6 = harmonic(centre.radiusByWedge, 6);
  std::printf("bokeh on axis: harmonics 1..12 of the boundary radius:");
  for (int k = 1; k <= 12; ++k) std::printf(" %.4f", harmonic(centre.radiusByWedge, k));
  std::printf("\n  round stop's 6th %.4f; minor/major hexagon %.3f\n",
              harmonic(roundCentre.radiusByWedge, 6), centre.minorOverMajor);
  if (const char* dump = std::getenv("LENSLAB_APERTURE_TEST_DUMP")) {
    writeImage(std::filesystem::path(dump) / "bokeh-hexagon.png",
               FloatImage{hexagon->width, hexagon->height, hexagon->rgb}, 0.0);
    writeImage(std::filesystem::path(dump) / "bokeh-round.png",
               FloatImage{round->width, round->height, round->rgb}, 0.0);
  }
  // (The first harmonic is left out: it is mostly the noise of the centroid the radii are
  // measured from.)
  for (int k : {2, 3, 4, 5, 7, 8, 9, 10, 11})
    EXPECT_GT(h6, 3.0 * harmonic(centre.radiusByWedge, k)) << "harmonic " << k;
  EXPECT_GT(h6, 0.02);
  EXPECT_LT(harmonic(roundCentre.radiusByWedge, 6), 0.4 * h6);
  // The regular hexagon's second moments are isotropic.
  EXPECT_GT(centre.minorOverMajor, 0.93);

  // Toward the corner the rims cut the blob into a cat's eye: narrower along the radius.
  double cornerX = 0, cornerY = 0;
  {
    // The corner light's blob: the lit pixels beyond the central one.
    double sum = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double v = hexagon->rgb[3 * static_cast<std::size_t>(y * kSize + x)];
        if (std::hypot(x + 0.5 - half, y + 0.5 - half) > 60 && v > 0) {
          cornerX += v * (x + 0.5);
          cornerY += v * (y + 0.5);
          sum += v;
        }
      }
    ASSERT_GT(sum, 0.0);
    cornerX /= sum;
    cornerY /= sum;
  }
  const Blob corner = measureBlob(*hexagon, cornerX, cornerY, 45, kWedges);
  std::printf("corner blob: minor/major %.3f, narrow axis %.1f deg, radial %.1f deg\n",
              corner.minorOverMajor, corner.minorAxisAngle * 180 / kApertureRenderPi,
              std::atan2(corner.cy - half, corner.cx - half) * 180 / kApertureRenderPi);
  EXPECT_LT(corner.minorOverMajor, 0.85);
  const double radial = std::atan2(corner.cy - half, corner.cx - half);
  EXPECT_GT(std::abs(std::cos(corner.minorAxisAngle - radial)), 0.9)
      << "the narrow direction points at the image centre";
}

// The bundled bokeh scene (scenes/bokeh.pbrt): it reads without a warning, its lights sit far out
// of focus behind a subject at 0.45 m, and the light on the axis comes out as pbrt-v4's pentagon:
// the fifth harmonic of its boundary stands out, as the sixth does for six blades above.
TEST(ApertureRender, TheBundledBokehSceneShowsAPentagonOnTheAxis) {
  const auto scene = std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "bokeh.pbrt";
  const ParseResult parsed = parsePbrtFile(scene);
  ASSERT_TRUE(parsed.scene) << parsed.diagnostics.formatAll();
  EXPECT_TRUE(parsed.diagnostics.empty()) << parsed.diagnostics.formatAll();
  CameraOverrides overrides;
  overrides.width = 300;
  overrides.height = 200;
  overrides.falloff.spectral = SpectralMode::Off;  // the shape, without colour noise
  RenderJob job = loadJob(scene, 256, overrides);
  ASSERT_TRUE(job.camera && job.scene);
  const auto image = renderToCompletion(job);
  ASSERT_TRUE(image);
  const Blob centre = measureBlob(*image, 150.0, 100.0, 24, 40);
  ASSERT_GT(centre.total, 0.0);
  EXPECT_NEAR(centre.cx, 150.0, 2.0);
  EXPECT_NEAR(centre.cy, 100.0, 2.0);
  const double h5 = harmonic(centre.radiusByWedge, 5);
  std::printf("bundled bokeh scene, light on the axis: harmonics 2..10:");
  for (int k = 2; k <= 10; ++k) std::printf(" %.4f", harmonic(centre.radiusByWedge, k));
  std::printf("\n");
  for (int k : {2, 3, 4, 6, 7, 8, 9})
    EXPECT_GT(h5, 2.0 * harmonic(centre.radiusByWedge, k)) << "harmonic " << k;
  EXPECT_GT(h5, 0.02);
  // Far out of focus: the disc's mean radius is many pixels.
  double meanRadius = 0.0;
  for (double r : centre.radiusByWedge) meanRadius += r / centre.radiusByWedge.size();
  EXPECT_GT(meanRadius, 8.0);
}

// The default scene's lamps (scenes/default.pbrt), 0.55 m from the camera and far out of focus:
// through five blades the disc of the lamp in the middle is a pentagon (its fifth harmonic stands
// out, three times the round stop's), and the discs at the ends of the string, near the picture's
// sides, are cat's eyes. A disc is the light above the sky around it, within 20 px (measureBlob's
// moments average the discs' grain; a threshold at half their brightness left the round stop's
// fifth harmonic at 0.010-0.013, too near the blades'). The lamp is not a point: its own image,
// about 8 px across, softens the corners. (Six blades measured a sixth harmonic of 0.021 against
// the round stop's 0.008, too close to its noise for a test.)
TEST(ApertureRender, TheDefaultScenesLampsShowTheBladesAndCatsEyes) {
  const auto directory = lenslab::testing::makeTestDirectory("aperture-default-lamps");
  const std::string lensText = lenslab::testing::readWholeFile(
      std::filesystem::path(LENSLAB_SOURCE_DIR) / "lenses" / "dgauss-50mm.dat");
  auto render = [&](const std::string& apertureLine) {
    CameraOverrides overrides;
    overrides.lensPath = writeFile(directory / "dgauss.dat", apertureLine + lensText);
    overrides.falloff.spectral = SpectralMode::Off;  // the shape, without colour noise
    RenderJob job = loadJob(std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes" / "default.pbrt",
                            128, overrides);
    EXPECT_TRUE(job.camera && job.scene);
    return job.camera ? renderToCompletion(job) : nullptr;
  };
  // The disc around (x, y): the luminance above the sky's, in channel 0 (which measureBlob reads).
  auto disc = [](const RenderSnapshot& image, double x, double y) {
    auto luminance = [&](std::size_t i) {
      return 0.2126 * image.rgb[3 * i] + 0.7152 * image.rgb[3 * i + 1] +
             0.0722 * image.rgb[3 * i + 2];
    };
    // The sky around the disc: the median of the ring 21-24 px out.
    std::vector<double> ring;
    for (int py = 0; py < image.height; ++py)
      for (int px = 0; px < image.width; ++px) {
        const double r = std::hypot(px + 0.5 - x, py + 0.5 - y);
        if (r > 21.0 && r < 24.0) {
          ring.push_back(luminance(static_cast<std::size_t>(py) * image.width + px));
        }
      }
    std::nth_element(ring.begin(), ring.begin() + ring.size() / 2, ring.end());
    const double sky = ring[ring.size() / 2];
    RenderSnapshot lamp = image;
    for (std::size_t i = 0; i < lamp.rgb.size() / 3; ++i) {
      lamp.rgb[3 * i] = static_cast<float>(std::max(0.0, luminance(i) - sky));
    }
    return measureBlob(lamp, x, y, 20, 24);
  };
  const auto blades = render("# lenslab aperture: blades 5 rotation 90\n");
  const auto round = render("");
  ASSERT_TRUE(blades && round);
  // Where the lamps' discs are at 600 x 400 (measured: the middle at (300, 67), the ends at
  // (30, 94) and (570, 94)).
  const Blob middle = disc(*blades, 300.0, 67.0);
  const Blob roundMiddle = disc(*round, 300.0, 67.0);
  const Blob left = disc(*blades, 30.0, 94.0), right = disc(*blades, 570.0, 94.0);
  ASSERT_GT(middle.total, 0.0);
  ASSERT_GT(roundMiddle.total, 0.0);
  ASSERT_GT(left.total, 0.0);
  ASSERT_GT(right.total, 0.0);
  EXPECT_NEAR(middle.cx, 300.0, 2.0);
  std::printf("default scene's lamps: middle at (%.1f, %.1f); harmonics 2..10:", middle.cx,
              middle.cy);
  for (int k = 2; k <= 10; ++k) std::printf(" %.4f", harmonic(middle.radiusByWedge, k));
  std::printf(
      "\n  round stop's fifth %.4f; minor/major: middle %.3f, left end %.3f, right end "
      "%.3f\n",
      harmonic(roundMiddle.radiusByWedge, 5), middle.minorOverMajor, left.minorOverMajor,
      right.minorOverMajor);
  // (The second harmonic is left out: the middle lamp is a third of the way to the picture's top,
  // where the rims already narrow its disc a little.)
  const double h5 = harmonic(middle.radiusByWedge, 5);
  for (int k : {3, 4, 6, 7, 8, 9, 10})
    EXPECT_GT(h5, 1.5 * harmonic(middle.radiusByWedge, k)) << "harmonic " << k;
  EXPECT_GT(h5, 3.0 * harmonic(roundMiddle.radiusByWedge, 5));  // 0.030 and 0.008 measured
  EXPECT_GT(middle.minorOverMajor, 0.9);
  EXPECT_LT(left.minorOverMajor, 0.8);
  EXPECT_LT(right.minorOverMajor, 0.8);
  // Far out of focus: discs about 30 px across.
  double meanRadius = 0.0;
  for (double r : middle.radiusByWedge) meanRadius += r / middle.radiusByWedge.size();
  EXPECT_GT(meanRadius, 10.0);
}

// The lamps' discs cover 2.6% of the default scene's picture, so the viewer's auto exposure (the
// 99th percentile of the luminance, render/auto_exposure.h) meters on them. Their radiance keeps
// the rest of the picture within 0.6 stop of its exposure without them (0.43 measured; five
// times that radiance put it 2.3 stops darker).
TEST(ApertureRender, TheDefaultScenesLampsBarelyMoveItsAutoExposure) {
  const auto scenes = std::filesystem::path(LENSLAB_SOURCE_DIR) / "scenes";
  const std::string text = lenslab::testing::readWholeFile(scenes / "default.pbrt");
  const std::string lampRadiance = "AreaLightSource \"diffuse\" \"rgb L\" [30 24 15]";
  const std::size_t at = text.find(lampRadiance);
  ASSERT_NE(at, std::string::npos) << "the lamps' radiance changed: update this test";
  std::string dark = text;
  dark.replace(at, lampRadiance.size(), "AreaLightSource \"diffuse\" \"rgb L\" [0 0 0]");
  auto exposure = [&](const std::string& sceneText) {
    CameraOverrides overrides;
    overrides.width = 300;
    overrides.height = 200;
    overrides.falloff.spectral = SpectralMode::Off;
    const RenderJob job = render::testing::jobFromParsed(
        parsePbrtText(sceneText, "default.pbrt", scenes), 64, overrides);
    if (!job.camera || !job.scene) return 0.0;
    const auto image = renderToCompletion(job);
    EXPECT_TRUE(image);
    return image ? autoExposureStops(FloatImage{image->width, image->height, image->rgb}) : 0.0;
  };
  const double withLamps = exposure(text), without = exposure(dark);
  std::printf("auto exposure of the default scene: %.2f stops with its lamps, %.2f without\n",
              withLamps, without);
  EXPECT_GT(without, 1.0);  // a dim picture brightened: the meter reads the scene
  EXPECT_NEAR(withLamps, without, 0.6);
}

}  // namespace
}  // namespace lenslab::render
