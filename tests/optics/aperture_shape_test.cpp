// Aperture shapes (aperture_shape.h): the blades' inside test against their analytic area by a
// Monte Carlo count, the image mask's mapping and refusals, and the traces with a shaped stop.

#include <gtest/gtest.h>

#include <stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "optics/aperture_shape.h"
#include "optics/exit_pupil.h"
#include "optics/lens_outline.h"
#include "test_lenses.h"
#include "test_shapes.h"

namespace lenslab::optics {
namespace {

constexpr double kPi = std::numbers::pi;

using testing::blades;

// The area of N blades inscribed in the unit circle, worked out here from elementary geometry:
// N isosceles triangles with apex angle 2 pi / N, plus (curved) N circular segments of an arc of
// radius 1 / curvature over a chord of length 2 sin(pi / N).
double analyticBladeArea(int n, double curvature) {
  const double triangles = 0.5 * n * std::sin(2.0 * kPi / n);
  if (curvature == 0.0) return triangles;
  const double rho = 1.0 / curvature, halfChord = std::sin(kPi / n);
  const double halfAngle = std::asin(halfChord / rho);  // half the angle the chord subtends
  const double segment = 0.5 * rho * rho * (2.0 * halfAngle - std::sin(2.0 * halfAngle));
  return triangles + n * segment;
}

TEST(ApertureShape, BladeAreaByMonteCarloCountMatchesGeometry) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  constexpr int kSamples = 100000;
  for (int n : {3, 6, 9, 32}) {
    for (double curvature : {0.0, 0.5, 1.0}) {
      for (double rotation : {0.0, 17.0}) {
        const ApertureShape shape = blades(n, curvature, rotation);
        const double stopRadiusMm = 7.5;
        const StopShapeTest test(shape, stopRadiusMm);
        int inUnit = 0, inMm = 0;
        for (int i = 0; i < kSamples; ++i) {
          const glm::dvec2 p{u(rng), u(rng)};
          inUnit += shape.containsUnit(p);
          inMm += test.contains(p.x * stopRadiusMm, p.y * stopRadiusMm);
        }
        const double expected = analyticBladeArea(n, curvature);
        // Binomial standard error of 4 * fraction is about 0.003 here; allow 4 sigma.
        const double sigma = 4.0 * std::sqrt(expected / 4.0 * (1.0 - expected / 4.0) / kSamples);
        EXPECT_NEAR(4.0 * inUnit / kSamples, expected, 4.0 * sigma)
            << n << " blades, curvature " << curvature;
        EXPECT_NEAR(4.0 * inMm / kSamples, expected, 4.0 * sigma)
            << n << " blades, curvature " << curvature << " (mm test)";
        EXPECT_NEAR(shape.areaFactor(), expected, 1e-12);
      }
    }
  }
  EXPECT_NEAR(analyticBladeArea(4, 0.0), 2.0, 1e-15);  // the square inscribed in the unit circle
  EXPECT_NEAR(analyticBladeArea(7, 1.0), kPi, 1e-12);  // fully rounded: the circle
}

TEST(ApertureShape, PbrtsGaussianIsAHalftoneOfItsTransmission) {
  const auto gaussian = builtinPbrtAperture("gaussian");
  ASSERT_TRUE(gaussian);
  ASSERT_EQ(gaussian->kind, ApertureShape::Kind::Image);
  ASSERT_TRUE(gaussian->mask);
  const ApertureMask& mask = *gaussian->mask;
  const int n = mask.sizePx;
  ASSERT_EQ(n % 16, 0);
  // pbrt-v4's transmission, written out here: exp(-r^2) - exp(-1), 0 beyond the rim.
  auto transmission = [](double x, double y) {
    const double r2 = x * x + y * y;
    return r2 < 1.0 ? std::exp(-r2) - std::exp(-1.0) : 0.0;
  };
  // Each aligned 16 x 16 block passes the transmission at its centre: to within 1/256 of the
  // dither, plus T's change across the block (|dT/dr| = 2 r exp(-r^2) <= 0.86, over half a
  // diagonal of 32 / 1024 * sqrt(2) / 2 units).
  const double tolerance = 1.0 / 256.0 + 0.86 * (16.0 / n) * std::sqrt(2.0);
  double worst = 0.0;
  for (int blockRow = 0; blockRow < n / 16; ++blockRow) {
    for (int blockCol = 0; blockCol < n / 16; ++blockCol) {
      int open = 0;
      for (int row = 16 * blockRow; row < 16 * blockRow + 16; ++row)
        for (int col = 16 * blockCol; col < 16 * blockCol + 16; ++col)
          open += mask.open[static_cast<std::size_t>(row) * n + col];
      const double x = -1.0 + 2.0 * (16 * blockCol + 8) / n;
      const double y = 1.0 - 2.0 * (16 * blockRow + 8) / n;
      worst = std::max(worst, std::abs(open / 256.0 - transmission(x, y)));
    }
  }
  EXPECT_LT(worst, tolerance);
  // In all: the integral of T over the unit disk, pi (1 - 2/e).
  EXPECT_NEAR(gaussian->areaFactor(), kPi * (1.0 - 2.0 / std::numbers::e), 0.002 * kPi);
  // Open out to the rim, so the exit-pupil table's circle is the stop's.
  EXPECT_NEAR(gaussian->boundRadiusFactor(), 1.0, 0.01);
}

TEST(ApertureShape, CornersFollowTheRotation) {
  // A square with its first corner at 45 degrees has its edges along x and y at 1/sqrt(2).
  const ApertureShape square = blades(4, 0.0, 45.0);
  const double half = std::sqrt(0.5);
  EXPECT_TRUE(square.containsUnit({half - 1e-6, half - 1e-6}));
  EXPECT_FALSE(square.containsUnit({half + 1e-3, 0.0}));
  EXPECT_FALSE(square.containsUnit({0.0, -half - 1e-3}));
  // With its first corner on +x it reaches x = 1 there, but only 1/sqrt(2) along the diagonal.
  const ApertureShape diamond = blades(4, 0.0, 0.0);
  EXPECT_TRUE(diamond.containsUnit({0.999, 0.0}));
  EXPECT_FALSE(diamond.containsUnit({0.5 + 1e-3, 0.5 + 1e-3}));
  // Each outline corner lies on the unit circle at rotation + k 360 / N.
  const auto outline = blades(6, 0.0, 15.0).outlineUnit();
  ASSERT_EQ(outline.size(), 7u);
  for (int k = 0; k < 6; ++k) {
    const double a = (15.0 + 60.0 * k) * kPi / 180.0;
    EXPECT_NEAR(outline[k].x, std::cos(a), 1e-12);
    EXPECT_NEAR(outline[k].y, std::sin(a), 1e-12);
  }
}

TEST(ApertureShape, CurvedBladesStayAccurateAtTinyCurvature) {
  // A curvature of 1e-6 is an arc of radius a million stop radii: the single-precision test must
  // still put the edge at the straight one's place.
  const StopShapeTest test(blades(6, 1e-6, 0.0), 10.0);
  const double apothemMm = 10.0 * std::cos(kPi / 6.0);
  // Edge 0's normal is at 30 degrees.
  const glm::dvec2 n{std::cos(kPi / 6.0), std::sin(kPi / 6.0)};
  EXPECT_TRUE(test.contains(n.x * (apothemMm - 1e-3), n.y * (apothemMm - 1e-3)));
  EXPECT_FALSE(test.contains(n.x * (apothemMm + 1e-3), n.y * (apothemMm + 1e-3)));
}

class ScratchDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() /
        ("lenslab-aperture-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path writePng(const std::string& name, int w, int h,
                                 const std::function<int(int, int)>& grey) {
    std::vector<unsigned char> pixels(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c)
          pixels[(static_cast<std::size_t>(y) * w + x) * 3 + c] = grey(x, y);
    const auto path = dir_ / name;
    EXPECT_NE(stbi_write_png(path.c_str(), w, h, 3, pixels.data(), w * 3), 0);
    return path;
  }
  std::filesystem::path dir_;
};

using ApertureMaskFile = ScratchDir;

TEST_F(ApertureMaskFile, MapsTheImageOntoTheSquareAroundTheStop) {
  // 8x8: white only in the top-left quarter (the image's top is +y).
  const auto path =
      writePng("quarter.png", 8, 8, [](int x, int y) { return x < 4 && y < 4 ? 255 : 0; });
  std::string error;
  const auto mask = loadApertureMask(path, &error);
  ASSERT_TRUE(mask) << error;
  EXPECT_EQ(mask->sizePx, 8);
  EXPECT_DOUBLE_EQ(mask->openFraction(), 0.25);
  ApertureShape shape;
  shape.kind = ApertureShape::Kind::Image;
  shape.mask = mask;
  shape.imageName = "quarter.png";
  EXPECT_DOUBLE_EQ(shape.areaFactor(), 1.0);  // a quarter of the 2R x 2R square
  const StopShapeTest test(shape, 5.0);
  EXPECT_TRUE(test.contains(-2.5, 2.5));
  EXPECT_TRUE(test.contains(-4.9, 4.9));  // the square's corner, beyond the stop circle
  EXPECT_FALSE(test.contains(2.5, 2.5));
  EXPECT_FALSE(test.contains(-2.5, -2.5));
  EXPECT_FALSE(test.contains(-5.1, 2.5));  // outside the image
}

TEST_F(ApertureMaskFile, RefusesMissingUnreadableNonSquareAndBlackImages) {
  std::string error;
  EXPECT_FALSE(loadApertureMask(dir_ / "none.png", &error));
  EXPECT_NE(error.find("not found"), std::string::npos) << error;
  const auto garbage = dir_ / "garbage.png";
  std::ofstream(garbage) << "this is not an image";
  EXPECT_FALSE(loadApertureMask(garbage, &error));
  EXPECT_NE(error.find("cannot read"), std::string::npos) << error;
  EXPECT_FALSE(loadApertureMask(writePng("wide.png", 8, 4, [](int, int) { return 255; }), &error));
  EXPECT_NE(error.find("must be square (it is 8x4)"), std::string::npos) << error;
  EXPECT_FALSE(loadApertureMask(writePng("black.png", 6, 6, [](int, int) { return 100; }), &error));
  EXPECT_NE(error.find("all black"), std::string::npos) << error;
}

TEST(ApertureSpec, ReadsAndRefusesWithColumns) {
  const auto ok = parseApertureSpec("blades 6 curvature 0.5 rotation 15");
  ASSERT_TRUE(ok.shape) << ok.error;
  EXPECT_EQ(ok.shape->bladeCount, 6);
  EXPECT_EQ(ok.shape->curvature, 0.5);
  EXPECT_EQ(ok.shape->rotationDeg, 15.0);
  EXPECT_EQ(parseApertureSpec(ok.shape->spec()).shape, ok.shape);
  EXPECT_TRUE(parseApertureSpec("circle").shape->isCircle());
  EXPECT_EQ(parseApertureSpec("image my iris.png").shape->imageName, "my iris.png");
  struct Bad {
    const char* text;
    int column;
    const char* says;
  };
  for (const Bad& bad :
       {Bad{"blades 2", 7, "out of range"}, Bad{"blades 33", 7, "out of range"},
        Bad{"blades 6.5", 7, "whole number"}, Bad{"blades", 0, "blade count"},
        Bad{"blades 6 curvature 2", 19, "0 straight to 1 round"},
        Bad{"blades 6 twist 3", 9, "unknown blade setting"},
        Bad{"blades 6 rotation", 9, "needs a value"}, Bad{"hexagon", 0, "unknown aperture"}}) {
    const auto r = parseApertureSpec(bad.text);
    EXPECT_FALSE(r.shape) << bad.text;
    EXPECT_EQ(r.column, bad.column) << bad.text;
    EXPECT_NE(r.error.find(bad.says), std::string::npos) << bad.text << ": " << r.error;
  }
}

std::shared_ptr<const LensSystem> doubleGaussAtF8() {
  auto lens = testing::loadLens(testing::bundledLensDir() / "dgauss-50mm.dat");
  if (!lens) return nullptr;
  return lens->withStopDiameter(lens->stopDiameterMm() * lens->firstOrder().fNumber / 8.0);
}

TEST(ShapedStop, ScalarAndBatchTracesAgreeRayByRay) {
  const auto base = doubleGaussAtF8();
  ASSERT_TRUE(base);
  ApertureShape star = *builtinPbrtAperture("star");
  // Masks as the batch trace reads them, one bit a pixel: the gaussian's 1024 px halftone,
  // mirrored, and a triangle at 101 px, whose rows do not start on a 32-bit word.
  const ApertureShape gaussian = builtinPbrtAperture("gaussian")->mirroredLeftToRight();
  ApertureShape triangle;
  triangle.kind = ApertureShape::Kind::Image;
  triangle.imageName = "triangle";
  triangle.mask = rasterizeApertureMask({{-0.9, -0.6}, {0.9, -0.3}, {-0.2, 0.95}}, 101, "triangle");
  // A mask made by hand without ApertureMask::finish() (no bits): the trace packs its own.
  ApertureShape unpacked = star;
  auto bare = std::make_shared<ApertureMask>(*star.mask);
  bare->openBits.clear();
  unpacked.mask = bare;
  for (const ApertureShape& shape :
       {blades(6, 0.0, 10.0), blades(5, 0.6, 0.0), star, gaussian, triangle, unpacked}) {
    const auto lens = base->withStopShape(shape);
    ASSERT_TRUE(lens);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    LensRayBatch batch;
    batch.resize(4000);
    std::vector<bool> scalar(batch.size());
    for (std::size_t i = 0; i < batch.size(); ++i) {
      // Aimed by the exit-pupil table (the circle's around the star and the gaussian; cells
      // following the triangle), from film points across the image: the shape stops a share.
      const glm::dvec3 o{15.0 * u(rng), 15.0 * u(rng), 0.0};
      const auto aim = lens->sampleExitPupil({o.x, o.y}, {u(rng), u(rng)});
      const glm::dvec3 d = glm::normalize((aim ? aim->pointMm : glm::dvec3{0, 0, 1}) - o);
      batch.ox[i] = o.x, batch.oy[i] = o.y, batch.oz[i] = o.z;
      batch.dx[i] = d.x, batch.dy[i] = d.y, batch.dz[i] = d.z;
      scalar[i] = lens->traceFromFilm({o, d}).has_value();
    }
    for (auto kernel : {LensSystem::BatchKernel::Portable, LensSystem::BatchKernel::Auto}) {
      LensRayBatch b = batch;
      lens->traceFromFilmBatch(b, kernel);
      int disagree = 0, passing = 0;
      for (std::size_t i = 0; i < b.size(); ++i) {
        disagree += (b.alive[i] != 0) != scalar[i];
        passing += scalar[i];
      }
      EXPECT_GT(passing, 500);
      EXPECT_LT(passing, 3900);  // the shape stops some
      // Single against double precision: only rays grazing an edge may differ.
      EXPECT_LE(disagree, 2) << shape.spec();
    }
  }
}

// The estimator E[pass / pdf] over exit-pupil samples is the area of the pass region on the
// rear-vertex plane. On the axis, at f/8 (no rim cuts the beam), that region is the stop's image:
// shaped and round stops differ by the ratio of their areas (up to the pupil's small distortion),
// which is what the square (2 / pi) and the hexagon (3 sqrt(3) / (2 pi)) give.
TEST(ShapedStop, TableSamplingIsUnbiasedAndKeepsMostSamples) {
  const auto circle = doubleGaussAtF8();
  ASSERT_TRUE(circle);
  auto estimate = [](const LensSystem& lens, glm::dvec2 film, double& keptShare) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double sum = 0.0;
    int kept = 0, sampled = 0;
    constexpr int kN = 200000;
    for (int i = 0; i < kN; ++i) {
      const auto s = lens.sampleExitPupil(film, {u(rng), u(rng)});
      if (!s) continue;
      ++sampled;
      const glm::dvec3 o{film, 0.0};
      if (lens.traceFromFilm({o, glm::normalize(s->pointMm - o)})) {
        sum += 1.0 / s->pdfPerMm2;
        ++kept;
      }
    }
    keptShare = static_cast<double>(kept) / std::max(1, sampled);
    return sum / kN;
  };
  double keptCircle = 0.0, keptSquare = 0.0, keptHexagon = 0.0;
  const double areaCircle = estimate(*circle, {0.0, 0.0}, keptCircle);
  const auto square = circle->withStopShape(blades(4, 0.0, 45.0));
  const auto hexagon = circle->withStopShape(blades(6, 0.0, 0.0));
  const double areaSquare = estimate(*square, {0.0, 0.0}, keptSquare);
  const double areaHexagon = estimate(*hexagon, {0.0, 0.0}, keptHexagon);
  EXPECT_NEAR(areaSquare / areaCircle, 2.0 / kPi, 0.01);
  EXPECT_NEAR(areaHexagon / areaCircle, 3.0 * std::sqrt(3.0) / (2.0 * kPi), 0.01);
  // The table follows the blades (stop_cells.h): they keep most samples, more than the square's
  // and the hexagon's shares of the circle (0.64, 0.83) that the circle's table kept.
  EXPECT_GT(keptHexagon, 0.9 * keptCircle);
  EXPECT_GT(keptSquare, 0.85 * keptCircle);
}

TEST(ShapedStop, TableContainsEveryPassingRayOfAShapedStop) {
  const auto base = doubleGaussAtF8();
  ASSERT_TRUE(base);
  for (const ApertureShape& shape : {blades(6, 0.4, 20.0), *builtinPbrtAperture("star")}) {
    const auto lens = base->withStopShape(shape);
    const ExitPupilTable& table = lens->exitPupilTable();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int passing = 0, outside = 0;
    for (int f = 0; f < 40; ++f) {
      const double r = table.filmRadiusMaxMm() * (f + u(rng)) / 40.0;
      const double phi = 2.0 * kPi * u(rng);
      const glm::dvec2 film{r * std::cos(phi), r * std::sin(phi)};
      const double domain = table.fallbackRadiusMm();
      for (int i = 0; i < 400; ++i) {
        const glm::dvec2 p{domain * (2 * u(rng) - 1), domain * (2 * u(rng) - 1)};
        const glm::dvec3 o{film, 0.0};
        if (!lens->traceFromFilm({o, glm::normalize(glm::dvec3{p, table.planeZMm()} - o)}))
          continue;
        ++passing;
        if (table.pdf(film, p) <= 0.0) ++outside;
      }
    }
    EXPECT_GT(passing, 50);
    EXPECT_EQ(outside, 0) << shape.spec();
  }
}

TEST(ShapedStop, TheOutlineCutsTheSectionAtTheBladesAndDrawsTheIrisFaceOn) {
  Prescription p = testing::loadPrescription(testing::bundledLensDir() / "dgauss-50mm.dat");
  ASSERT_FALSE(p.surfaces.empty());
  const double radiusMm = 0.5 * p.surfaces[*p.stopIndex()].apertureDiameterMm;
  const LensOutline round = computeLensOutline(p);
  ASSERT_TRUE(round.stop);
  EXPECT_EQ(round.stop->openingUpMm, radiusMm);
  EXPECT_TRUE(round.stop->shapeOutlineMm.empty());
  // A square with edges along x and y meets the y axis at R / sqrt(2); a square standing on a
  // corner at R.
  p.stopShape = blades(4, 0.0, 45.0);
  const LensOutline square = computeLensOutline(p);
  EXPECT_NEAR(square.stop->openingUpMm, radiusMm / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(square.stop->openingDownMm, radiusMm / std::sqrt(2.0), 1e-9);
  ASSERT_EQ(square.stop->shapeOutlineMm.size(), 5u);
  EXPECT_NEAR(glm::length(square.stop->shapeOutlineMm[0]), radiusMm, 1e-9);
  p.stopShape = blades(4, 0.0, 90.0);
  EXPECT_NEAR(computeLensOutline(p).stop->openingUpMm, radiusMm, 1e-9);
}

TEST(ShapedStop, WithStopShapeRefusesABladeCountOutOfRange) {
  const auto lens = doubleGaussAtF8();
  ASSERT_TRUE(lens);
  EXPECT_FALSE(lens->withStopShape(blades(2, 0.0, 0.0)));
  EXPECT_FALSE(lens->withStopShape(blades(33, 0.0, 0.0)));
  ApertureShape noMask;
  noMask.kind = ApertureShape::Kind::Image;
  EXPECT_FALSE(lens->withStopShape(noMask));
  Prescription p = lens->prescription();
  p.stopShape = blades(40, 0.0, 0.0);
  const auto errors = validate(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].toString().find("blade count 40 is out of range"), std::string::npos);
}

}  // namespace
}  // namespace lenslab::optics
