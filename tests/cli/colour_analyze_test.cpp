// `lenslab analyze` as a real process: the Seidel and colour keys. A plano-convex singlet's focal
// shift against the thick-lens formula (its power (n - 1)/R, its back focus f - t/n) with the glass
// model's Cauchy indices written out here; no chromatic key at all for a lens without V_d.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/analyze_test_fixture.h"
#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class ColourAnalyze : public AnalyzeTest {
 protected:
  ColourAnalyze() : AnalyzeTest("colour-analyze") {}
};

// n(lambda) = a + b / lambda^2 through n_d with n_F - n_C = (n_d - 1) / V_d (optics/glass.h).
double cauchyIndex(double nD, double V, double wavelengthNm) {
  const double F = 486.13, C = 656.27, d = 587.56;
  const double b = (nD - 1.0) / V / (1.0 / (F * F) - 1.0 / (C * C));
  return nD - b / (d * d) + b / (wavelengthNm * wavelengthNm);
}

TEST_F(ColourAnalyze, PlanoConvexFocalShiftFollowsTheThickLensFormula) {
  const double R = 51.68, t = 4.0, nD = 1.5168, V = 64.17;
  const std::string lens = writeFile("plano-convex.dat",
                                     "# plano-convex BK7, stop behind it\n"
                                     "51.68 4 1.5168 25 64.17\n"
                                     "inf 1 1 25\n"
                                     "0 95 0 20\n");
  auto backFocus = [&](double wavelengthNm) {  // from the stop row, 1 mm behind the flat
    const double n = cauchyIndex(nD, V, wavelengthNm);
    return R / (n - 1.0) - t / n - 1.0;
  };
  const auto json = analyzeJson(lens);
  ASSERT_TRUE(json.contains("chromatic_focal_shift_mm"));
  EXPECT_NEAR(json.at("chromatic_focal_shift_mm").get<double>(),
              backFocus(486.13) - backFocus(656.27), 1e-9);
  const auto& curve = json.at("chromatic_focal_shift_curve");
  EXPECT_EQ(curve.at("relative_to_wavelength_nm").get<double>(), 587.56);
  ASSERT_EQ(curve.at("points").size(), 31u);
  for (const auto& point : curve.at("points")) {
    const double wavelength = point.at("wavelength_nm").get<double>();
    EXPECT_NEAR(point.at("focal_shift_mm").get<double>(), backFocus(wavelength) - backFocus(587.56),
                1e-9)
        << wavelength;
  }
  const auto& lateral = json.at("lateral_color_um");
  ASSERT_EQ(lateral.size(), 3u);
  EXPECT_NEAR(lateral[0].at("lateral_color_um").get<double>(), 0.0, 1e-6);
  for (const auto& field : lateral) {
    EXPECT_TRUE(field.at("field_angle_deg").is_number());
    EXPECT_TRUE(field.at("image_height_mm").is_number());
  }
  // The stop behind a positive lens: blue's image is the larger.
  EXPECT_GT(lateral[2].at("lateral_color_um").get<double>(), 0.0);
  const auto& seidel = json.at("seidel");
  ASSERT_EQ(seidel.at("surfaces").size(), 3u);
  EXPECT_EQ(seidel.at("surfaces")[0].at("surface").get<int>(), 1);
  EXPECT_TRUE(seidel.at("total").contains("CL"));
  EXPECT_TRUE(seidel.at("third_order").contains("lateral_color_mm"));
  // No aspheric surface: the list of surfaces whose odd powers the sums leave out is there, empty.
  EXPECT_EQ(seidel.at("odd_aspheric_terms_left_out"), nlohmann::json::array());
  // A finite object moves the images and keeps the keys.
  const auto near = analyzeJson("--object-distance 1000 " + lens);
  EXPECT_LT(near.at("chromatic_focal_shift_mm").get<double>(),
            json.at("chromatic_focal_shift_mm").get<double>());
}

TEST_F(ColourAnalyze, LensWithoutAbbeNumbersHasNoChromaticKeys) {
  // The bundled double-Gauss 50 mm without its V_d column: pbrt's prescription.
  std::ifstream bundled(lensPath("dgauss-50mm.dat"));
  std::string plain, row;
  while (std::getline(bundled, row)) {
    if (row.empty() || row[0] == '#') continue;
    std::istringstream values(row);
    double radius, thickness, index, aperture;
    values >> radius >> thickness >> index >> aperture;
    plain += std::to_string(radius) + " " + std::to_string(thickness) + " " +
             std::to_string(index) + " " + std::to_string(aperture) + "\n";
  }
  const std::string lens = writeFile("dgauss-no-vd.dat", plain);
  const auto json = analyzeJson(lens);
  for (const char* key :
       {"chromatic_focal_shift_mm", "chromatic_focal_shift_curve", "lateral_color_um"})
    EXPECT_FALSE(json.contains(key)) << key;
  const auto& seidel = json.at("seidel");
  ASSERT_EQ(seidel.at("surfaces").size(), 11u);
  for (const auto& surface : seidel.at("surfaces")) {
    EXPECT_FALSE(surface.contains("CL"));
    EXPECT_FALSE(surface.contains("CT"));
  }
  EXPECT_FALSE(seidel.at("total").contains("CL"));
  EXPECT_FALSE(seidel.at("third_order").contains("lateral_color_mm"));
  // The stop row (6) adds nothing; the sum of the rows is the total.
  EXPECT_EQ(seidel.at("surfaces")[5].at("S1").get<double>(), 0.0);
  double s1 = 0.0;
  for (const auto& surface : seidel.at("surfaces")) s1 += surface.at("S1").get<double>();
  EXPECT_NEAR(seidel.at("total").at("S1").get<double>(), s1, 1e-12);

  const auto text =
      testing::runProcess(lenslab("analyze --only chromatic_focal_shift_mm " + lens), scratch);
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("V_d"), std::string::npos) << text.out;
}

TEST_F(ColourAnalyze, AfocalLensIsUnavailableWithAReason) {
  const std::string window = writeFile("window.dat", "inf 5 1.5 20 60\ninf 1 1 20\n0 50 0 10\n");
  const auto result = testing::runProcess(
      lenslab("analyze --json --film-distance 50 --only seidel,chromatic_focal_shift_mm " + window),
      scratch);
  EXPECT_EQ(result.exitCode, 1);
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_TRUE(json.at("seidel").is_null());
  EXPECT_NE(json.at("unavailable").at("seidel").get<std::string>().find("afocal"),
            std::string::npos);
  EXPECT_TRUE(json.at("chromatic_focal_shift_mm").is_null());
  EXPECT_NE(result.err.find("seidel"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace lenslab
