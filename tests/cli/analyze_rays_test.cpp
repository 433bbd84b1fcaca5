// `lenslab analyze`'s `ray_fan` and `spot` keys, run as a real process: a bare opening, where
// every ray error is the bundle's geometric spread (a ray through the 20 mm opening at 10 (px, py)
// mm from its centre lands 10 (px, py) mm from the chief ray, object at infinity), the colour
// fans of a singlet with an Abbe number, and a field no ray reaches.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/analyze_test_fixture.h"
#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class AnalyzeRays : public AnalyzeTest {
 protected:
  AnalyzeRays() : AnalyzeTest("analyze-rays") {}
};

TEST_F(AnalyzeRays, BareOpeningFansAndSpotsAreTheBundlesSpread) {
  const std::string lens = writeFile("opening.dat", "0 30 0 20\n");
  const auto json = analyzeJson(
      lens + " --film-distance 30 --only ray_fan,spot --fields 0,0.5 --film-diagonal 40");
  EXPECT_FALSE(json.contains("relative_illumination"));
  const auto& fans = json.at("ray_fan");
  EXPECT_EQ(fans.at("wavelengths_nm"), nlohmann::json::array({587.56}));
  ASSERT_EQ(fans.at("fields").size(), 2u);
  for (const auto& field : fans.at("fields")) {
    EXPECT_TRUE(field.at("field_angle_deg").is_number());
    ASSERT_EQ(field.at("wavelengths").size(), 1u);
    const auto& at = field.at("wavelengths")[0];
    EXPECT_EQ(at.at("wavelength_nm").get<double>(), 587.56);
    for (const char* kind : {"tangential", "sagittal"}) {
      ASSERT_EQ(at.at(kind).size(), 64u) << kind;
      for (const auto& point : at.at(kind)) {
        const double pupil = point.at("pupil").get<double>();
        if (std::abs(pupil) == 1.0) continue;  // grazes the opening's edge
        EXPECT_NEAR(point.at("error_um").get<double>(), 10000.0 * pupil, 1e-3) << kind;
      }
    }
  }
  EXPECT_NEAR(fans.at("fields")[1].at("image_height_mm").get<double>(), 10.0, 1e-12);
  EXPECT_NEAR(fans.at("fields")[1].at("field_angle_deg").get<double>(),
              std::atan(10.0 / 30.0) * 180.0 / M_PI, 1e-6);

  // The spot: the uniform disk of radius 10 mm; parallel rays have no focus, so no Airy disk and
  // no through-focus row, given as nulls, not NaN.
  const auto& spot = json.at("spot");
  EXPECT_TRUE(spot.at("airy_radius_um").is_null());
  for (const auto& field : spot.at("fields")) {
    EXPECT_NEAR(field.at("rms_radius_um").get<double>(), 10000.0 / std::sqrt(2.0), 30.0);
    EXPECT_NEAR(field.at("geo_radius_um").get<double>(), 10000.0, 1.0);
    EXPECT_GE(field.at("rays").size(), 500u);
    for (const auto& ray : field.at("rays"))
      EXPECT_LE(std::hypot(ray[0].get<double>(), ray[1].get<double>()), 10000.0 + 1e-3);
    EXPECT_TRUE(field.at("through_focus").empty());
  }
}

// A plano-convex singlet of BK7-like glass (n_d 1.5168, V_d 64.17): fans at d, F and C; on the
// axis the spot's Airy radius is 1.22 lambda N_w and its through-focus row has five positions.
TEST_F(AnalyzeRays, ALensWithAbbeNumbersHasColourFans) {
  const std::string lens =
      writeFile("singlet.dat", "0 1 0 10\n51.68 4 1.5168 30 64.17\ninf 97.4 1 30\n");
  const auto json = analyzeJson(lens + " --only ray_fan,spot --fields 0,1 --film-diagonal 10");
  EXPECT_EQ(json.at("ray_fan").at("wavelengths_nm"),
            nlohmann::json::array({587.56, 486.13, 656.27}));
  for (const auto& field : json.at("ray_fan").at("fields"))
    EXPECT_EQ(field.at("wavelengths").size(), 3u);
  const auto& spot = json.at("spot");
  const double n = spot.at("working_f_number").get<double>();
  EXPECT_NEAR(n, 10.0, 0.3);  // about f / D = 100 mm / 10 mm
  EXPECT_NEAR(spot.at("airy_radius_um").get<double>(), 1.22 * 0.58756 * n, 1e-6);
  EXPECT_NEAR(spot.at("depth_of_focus_mm").get<double>(), 2.0 * 0.58756e-3 * n * n, 1e-9);
  for (const auto& field : spot.at("fields")) {
    ASSERT_EQ(field.at("through_focus").size(), 5u);
    EXPECT_EQ(field.at("through_focus")[2].at("film_shift_mm").get<double>(), 0.0);
    EXPECT_NEAR(field.at("through_focus")[2].at("rms_radius_um").get<double>(),
                field.at("rms_radius_um").get<double>(), 1e-9);
  }
}

// A film so large that its corner is beyond what the lens can image: that field has null numbers
// and says why, the others are whole, and the command still succeeds.
TEST_F(AnalyzeRays, AFieldNoRayReachesIsNullWithAReason) {
  const auto json = analyzeJson(lensPath("dgauss-50mm.dat") +
                                " --only ray_fan,spot --fields 0,1 --film-diagonal 300");
  for (const char* key : {"ray_fan", "spot"}) {
    const auto& fields = json.at(key).at("fields");
    ASSERT_EQ(fields.size(), 2u);
    EXPECT_TRUE(fields[0].at("field_angle_deg").is_number()) << key;
    EXPECT_FALSE(fields[0].contains("why_not")) << key;
    // Field 1 is at the coverage's edge (issue 38, optics/field_coverage.h), not at the
    // 150 mm corner no ray reaches.
    EXPECT_TRUE(fields[1].at("field_angle_deg").is_number()) << key;
    EXPECT_LT(fields[1].at("image_height_mm").get<double>(), 150.0) << key;
  }

  const auto text = testing::runProcess(
      lenslab("analyze " + lensPath("dgauss-50mm.dat") + " --only ray_fan,spot"), scratch);
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("== ray_fan =="), std::string::npos);
  EXPECT_NE(text.out.find("== spot =="), std::string::npos);
  EXPECT_NE(text.out.find("Airy radius"), std::string::npos);
}

}  // namespace
}  // namespace lenslab
