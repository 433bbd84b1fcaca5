// `lenslab analyze`, run as a real process: its relative-illumination JSON against the closed
// form for a bare circular opening, and its options.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cli/analyze_test_fixture.h"
#include "cli/headless_lenslab.h"
#include "common/distance_text.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class AnalyzeCommand : public AnalyzeTest {
 protected:
  AnalyzeCommand() : AnalyzeTest("analyze-command") {}
};

// A film point offset h below a circular opening of radius a at distance z receives
// E = pi (1 - (z^2 + h^2 - a^2) / sqrt((z^2 + h^2 + a^2)^2 - 4 a^2 h^2)) / 2 (configuration factor
// from a differential area to a parallel disk), and the chief ray runs straight to the opening's
// centre, so cos4 = (z^2 / (z^2 + h^2))^2.
TEST_F(AnalyzeCommand, RelativeIlluminationOfABareOpeningFollowsTheClosedForm) {
  const std::string lens =
      writeFile("opening.dat", "# a 20 mm stop, 30 mm from the film\n0 30 0 20\n");
  const auto json =
      analyzeJson(lens + " --film-distance 30 --film-diagonal 60 --only relative_illumination");
  ASSERT_TRUE(json.contains("relative_illumination"));
  EXPECT_EQ(json.at("film_distance_mm").get<double>(), 30.0);
  EXPECT_EQ(json.at("film_diagonal_mm").get<double>(), 60.0);
  const auto& points = json.at("relative_illumination");
  ASSERT_EQ(points.size(), 64u);
  auto irradiance = [](double h) {
    const double a = 10.0, z = 30.0, s = z * z + h * h + a * a;
    return 0.5 * std::numbers::pi *
           (1.0 - (z * z + h * h - a * a) / std::sqrt(s * s - 4 * a * a * h * h));
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const double h = p.at("image_height_mm").get<double>();
    EXPECT_NEAR(h, 30.0 * i / 63.0, 1e-9);
    const double total = irradiance(h) / irradiance(0.0);
    EXPECT_NEAR(p.at("total").get<double>(), total, 5e-4) << "h = " << h;
    const double cos4 = std::pow(30.0 * 30.0 / (30.0 * 30.0 + h * h), 2);
    EXPECT_NEAR(p.at("cos4").get<double>(), cos4, 1e-9);
    EXPECT_NEAR(p.at("vignetting").get<double>(), total / cos4, 1e-3);
    EXPECT_EQ(p.at("clipped_by"), nlohmann::json::array({1}));  // surfaces count from 1
    // The opening is the rear element's disk itself, so the course's sampling sees it all.
    EXPECT_NEAR(p.at("rear_disk_total").get<double>(), total, 5e-4);
  }
}

TEST_F(AnalyzeCommand, FocusesFirstWhenGivenAnObjectDistance) {
  const auto focus = testing::runProcess(
      lenslab("focus --json --object-distance 2000 " + lensPath("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(focus.exitCode, 0) << focus.err;
  const double film = nlohmann::json::parse(focus.out).at("film_distance_mm").get<double>();
  const auto json = analyzeJson(lensPath("dgauss-50mm.dat") + " --object-distance 2000");
  EXPECT_NEAR(json.at("film_distance_mm").get<double>(), film, 1e-9);
  EXPECT_EQ(json.at("object_distance_mm").get<double>(), 2000.0);
  const auto given = analyzeJson(lensPath("dgauss-50mm.dat") + " --film-distance 40 --points 65");
  EXPECT_EQ(given.at("film_distance_mm").get<double>(), 40.0);
  EXPECT_EQ(given.at("relative_illumination").size(), 65u);
  // The double-Gauss darkens toward the corner, and the rims do part of it.
  const auto& corner = given.at("relative_illumination").back();
  EXPECT_LT(corner.at("total").get<double>(), 0.6);
  EXPECT_LT(corner.at("vignetting").get<double>(), 0.9);
  EXPECT_FALSE(corner.at("clipped_by").empty());
}

// Without --film-distance the lens is focused at the object distance, infinity by default, as
// the help says: the telephoto's file puts its film where it focuses 3.7 m, where the on-axis
// spot of an object at infinity is over a millimetre wide.
TEST_F(AnalyzeCommand, FocusesAtInfinityByDefault) {
  const std::string telephoto = lensPath("telephoto-250mm.dat");
  const auto focus =
      testing::runProcess(lenslab("focus --json --object-distance inf " + telephoto), scratch);
  ASSERT_EQ(focus.exitCode, 0) << focus.err;
  const double infinityFilm = nlohmann::json::parse(focus.out).at("film_distance_mm").get<double>();
  ASSERT_GT(std::abs(infinityFilm - 123.7439), 1.0);  // the file's film is elsewhere
  auto axialSpotUm = [](const nlohmann::json& json) {
    return json.at("spot").at("fields")[0].at("rms_radius_um").get<double>();
  };
  const auto byDefault = analyzeJson("--only spot " + telephoto);
  const auto atInfinity = analyzeJson("--only spot --object-distance inf " + telephoto);
  const auto atFileFilm = analyzeJson("--only spot --film-distance 123.7439 " + telephoto);
  EXPECT_NEAR(byDefault.at("film_distance_mm").get<double>(), infinityFilm, 1e-9);
  EXPECT_EQ(axialSpotUm(byDefault), axialSpotUm(atInfinity));
  EXPECT_LT(axialSpotUm(byDefault), 50.0);
  EXPECT_GT(axialSpotUm(atFileFilm), 20.0 * axialSpotUm(byDefault));
  EXPECT_EQ(byDefault.at("focused_by"), "object_distance");
  EXPECT_TRUE(byDefault.at("focused_at_infinity").get<bool>());
  EXPECT_TRUE(byDefault.at("object_in_focus").get<bool>());

  // A given film distance stays, and the header says where it focuses: at the distance `focus`
  // finds for it, with the object at infinity out of focus.
  const auto reverse =
      testing::runProcess(lenslab("focus --json --film-distance 123.7439 " + telephoto), scratch);
  ASSERT_EQ(reverse.exitCode, 0) << reverse.err;
  const double focusedMm =
      nlohmann::json::parse(reverse.out).at("object_distance_mm").get<double>();
  EXPECT_EQ(atFileFilm.at("focused_by"), "film_distance");
  EXPECT_NEAR(atFileFilm.at("focus_object_distance_mm").get<double>(), focusedMm, 1e-9);
  EXPECT_FALSE(atFileFilm.at("focused_at_infinity").get<bool>());
  EXPECT_FALSE(atFileFilm.at("object_in_focus").get<bool>());
  EXPECT_TRUE(atFileFilm.at("object_at_infinity").get<bool>());
  const auto text = testing::runProcess(
      lenslab("analyze --only spot --film-distance 123.7439 " + telephoto), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  const std::string header = text.out.substr(0, text.out.find('\n'));
  EXPECT_NE(header.find("as given, focused at " + distanceText(focusedMm) + " from the film"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("object at infinity (out of focus)"), std::string::npos) << header;
  const auto focusedText =
      testing::runProcess(lenslab("analyze --only spot " + telephoto), scratch);
  ASSERT_EQ(focusedText.exitCode, 0) << focusedText.err;
  const std::string focusedHeader = focusedText.out.substr(0, focusedText.out.find('\n'));
  EXPECT_NE(focusedHeader.find("(focused at infinity)"), std::string::npos) << focusedHeader;
  EXPECT_EQ(focusedHeader.find("out of focus"), std::string::npos) << focusedHeader;
}

// A lens that forms no real image of an object at infinity cannot be focused there by default:
// the command says so and why, instead of analysing it at the file's film distance.
TEST_F(AnalyzeCommand, SaysWhyItCannotFocusAtInfinityByDefault) {
  const std::string opening = writeFile("opening.dat", "# a bare 20 mm stop\n0 30 0 20\n");
  const auto refused = testing::runProcess(lenslab("analyze --only spot " + opening), scratch);
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("cannot focus at infinity"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("no real image"), std::string::npos) << refused.err;
  EXPECT_TRUE(refused.out.empty()) << refused.out;
}

TEST_F(AnalyzeCommand, TextTableAndBadOptions) {
  const auto text = testing::runProcess(lenslab("analyze " + lensPath("wide-22mm.dat")), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("vignetting"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("clipped by surfaces"), std::string::npos) << text.out;
  const auto bad = testing::runProcess(
      lenslab("analyze --object-distance near " + lensPath("wide-22mm.dat")), scratch);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--object-distance: 'near'"), std::string::npos) << bad.err;
  // Both: the film stays where it is told, and the object distance only places the object.
  const auto both =
      analyzeJson("--object-distance 5000 --film-distance 20 " + lensPath("wide-22mm.dat"));
  EXPECT_EQ(both.at("film_distance_mm").get<double>(), 20.0);
  EXPECT_EQ(both.at("object_distance_mm").get<double>(), 5000.0);
  EXPECT_FALSE(both.at("object_at_infinity").get<bool>());
  for (const char* option : {"--only relative_illumination,nonsense", "--fields 0,1.2",
                             "--fields 0,nan", "--wavelength 200", "--wavelength 1200"}) {
    const auto refused = testing::runProcess(
        lenslab(std::string("analyze ") + option + " " + lensPath("wide-22mm.dat")), scratch);
    EXPECT_EQ(refused.exitCode, 2) << option;
    EXPECT_NE(refused.err.find(std::string(option).substr(0, 6)), std::string::npos) << refused.err;
  }
  const auto missing = testing::runProcess(lenslab("analyze nothing-here.dat"), scratch);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("nothing-here.dat"), std::string::npos) << missing.err;
}

// --only limits the JSON to the keys it names; the setup is always there.
TEST_F(AnalyzeCommand, OnlyRunsTheNamedAnalyses) {
  const auto json = analyzeJson("--only relative_illumination --fields 0,0.5 --wavelength 656.27 " +
                                lensPath("dgauss-50mm.dat"));
  EXPECT_TRUE(json.contains("relative_illumination"));
  EXPECT_EQ(json.at("field_fractions"), nlohmann::json::array({0.0, 0.5}));
  EXPECT_EQ(json.at("wavelength_nm").get<double>(), 656.27);
  EXPECT_TRUE(json.at("object_at_infinity").get<bool>());
  EXPECT_TRUE(json.at("object_distance_mm").is_null());
}

// A list as a person types it, with spaces after the commas, names the same analyses.
TEST_F(AnalyzeCommand, OnlyAcceptsSpacesAroundTheKeys) {
  const auto json = analyzeJson("--only 'mtf, spot' --fields 0 " + lensPath("dgauss-50mm.dat"));
  EXPECT_TRUE(json.contains("mtf"));
  EXPECT_TRUE(json.contains("spot"));
  EXPECT_FALSE(json.contains("relative_illumination"));
  const auto padded = analyzeJson("--only ' distortion ,seidel ' " + lensPath("dgauss-50mm.dat"));
  EXPECT_TRUE(padded.contains("distortion"));
  EXPECT_TRUE(padded.contains("seidel"));
}

// The fisheye's image circle ends inside the full-frame film: analyze says so in its header and
// its JSON, as the viewer's panels do, and its field 1.0 is the circle's edge, not the film's
// corner (21.6 mm). The double-Gauss covers the film: no warning, field 1.0 at the corner.
TEST_F(AnalyzeCommand, SaysWhenTheFilmCornerIsBeyondTheImageCircle) {
  const auto fisheye = analyzeJson("--only distortion " + lensPath("fisheye-10mm.dat"));
  EXPECT_FALSE(fisheye.at("film_covered").get<bool>());
  const double radiusMm = fisheye.at("field_radius_mm").get<double>();
  EXPECT_LT(radiusMm, 21.0);
  EXPECT_GT(radiusMm, 5.0);
  const std::string warning = fisheye.at("coverage_warning").get<std::string>();
  EXPECT_NE(warning.find("beyond the lens's coverage"), std::string::npos) << warning;
  const auto text = testing::runProcess(
      lenslab("analyze --only distortion " + lensPath("fisheye-10mm.dat")), scratch);
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("warning: " + warning), std::string::npos) << text.out;

  const auto dgauss = analyzeJson("--only distortion " + lensPath("dgauss-50mm.dat"));
  EXPECT_TRUE(dgauss.at("film_covered").get<bool>());
  EXPECT_NEAR(dgauss.at("field_radius_mm").get<double>(),
              0.5 * dgauss.at("film_diagonal_mm").get<double>(), 1e-9);
  EXPECT_FALSE(dgauss.contains("coverage_warning"));
}

// `mtf` of a slow singlet (f/40: a hundredth of a wave of spherical aberration) at its paraxial
// focus, by the thick-lens formulas: the MTF of a circular aperture with the cutoff D / (lambda f);
// a field beyond what the lens images is an entry with nulls and its reason.
TEST_F(AnalyzeCommand, MtfOfASlowSingletIsTheCircularApertureMtf) {
  const double n = 1.5168, r1 = 60.0, r2 = -200.0, t = 5.0, stopMm = 2.5;
  const double power = (n - 1.0) * (1.0 / r1 - 1.0 / r2 + (n - 1.0) * t / (n * r1 * r2));
  const double eflMm = 1.0 / power, backFocusMm = eflMm * (1.0 - (n - 1.0) * t / (n * r1));
  const std::string lens =
      writeFile("singlet.dat",
                "# stop 1 mm in front of a singlet\n0 1 0 2.5\n60 5 1.5168 20\n"
                "-200 100 0 20\n");
  for (const double wavelengthNm : {587.56, 486.13}) {
    const auto json = analyzeJson("--only mtf --fields 0,1 --film-diagonal 10000 --wavelength " +
                                  std::to_string(wavelengthNm) + " --film-distance " +
                                  std::to_string(backFocusMm) + " " + lens);
    const auto& mtf = json.at("mtf");
    EXPECT_NEAR(mtf.at("wavelength_nm").get<double>(), wavelengthNm, 1e-6);
    EXPECT_EQ(mtf.at("pupil_grid").get<int>(), 128);
    ASSERT_EQ(mtf.at("fields").size(), 2u);
    const auto& axis = mtf.at("fields")[0];
    EXPECT_EQ(axis.at("field_angle_deg").get<double>(), 0.0);
    EXPECT_EQ(axis.at("image_height_mm").get<double>(), 0.0);
    const double cutoff = stopMm / (wavelengthNm * 1e-6 * eflMm);
    EXPECT_NEAR(axis.at("cutoff_cycles_per_mm").get<double>(), cutoff, 0.005 * cutoff);
    const auto& frequencies = axis.at("frequencies_cycles_per_mm");
    ASSERT_GT(frequencies.size(), 16u);
    for (std::size_t k = 0; k < frequencies.size(); ++k) {
      const double v = std::min(1.0, frequencies[k].get<double>() / cutoff);
      const double expected = 2.0 / std::numbers::pi * (std::acos(v) - v * std::sqrt(1.0 - v * v));
      EXPECT_NEAR(axis.at("tangential")[k].get<double>(), expected, 0.01) << k;
      EXPECT_NEAR(axis.at("sagittal")[k].get<double>(), expected, 0.01) << k;
      EXPECT_NEAR(axis.at("diffraction_limit")[k].get<double>(), expected, 0.01) << k;
    }
    EXPECT_LT(axis.at("rms_wavefront_error_waves").get<double>(), 0.01);
    // The film's corner lies far beyond the singlet's coverage: the field is at the coverage's
    // edge instead (issue 38, optics/field_coverage.h), not 5000 mm out with no ray.
    const auto& beyond = mtf.at("fields")[1];
    EXPECT_GT(beyond.at("image_height_mm").get<double>(), 0.0);
    EXPECT_LT(beyond.at("image_height_mm").get<double>(), 5000.0);
  }
  const auto text = testing::runProcess(lenslab("analyze --only mtf " + lens), scratch);
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("diffraction MTF"), std::string::npos) << text.out;
}

}  // namespace
}  // namespace lenslab
