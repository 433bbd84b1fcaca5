// `lenslab info` and `lenslab focus` with the iris opened past the rims, the keys that say which
// aperture limits the axial beam, and a lens that forms no image reported the same way by both
// (issue 20).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

std::string bundled(const std::string& name) {
  return std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + name;
}

// True when every number in the document is finite (nlohmann writes NaN and infinity as null,
// but a NaN that reached a string would still read "nan").
bool allNumbersFinite(const nlohmann::json& j) {
  if (j.is_number()) return std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const auto& item : j)
      if (!allNumbersFinite(item)) return false;
  return true;
}

class LimitingApertureCommands : public ::testing::Test {
 protected:
  std::filesystem::path scratch = testing::makeTestDirectory("limiting-aperture-commands");

  // The bundled double-Gauss 50 mm with the iris (row 6) opened to `irisMm`.
  std::string doubleGaussWithIris(double irisMm) {
    std::ifstream in(bundled("dgauss-50mm.dat"));
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("0\t4.5\t0\t17.1", 0) == 0) line = "0\t4.5\t0\t" + std::to_string(irisMm);
      out << line << "\n";
    }
    const auto path =
        scratch / ("dgauss-iris-" + std::to_string(static_cast<int>(irisMm)) + ".dat");
    std::ofstream(path) << out.str();
    return path.string();
  }

  nlohmann::json infoJson(const std::string& lens) {
    const auto result = testing::runProcess(lenslab("info --json '" + lens + "'"), scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }
};

// Issue 20: in pbrt's double-Gauss 50 mm surface 3 clips the axial beam before the iris does.
TEST_F(LimitingApertureCommands, StockDoubleGaussSaysSurface3LimitsTheBeam) {
  const auto json = infoJson(bundled("dgauss-50mm.dat"));
  EXPECT_EQ(json.at("limiting_aperture_surface").get<int>(), 3);
  EXPECT_FALSE(json.at("limiting_aperture_is_stop").get<bool>());
  EXPECT_EQ(json.at("stop_surface").get<int>(), 6);
  // Paraxially the beam from infinity is 24.29 mm across (the iris's pupil: 24.81 mm): f/2.073.
  EXPECT_NEAR(json.at("paraxial_limited_entrance_pupil_diameter_mm").get<double>(), 24.29, 0.005);
  EXPECT_NEAR(json.at("entrance_pupil").at("diameter_mm").get<double>(), 24.81, 0.005);
  EXPECT_NEAR(json.at("f_number").get<double>(), 50.358 / 24.29, 0.002);
  // Real rays: the widest passing axial ray enters at 24.96 mm. Its working f-number
  // 1 / (2 sin u') is a little faster than EFL / 24.96 = 2.018 would be without aberrations,
  // and slower than the paraxial figure.
  EXPECT_NEAR(json.at("passing_beam_diameter_mm").get<double>(), 24.96, 0.005);
  const double working = json.at("working_f_number").get<double>();
  EXPECT_GT(working, 2.0);
  EXPECT_LT(working, 2.073);
  EXPECT_TRUE(json.at("forms_real_image").get<bool>());
  EXPECT_TRUE(json.at("no_image_reason").is_null());
  EXPECT_GT(json.at("unvignetted_field_of_view_deg").get<double>(), 0.0);
  EXPECT_LT(json.at("unvignetted_field_of_view_deg").get<double>(),
            json.at("field_of_view_deg").get<double>());

  const auto text = testing::runProcess(lenslab("info " + bundled("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(text.exitCode, 0);
  EXPECT_NE(text.out.find("surface 3 limits the axial beam before the iris: working f/2.0"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("field of view, unvignetted"), std::string::npos) << text.out;
}

TEST_F(LimitingApertureCommands, StoppedDownTheIrisLimits) {
  const auto json = infoJson(doubleGaussWithIris(8.0));
  EXPECT_EQ(json.at("limiting_aperture_surface").get<int>(), 6);
  EXPECT_TRUE(json.at("limiting_aperture_is_stop").get<bool>());
  // EFL / the iris's pupil, and the real rays agree with it to a percent at f/4.3.
  const double pupil = json.at("entrance_pupil").at("diameter_mm").get<double>();
  EXPECT_NEAR(json.at("f_number").get<double>(), json.at("efl_mm").get<double>() / pupil, 1e-9);
  EXPECT_NEAR(json.at("working_f_number").get<double>(), json.at("f_number").get<double>(),
              0.01 * json.at("f_number").get<double>());
}

// Opening the iris to 40 mm or 500 mm (its neighbours are 17-18 mm across) used to give f/0.87
// and f/0.07, "no real image", and `focus` failing. The axial beam is still surface 3's, so
// every figure of it, and every focus, is the stock lens's.
TEST_F(LimitingApertureCommands, IrisOpenedPastTheRimsKeepsTheStockFigures) {
  const auto stock = infoJson(bundled("dgauss-50mm.dat"));
  auto focus = [&](const std::string& lens, const std::string& object) {
    const auto result = testing::runProcess(
        lenslab("focus --json --object-distance " + object + " '" + lens + "'"), scratch);
    EXPECT_EQ(result.exitCode, 0) << result.err;
    return result.exitCode == 0
               ? nlohmann::json::parse(result.out).at("film_distance_mm").get<double>()
               : -1.0;
  };
  const double stockInfinity = focus(bundled("dgauss-50mm.dat"), "inf");
  const double stockNear = focus(bundled("dgauss-50mm.dat"), "500");
  for (double iris : {40.0, 500.0}) {
    SCOPED_TRACE(iris);
    const std::string lens = doubleGaussWithIris(iris);
    const auto json = infoJson(lens);
    EXPECT_EQ(json.at("limiting_aperture_surface").get<int>(), 3);
    EXPECT_NEAR(json.at("f_number").get<double>(), stock.at("f_number").get<double>(), 1e-9);
    EXPECT_NEAR(json.at("working_f_number").get<double>(),
                stock.at("working_f_number").get<double>(), 1e-9);
    EXPECT_TRUE(json.at("forms_real_image").get<bool>());
    EXPECT_NEAR(focus(lens, "inf"), stockInfinity, 1e-6);
    EXPECT_NEAR(focus(lens, "500"), stockNear, 1e-6);
    const auto text = testing::runProcess(lenslab("info '" + lens + "'"), scratch);
    EXPECT_EQ(text.out.find("0.87"), std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("0.07"), std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("no real image"), std::string::npos) << text.out;
  }
}

// A random stack of 250 surfaces (fixed seed; a lens file holds at most 256): valid, but light
// from infinity does not come through as an image. `info` and `focus` say so in the same words;
// `focus` fails with one line; the JSON has no NaN.
std::string randomStack(int surfaces, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::ostringstream out;
  out << "# " << surfaces << " random surfaces, seed " << seed << "\n";
  for (int i = 0; i < surfaces; ++i) {
    const bool stop = i == surfaces / 2;
    const double radius =
        stop ? 0.0 : (uniform(rng) < 0.5 ? -1 : 1) * (30.0 + 270.0 * uniform(rng));
    const double thickness = 1.0 + 3.0 * uniform(rng);
    const double index = (stop || i % 2 == 1) ? 1.0 : 1.45 + 0.45 * uniform(rng);
    out << radius << "\t" << thickness << "\t" << index << "\t10\n";
  }
  return out.str();
}

TEST_F(LimitingApertureCommands, ALensThatFormsNoImageIsReportedTheSameWayByInfoAndFocus) {
  const auto path = scratch / "random-250.dat";
  std::ofstream(path) << randomStack(250, 20);
  const std::string lens = path.string();

  const auto json = infoJson(lens);
  EXPECT_TRUE(allNumbersFinite(json));
  ASSERT_FALSE(json.at("forms_real_image").get<bool>());
  const std::string reason = json.at("no_image_reason").get<std::string>();
  EXPECT_EQ(reason.rfind("the lens forms no real image of an object at infinity: ", 0), 0u)
      << reason;
  EXPECT_EQ(json.dump().find("nan"), std::string::npos);

  const auto text = testing::runProcess(lenslab("info '" + lens + "'"), scratch);
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find(reason + "\n"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("nan"), std::string::npos) << text.out;

  for (const std::string arguments : {"--object-distance inf", "--object-distance 1000",
                                      "--film-distance 50", "--json --object-distance inf"}) {
    SCOPED_TRACE(arguments);
    const auto focus =
        testing::runProcess(lenslab("focus " + arguments + " '" + lens + "'"), scratch);
    EXPECT_EQ(focus.exitCode, 1);
    EXPECT_TRUE(focus.out.empty()) << focus.out;
    EXPECT_EQ(focus.err, "lenslab focus: no solution: " + reason + "\n");
  }
}

}  // namespace
}  // namespace lenslab
