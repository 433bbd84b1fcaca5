// `lenslab analyze --only distortion,distortion_grid,field_curvature`, run as a real process:
// a thin lens with its stop at the lens (no distortion wherever the film is; the axial focus by
// the thick-lens formula worked out by hand), the double-Gauss's curves from the axis to the
// corner, and an afocal lens.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/analyze_test_fixture.h"
#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class AnalyzeDistortion : public AnalyzeTest {
 protected:
  AnalyzeDistortion() : AnalyzeTest("analyze-distortion") {}
};

// R = +-100 mm, n = 1.5, 0.4 mm thick: power (n-1)(c1 - c2) + (n-1)^2 t c1 c2 / n
// = 0.01 - 6.667e-6 per mm, f = 100.0667 mm, back focal distance f (1 - (n-1) t c1 / n)
// = 99.9333 mm. The stop 1 um in front of it.
constexpr const char* kThinLens =
    "# radius thickness n_d aperture\n"
    "0 0.001 0 4\n"
    "100 0.4 1.5 12\n"
    "-100 99 1 12\n";
constexpr double kBackFocusMm = 99.9333;

TEST_F(AnalyzeDistortion, ThinLensWithTheStopAtTheLens) {
  const std::string lens = writeFile("thin.dat", kThinLens);
  const auto json = analyzeJson(lens +
                                " --film-distance 99 --film-diagonal 40 --points 33 --only "
                                "distortion,field_curvature,distortion_grid");
  const auto& distortion = json.at("distortion");
  ASSERT_EQ(distortion.size(), 33u);
  for (std::size_t i = 0; i < distortion.size(); ++i) {
    const auto& p = distortion[i];
    EXPECT_NEAR(p.at("image_height_mm").get<double>(), 20.0 * i / 32.0, 1e-6);
    // The chief ray leaves at its entrance angle (distortion_test.cpp says why 0.02 %).
    EXPECT_NEAR(p.at("percent").get<double>(), 0.0, 0.02) << i;
    // The film 0.93 mm in front of the focus: the chief ray leaves the rear nodal point (the
    // rear principal point, f - BFL = 0.1333 mm in front of the rear vertex) at its entrance
    // angle and lands at 99.1333 tan(theta).
    const double tanTheta = std::tan(p.at("field_angle_deg").get<double>() * M_PI / 180.0);
    EXPECT_NEAR(p.at("image_height_mm").get<double>(), 99.1333 * tanTheta, 2e-4 * 20.0);
  }
  const auto& curves = json.at("field_curvature");
  ASSERT_EQ(curves.size(), 33u);
  EXPECT_NEAR(curves[0].at("tangential_mm").get<double>(), kBackFocusMm - 99.0, 1e-3);
  EXPECT_NEAR(curves[0].at("sagittal_mm").get<double>(), kBackFocusMm - 99.0, 1e-3);
  EXPECT_NEAR(curves[0].at("petzval_mm").get<double>(), kBackFocusMm - 99.0, 1e-3);
  // Coddington (field_curvature_test.cpp): at h = 5 mm the sagittal focus is
  // h^2 (1 + 1/n) / (2 f) = 0.2082 mm nearer the lens, the tangential one 0.4582 mm.
  const auto& at5 = curves[8];
  ASSERT_NEAR(at5.at("image_height_mm").get<double>(), 5.0, 1e-9);
  EXPECT_NEAR(at5.at("sagittal_mm").get<double>() - curves[0].at("sagittal_mm").get<double>(),
              -0.2082, 0.004);
  EXPECT_NEAR(at5.at("tangential_mm").get<double>() - curves[0].at("tangential_mm").get<double>(),
              -0.4582, 0.008);
  const auto& grid = json.at("distortion_grid");
  EXPECT_NEAR(grid.at("film_width_mm").get<double>(), 40.0 * 3.0 / std::sqrt(13.0), 1e-9);
  EXPECT_EQ(grid.at("ideal").size(), 22u);
  EXPECT_FALSE(grid.at("real").empty());
}

// The double-Gauss: 64 points to the corner with numbers everywhere, a mild barrel toward the
// corner, and an astigmatic field at the corner.
TEST_F(AnalyzeDistortion, DoubleGaussCurvesReachTheCorner) {
  const auto json = analyzeJson(lensPath("dgauss-50mm.dat") + " --only distortion,field_curvature");
  const auto& distortion = json.at("distortion");
  ASSERT_EQ(distortion.size(), 64u);
  EXPECT_EQ(distortion[0].at("percent").get<double>(), 0.0);
  for (const auto& p : distortion) ASSERT_TRUE(p.at("percent").is_number()) << p.dump();
  const double corner = distortion.back().at("percent").get<double>();
  EXPECT_LT(corner, 0.0);
  EXPECT_GT(corner, -5.0);
  EXPECT_NEAR(distortion.back().at("image_height_mm").get<double>(), 0.5 * 43.27, 1e-6);
  const auto& curves = json.at("field_curvature");
  ASSERT_EQ(curves.size(), 64u);
  for (const auto& p : curves)
    for (const char* key : {"field_angle_deg", "tangential_mm", "sagittal_mm", "petzval_mm"})
      ASSERT_TRUE(p.at(key).is_number()) << p.dump();
  EXPECT_EQ(curves[0].at("tangential_mm"), curves[0].at("sagittal_mm"));
  EXPECT_GT(std::abs(curves.back().at("tangential_mm").get<double>() -
                     curves.back().at("sagittal_mm").get<double>()),
            0.1);

  const auto text = testing::runProcess(
      lenslab("analyze --only distortion,field_curvature " + lensPath("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("f tan theta"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("tangential"), std::string::npos) << text.out;
}

// A film beyond the lens's coverage: the curves end at the coverage's edge (issue 38,
// optics/field_coverage.h), every point a number, none past it.
TEST_F(AnalyzeDistortion, FieldsNoRayReachesAreNullWithAReason) {
  const auto json = analyzeJson(lensPath("dgauss-50mm.dat") +
                                " --film-diagonal 400 --only distortion,field_curvature");
  for (const char* key : {"distortion", "field_curvature"}) {
    const auto& last = json.at(key).back();
    EXPECT_TRUE(last.at("field_angle_deg").is_number()) << key;
    EXPECT_LT(last.at("image_height_mm").get<double>(), 200.0) << key;
    EXPECT_TRUE(json.at(key)[1].at("field_angle_deg").is_number()) << key;
  }
}

TEST_F(AnalyzeDistortion, AnAfocalLensIsRefusedWithAReason) {
  const std::string lens = writeFile("opening.dat", "0 30 0 20\n");
  const auto result = testing::runProcess(
      lenslab("analyze --json --film-distance 30 --only distortion,field_curvature " + lens),
      scratch);
  EXPECT_EQ(result.exitCode, 1);
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_TRUE(json.at("distortion").is_null());
  EXPECT_NE(json.at("unavailable").at("field_curvature").get<std::string>().find("afocal"),
            std::string::npos);
  EXPECT_NE(result.err.find("afocal"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace lenslab
