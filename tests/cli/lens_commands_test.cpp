// `lenslab info` and `lenslab focus`, run as real processes.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class LensCommands : public ::testing::Test {
 protected:
  std::filesystem::path scratch = testing::makeTestDirectory("lens-commands");

  std::string writeFile(const std::string& name, const std::string& text) {
    const auto path = scratch / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }
};

TEST_F(LensCommands, InfoGivesTheFNumberByAreaOfAShapedStop) {
  // A 10 mm stop 2 mm ahead of a biconvex singlet (R 50, -50, 4 mm of n 1.5): the beam from
  // infinity has the stop's shape. EFL by the thick-lens formula: 1 / (0.5 (0.04 - 2 / 3750)) =
  // 50.6757 mm. A square inscribed in the 5 mm circle passes 2 R^2 = 50 mm^2, the light of a
  // circle 2 sqrt(50 / pi) = 7.9788 mm across: f/6.3513 by area, against f/5.0676 for the circle.
  const std::string rows = "0 2 0 10\n50 4 1.5 20\n-50 48 1 20\n";
  const std::string square = writeFile("square.dat", "# lenslab aperture: blades 4\n" + rows);
  const std::string round = writeFile("round.dat", rows);
  const double efl = 1.0 / (0.5 * (0.04 - 2.0 / 3750.0));

  auto result = testing::runProcess(lenslab("info --json " + square), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("stop_shape").get<std::string>(), "blades 4 curvature 0 rotation 0");
  EXPECT_NEAR(json.at("passing_beam_area_mm2").get<double>(), 50.0, 0.15);
  EXPECT_NEAR(json.at("f_number_by_area").get<double>(), efl / 7.978846, 0.01);
  EXPECT_NEAR(json.at("f_number").get<double>(), efl / 10.0, 0.01);

  result = testing::runProcess(lenslab("info " + square), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("f-number by area"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("stop's blades 4 curvature 0 rotation 0"), std::string::npos)
      << result.out;

  // The circle: its f-number already says it.
  result = testing::runProcess(lenslab("info --json " + round), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("stop_shape").get<std::string>(), "circle");
  EXPECT_TRUE(json.at("f_number_by_area").is_null());
  result = testing::runProcess(lenslab("info " + round), scratch);
  EXPECT_EQ(result.out.find("f-number by area"), std::string::npos) << result.out;
}

TEST_F(LensCommands, InfoJsonHasTheFirstOrderKeys) {
  const auto result =
      testing::runProcess(lenslab("info --json " + lensPath("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_NEAR(json.at("efl_mm").get<double>(), 50.36, 50.36 * 0.0005);
  EXPECT_GT(json.at("bfl_mm").get<double>(), 30.0);
  // The f-number of the beam that passes: surface 3 cuts the paraxial beam from infinity to
  // 24.29 mm before the iris's 24.81 mm pupil would (issue 20), so 50.358 / 24.29 = 2.073, not
  // the iris's 2.03.
  EXPECT_NEAR(json.at("f_number").get<double>(), 2.073, 0.002);
  EXPECT_NEAR(json.at("total_track_mm").get<double>(), 32.04 + 36.77, 1e-9);
  EXPECT_GT(json.at("entrance_pupil").at("diameter_mm").get<double>(), 20.0);
  EXPECT_TRUE(json.at("entrance_pupil").at("position_mm").is_number());
  EXPECT_GT(json.at("exit_pupil").at("diameter_mm").get<double>(), 20.0);
  EXPECT_TRUE(json.at("exit_pupil").at("position_mm").is_number());
  // Surfaces count from 1, as in the viewer's table and the script commands: the stop is the
  // sixth row, surfaces[5] in the JSON array, whose "surface" says 6.
  EXPECT_EQ(json.at("stop_surface").get<int>(), 6);
  EXPECT_EQ(json.at("surfaces").at(5).at("surface").get<int>(), 6);
  EXPECT_FALSE(json.at("afocal").get<bool>());
  EXPECT_NEAR(json.at("field_of_view_real_deg").get<double>(), 46.7, 0.5);
  EXPECT_EQ(json.at("surfaces").size(), 11u);
  EXPECT_TRUE(json.at("surfaces").at(5).at("stop").get<bool>());
}

TEST_F(LensCommands, InfoReadsALensFileWithItsAsphericTermsAndSource) {
  // The square-stop test's singlet as a .lens file, its front surface written as R 100 with
  // A2 = (1/50 - 1/100) / 2: paraxially the R 50 of that test (c + 2 A2 = 1/50), so the same thick-
  // lens EFL, 50.6757 mm. The conic and the r^4 term act beyond the paraxial region and leave it.
  const std::string path = writeFile("asphere.lens",
                                     "lenslab-lens 1\n"
                                     "title Test asphere\n"
                                     "source A hand calculation\n"
                                     "published_efl_mm 50.68\n"
                                     "stop thickness 2 diameter 10\n"
                                     "surface radius 100 thickness 4 nd 1.5 diameter 20 "
                                     "a2 0.005 conic -0.6 a4 -2e-06\n"
                                     "surface radius -50 thickness 48 diameter 20\n");
  const auto result = testing::runProcess(lenslab("info --json " + path), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_NEAR(json.at("efl_mm").get<double>(), 1.0 / (0.5 * (0.04 - 2.0 / 3750.0)), 1e-9);
  EXPECT_EQ(json.at("title"), "Test asphere");
  EXPECT_EQ(json.at("source"), "A hand calculation");
  EXPECT_EQ(json.at("published_efl_mm").get<double>(), 50.68);
  const auto& front = json.at("surfaces").at(1);
  EXPECT_EQ(front.at("conic").get<double>(), -0.6);
  EXPECT_EQ(front.at("aspheric_coefficients"),
            nlohmann::json::parse(R"({"2": 0.005, "4": -2e-06})"));
  const auto& rear = json.at("surfaces").at(2);
  EXPECT_EQ(rear.at("conic").get<double>(), 0.0);
  EXPECT_EQ(rear.at("aspheric_coefficients"), nlohmann::json::object());
  // A .dat file has no title: the key is left out rather than given empty.
  const std::string dat = writeFile("plain.dat", "0 2 0 10\n50 4 1.5 20\n-50 48 1 20\n");
  const auto plain = testing::runProcess(lenslab("info --json " + dat), scratch);
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("title"));
  // The text form names the lens and its source.
  const auto text = testing::runProcess(lenslab("info " + path), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_EQ(text.out.rfind("Test asphere\nsource: A hand calculation\n", 0), 0u) << text.out;
  EXPECT_NE(text.out.find("published focal length"), std::string::npos) << text.out;
}

TEST_F(LensCommands, InfoTextAndWavelengthAndFilmDiagonal) {
  const auto text = testing::runProcess(lenslab("info " + lensPath("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("effective focal length"), std::string::npos);
  EXPECT_NE(text.out.find("stop is surface 6 (counted from 1)"), std::string::npos) << text.out;
  // A lens without Abbe numbers (the wide-angle's source gives none): the same EFL at any
  // wavelength...
  auto efl = [&](const std::string& lens, const std::string& extra) {
    const auto r =
        testing::runProcess(lenslab("info --json " + extra + " " + lensPath(lens)), scratch);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  EXPECT_EQ(efl("wide-22mm.dat", "--wavelength 450").at("efl_mm"),
            efl("wide-22mm.dat", "").at("efl_mm"));
  // ...but the 100 mm double-Gauss with V_d focuses blue shorter, and so does the 50 mm.
  EXPECT_LT(efl("dgauss-100mm.dat", "--wavelength 486.13").at("efl_mm").get<double>(),
            efl("dgauss-100mm.dat", "--wavelength 656.27").at("efl_mm").get<double>());
  EXPECT_LT(efl("dgauss-50mm.dat", "--wavelength 486.13").at("efl_mm").get<double>(),
            efl("dgauss-50mm.dat", "--wavelength 656.27").at("efl_mm").get<double>());
  const auto wide = efl("dgauss-50mm.dat", "--film-diagonal 70");
  EXPECT_EQ(wide.at("film_diagonal_mm").get<double>(), 70.0);
  EXPECT_GT(wide.at("field_of_view_deg").get<double>(),
            efl("dgauss-50mm.dat", "").at("field_of_view_deg").get<double>());
}

// A file that states its design wavelengths: info and analyze trace at its primary one unless
// --wavelength says otherwise, and say which. Thorlabs' aspheric singlet is specified at 780 nm
// (PWAV 1, WAVM 1 0.78): its catalogue EFL 15 mm, OpticStudio's 14.9956 (SOURCES.md).
TEST_F(LensCommands, InfoAndAnalyzeUseTheLensesDesignWavelength) {
  const std::string thorlabs = std::string("'") + LENSLAB_SOURCE_DIR +
                               "/../shared/reference/import/optiland/zemax/"
                               "lens_thorlabs_iso_8859_1.zmx'";
  auto json = [&](const std::string& arguments) {
    const auto r = testing::runProcess(lenslab(arguments), scratch);
    EXPECT_EQ(r.exitCode, 0) << arguments << "\n" << r.err;
    return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
  };
  const auto design = json("info --json " + thorlabs);
  EXPECT_DOUBLE_EQ(design.value("wavelength_nm", 0.0), 780.0);
  EXPECT_EQ(design.value("wavelength_from", ""), "design");
  EXPECT_NEAR(design.value("efl_mm", 0.0), 14.9956, 5e-4);
  // --wavelength wins; at the d line the singlet's EFL is shorter (higher index).
  const auto given = json("info --json --wavelength 587.56 " + thorlabs);
  EXPECT_DOUBLE_EQ(given.value("wavelength_nm", 0.0), 587.56);
  EXPECT_EQ(given.value("wavelength_from", ""), "option");
  EXPECT_LT(given.value("efl_mm", 0.0), 14.99);
  // A pbrt .dat file states none: the d line.
  const auto plain = json("info --json " + lensPath("dgauss-50mm.dat"));
  EXPECT_DOUBLE_EQ(plain.value("wavelength_nm", 0.0), 587.56);
  EXPECT_EQ(plain.value("wavelength_from", ""), "default");
  // The text says which.
  const auto text = testing::runProcess(lenslab("info " + thorlabs), scratch);
  EXPECT_NE(text.out.find("at 780.00 nm (the lens's primary design wavelength)"), std::string::npos)
      << text.out;
  // analyze the same.
  const auto analyzed = json("analyze --json --only seidel " + thorlabs);
  EXPECT_DOUBLE_EQ(analyzed.value("wavelength_nm", 0.0), 780.0);
  EXPECT_EQ(analyzed.value("wavelength_from", ""), "design");
  const auto analyzedGiven = json("analyze --json --only seidel --wavelength 550 " + thorlabs);
  EXPECT_DOUBLE_EQ(analyzedGiven.value("wavelength_nm", 0.0), 550.0);
  EXPECT_EQ(analyzedGiven.value("wavelength_from", ""), "option");
}

// A file that states its fields as image heights (a patent's Y' without an angle of view):
// analyze's film is twice the largest (12 mm -> 24 mm) and its fields the design's, {0, 12 mm}
// as fractions {0, 1}; the options still win.
TEST_F(LensCommands, AnalyzeTakesTheFilmFromTheDesignImageHeight) {
  const std::string table =
      writeFile("image-height.txt",
                "Fno 4.0  Y' 12.0\nSurface r d nd vd\n1 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n"
                "4 -80 40\n");
  auto json = [&](const std::string& arguments) {
    const auto r = testing::runProcess(lenslab(arguments), scratch);
    EXPECT_EQ(r.exitCode, 0) << arguments << "\n" << r.err;
    return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
  };
  const auto design = json("analyze --json --only seidel " + table);
  EXPECT_DOUBLE_EQ(design.value("film_diagonal_mm", 0.0), 24.0);
  EXPECT_EQ(design.value("film_diagonal_from", ""), "design");
  EXPECT_EQ(design.value("field_fractions", std::vector<double>{}),
            (std::vector<double>{0.0, 1.0}));
  const auto given = json("analyze --json --only seidel --film-diagonal 43.27 " + table);
  EXPECT_DOUBLE_EQ(given.value("film_diagonal_mm", 0.0), 43.27);
  EXPECT_EQ(given.value("film_diagonal_from", ""), "option");
  EXPECT_EQ(given.value("field_fractions", std::vector<double>{}),
            (std::vector<double>{0.0, 0.7, 1.0}));
  const auto fields = json("analyze --json --only seidel --fields 0,0.5 " + table);
  EXPECT_DOUBLE_EQ(fields.value("film_diagonal_mm", 0.0), 24.0);
  EXPECT_EQ(fields.value("field_fractions", std::vector<double>{}),
            (std::vector<double>{0.0, 0.5}));
  // A lens whose file states no fields: the full-frame default.
  EXPECT_EQ(json("analyze --json --only seidel " + lensPath("dgauss-50mm.dat"))
                .value("film_diagonal_from", ""),
            "default");
}

// The chromatic focal shift (F - C back focus from infinity) of a plano-convex singlet, against
// the thick-lens formula with indices from the two-term Cauchy fit to n_d and V_d worked here;
// null (and a dash with the reason in the text) without V_d.
TEST_F(LensCommands, InfoGivesTheChromaticFocalShift) {
  const double nD = 1.6, V = 30.0, R = 60.0, t = 4.0;
  const std::string singlet = writeFile("singlet.dat", "60 4 1.6 20 30\ninf 1 1 20\n0 95 0 18\n");
  const auto json = testing::runProcess(lenslab("info --json " + singlet), scratch);
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const double lF = 486.13, lD = 587.56, lC = 656.27;
  const double B = (nD - 1.0) / V / (1.0 / (lF * lF) - 1.0 / (lC * lC));
  const double A = nD - B / (lD * lD);
  const auto backFocus = [&](double l) {
    const double n = A + B / (l * l);
    return R / (n - 1.0) - t / n;
  };
  const double expected = backFocus(lF) - backFocus(lC);  // about -3.3 mm
  EXPECT_NEAR(nlohmann::json::parse(json.out).at("chromatic_focal_shift_mm").get<double>(),
              expected, 1e-9);
  const auto text = testing::runProcess(lenslab("info " + singlet), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  char line[64];
  std::snprintf(line, sizeof line, "%.4f mm", expected);
  EXPECT_NE(text.out.find(line), std::string::npos) << text.out;
  // No V_d: null, and the text says why.
  const auto wide =
      testing::runProcess(lenslab("info --json " + lensPath("wide-22mm.dat")), scratch);
  ASSERT_EQ(wide.exitCode, 0) << wide.err;
  EXPECT_TRUE(nlohmann::json::parse(wide.out).at("chromatic_focal_shift_mm").is_null());
  const auto wideText = testing::runProcess(lenslab("info " + lensPath("wide-22mm.dat")), scratch);
  EXPECT_NE(wideText.out.find("Abbe number"), std::string::npos) << wideText.out;
}

TEST_F(LensCommands, FocusPrintsTheFilmDistance) {
  const auto result = testing::runProcess(
      lenslab("focus --json --object-distance 2000 " + lensPath("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  const double film = json.at("film_distance_mm").get<double>();
  // Newton: x' = f^2 / x with x ~ 2000 - 70 - 23 mm from the front focal point: ~1.3 mm.
  EXPECT_GT(film, 36.1 + 1.0);
  EXPECT_LT(film, 36.1 + 1.8);
  const auto back =
      testing::runProcess(lenslab("focus --json --film-distance " + std::to_string(film) + " " +
                                  lensPath("dgauss-50mm.dat")),
                          scratch);
  ASSERT_EQ(back.exitCode, 0) << back.err;
  EXPECT_NEAR(nlohmann::json::parse(back.out).at("object_distance_mm").get<double>(), 2000.0, 0.1);
  const auto infinity = testing::runProcess(
      lenslab("focus --object-distance inf " + lensPath("dgauss-50mm.dat")), scratch);
  EXPECT_EQ(infinity.exitCode, 0) << infinity.err;
  EXPECT_NE(infinity.out.find("infinity"), std::string::npos);
}

// Distances read as the viewer shows them: "at infinity", "3.600 m", never "infinity mm" or
// "3600.000000 mm".
TEST_F(LensCommands, FocusTextGivesDistancesWithTheirUnits) {
  const std::string lens = lensPath("dgauss-50mm.dat");
  const auto infinity =
      testing::runProcess(lenslab("focus --object-distance inf " + lens), scratch);
  ASSERT_EQ(infinity.exitCode, 0) << infinity.err;
  EXPECT_NE(infinity.out.find("focuses an object at infinity\n"), std::string::npos)
      << infinity.out;
  const auto near = testing::runProcess(lenslab("focus --object-distance 3600 " + lens), scratch);
  ASSERT_EQ(near.exitCode, 0) << near.err;
  EXPECT_NE(near.out.find("focuses an object at 3.600 m from the film\n"), std::string::npos)
      << near.out;
  // And back: the film distance for 3.6 m focuses an object 3.600 m away.
  const auto json =
      testing::runProcess(lenslab("focus --json --object-distance 3600 " + lens), scratch);
  const double film = nlohmann::json::parse(json.out).at("film_distance_mm").get<double>();
  char filmText[32];
  std::snprintf(filmText, sizeof filmText, "%.9f", film);
  const auto back = testing::runProcess(
      lenslab("focus --film-distance " + std::string(filmText) + " " + lens), scratch);
  ASSERT_EQ(back.exitCode, 0) << back.err;
  EXPECT_NE(back.out.find("focuses an object at 3.600 m from the film\n"), std::string::npos)
      << back.out;
}

// Film distances print the digits they have (six significant at most), not "36.770000 mm".
TEST_F(LensCommands, FocusTextGivesFilmDistancesWithTheirOwnDigits) {
  const std::string lens = lensPath("dgauss-50mm.dat");
  const auto given = testing::runProcess(lenslab("focus --film-distance 36.77 " + lens), scratch);
  ASSERT_EQ(given.exitCode, 0) << given.err;
  EXPECT_EQ(given.out.rfind("film distance 36.77 mm focuses", 0), 0u) << given.out;
  const auto found = testing::runProcess(lenslab("focus --object-distance inf " + lens), scratch);
  ASSERT_EQ(found.exitCode, 0) << found.err;
  // "film distance 36.8439 mm (rear vertex to film) ...": a number of at most six digits.
  const std::string number = found.out.substr(14, found.out.find(" mm") - 14);
  EXPECT_LE(number.size(), 7u) << found.out;
  EXPECT_EQ(number.find("0000"), std::string::npos) << found.out;
}

TEST_F(LensCommands, FocusWithNoSolutionSaysSoAndFails) {
  const auto result = testing::runProcess(
      lenslab("focus --object-distance 100 " + lensPath("dgauss-50mm.dat")), scratch);
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("no solution"), std::string::npos) << result.err;
}

TEST_F(LensCommands, FocusReportsTheClosestFocusItReallyFinds) {
  // 196 mm is too close for the double-Gauss, 197 mm is not; the message used to say "about
  // 4 x EFL = 201.433 mm". It now gives the limit the solver found, which lies between.
  const auto near = testing::runProcess(
      lenslab("focus --object-distance 196 " + lensPath("dgauss-50mm.dat")), scratch);
  EXPECT_EQ(near.exitCode, 1);
  const std::string label = "the closest focus is ";
  const auto at = near.err.find(label);
  ASSERT_NE(at, std::string::npos) << near.err;
  const double limit = std::strtod(near.err.c_str() + at + label.size(), nullptr);
  EXPECT_GT(limit, 196.0) << near.err;
  EXPECT_LT(limit, 197.0) << near.err;
  EXPECT_EQ(near.err.find("4 x EFL"), std::string::npos) << near.err;
  const auto far = testing::runProcess(
      lenslab("focus --json --object-distance 197 " + lensPath("dgauss-50mm.dat")), scratch);
  ASSERT_EQ(far.exitCode, 0) << far.err;
  EXPECT_GT(nlohmann::json::parse(far.out).at("film_distance_mm").get<double>(), 70.0);
}

TEST_F(LensCommands, NumericOptionsMustBePositiveFiniteNumbers) {
  const std::string lens = lensPath("dgauss-50mm.dat");
  for (const std::string& arguments :
       {"info --wavelength nan " + lens, "info --wavelength inf " + lens,
        "info --wavelength 0 " + lens, "info --wavelength 5000 " + lens,
        "info --film-diagonal nan " + lens, "info --film-diagonal 0 " + lens,
        "info --film-diagonal -3 " + lens, "info --film-diagonal inf " + lens,
        "info --film-diagonal 2x " + lens, "focus --film-distance nan " + lens,
        "focus --film-distance inf " + lens, "focus --film-distance 0 " + lens,
        "focus --film-distance -1 " + lens, std::string("render --exposure nan scene.pbrt"),
        std::string("render --exposure inf scene.pbrt")}) {
    const auto result = testing::runProcess(lenslab(arguments), scratch);
    // A usage error (2), reported against the option, not against the lens file.
    EXPECT_EQ(result.exitCode, 2) << arguments << ": " << result.err;
    const std::string option = arguments.substr(
        arguments.find("--"), arguments.find(' ', arguments.find("--")) - arguments.find("--"));
    EXPECT_NE(result.err.find(option), std::string::npos) << arguments << ": " << result.err;
    EXPECT_EQ(result.err.find(".dat:"), std::string::npos) << arguments << ": " << result.err;
    // Short: no DBL_MAX spelled out in the message.
    EXPECT_EQ(result.err.find("17976931348623157"), std::string::npos) << result.err;
    EXPECT_TRUE(result.out.empty()) << arguments;
  }
  const auto nan = testing::runProcess(lenslab("info --film-diagonal nan " + lens), scratch);
  EXPECT_NE(nan.err.find("--film-diagonal: 'nan' is not a positive finite number"),
            std::string::npos)
      << nan.err;
  // Ordinary values still work, with a leading '+' too.
  for (const std::string& arguments :
       {"info --film-diagonal 70 --wavelength 486.13 " + lens,
        "info --film-diagonal +43.27 " + lens, "focus --film-distance 37.5 " + lens}) {
    const auto result = testing::runProcess(lenslab(arguments), scratch);
    EXPECT_EQ(result.exitCode, 0) << arguments << ": " << result.err;
  }
}

TEST_F(LensCommands, AfocalLensHasNullFocalLengths) {
  // A plane-parallel plate has zero power: no focal lengths, not 0 mm ones.
  const std::string plate = writeFile("plate.dat", "inf 5 1.5 20\ninf 5 1 20\n0 10 0 10\n");
  const auto json = testing::runProcess(lenslab("info --json " + plate), scratch);
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const auto data = nlohmann::json::parse(json.out);
  EXPECT_TRUE(data.at("afocal").get<bool>());
  for (const char* key : {"efl_mm", "bfl_mm", "ffl_mm", "front_principal_plane_mm",
                          "rear_principal_plane_mm", "f_number", "field_of_view_deg"})
    EXPECT_TRUE(data.at(key).is_null()) << key << ": " << data.at(key);
  EXPECT_EQ(data.at("stop_surface").get<int>(), 3);
  const auto text = testing::runProcess(lenslab("info " + plate), scratch);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("afocal (infinite)"), std::string::npos) << text.out;
  for (const char* label : {"effective focal length", "back focal length", "front focal length",
                            "principal plane", "f-number"}) {
    const auto at = text.out.find(label);
    ASSERT_NE(at, std::string::npos) << label;
    const std::string line = text.out.substr(at, text.out.find('\n', at) - at);
    EXPECT_NE(line.find("afocal (infinite)"), std::string::npos) << line;
    EXPECT_EQ(line.find("0.0000"), std::string::npos) << line;  // not a focal length of 0 mm
  }
  // A lens with power is not afocal.
  const auto lens = testing::runProcess(lenslab("info " + lensPath("dgauss-50mm.dat")), scratch);
  EXPECT_EQ(lens.out.find("afocal"), std::string::npos) << lens.out;
}

TEST_F(LensCommands, UsageErrorsExit2) {
  for (const char* arguments : {"info", "focus", "info --wavelength -3 x.dat",
                                "focus --object-distance 5 --film-distance 5 x.dat"}) {
    const auto result = testing::runProcess(lenslab(arguments), scratch);
    EXPECT_EQ(result.exitCode, 2) << arguments << ": " << result.err;
  }
  const auto notANumber = testing::runProcess(
      lenslab("focus --object-distance far " + lensPath("dgauss-50mm.dat")), scratch);
  EXPECT_EQ(notANumber.exitCode, 2) << notANumber.err;
}

TEST_F(LensCommands, BadLensFilesGiveFileLineColumnAndExit1) {
  struct Case {
    std::string name, text, expected;
  };
  const Case cases[] = {
      {"garbage.dat", "50 5 1.5 20\n0 5 zz 10\n-50 40 1 20\n", ":2:5: error: "},
      {"short.dat", "50 5 1.5 20\n0 5 0\n", ":2:6: error: "},
      {"empty.dat", "", ":1:1: error: "},
      {"binary.dat",
       std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\0",
                   10),
       ":1:"},
      {"nan.dat", "50 5 1.5 nan\n0 5 0 10\n-50 40 1 20\n", ":1:10: error: "},
      {"nostop.dat", "50 5 1.5 20\n-50 40 1 20\n", ":1:1: error: "},
      {"huge.dat", "50 5 1.5 20\n0 5 0 10\n-50 1e300 1 20\n",
       ":3:5: error: thickness 1e300 is beyond"},
      // Surfaces are named counting from 1, as everywhere users see them.
      {"crossing.dat", "12 1 1.5 20\n-12 5 1 20\n0 40 0 10\n",
       ":2:1: error: surface 2: crosses the previous surface (surface 1)"},
  };
  for (const auto& c : cases) {
    const std::string path = writeFile(c.name, c.text);
    for (const char* command : {"info", "focus --object-distance 1000"}) {
      const auto result = testing::runProcess(lenslab(std::string(command) + " " + path), scratch);
      EXPECT_EQ(result.exitCode, 1) << c.name << ": " << result.err;
      EXPECT_NE(result.err.find(path + c.expected), std::string::npos)
          << c.name << ": " << result.err;
      EXPECT_TRUE(result.out.empty()) << c.name;
    }
  }
  const auto missing =
      testing::runProcess(lenslab("info " + (scratch / "missing.dat").string()), scratch);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("missing.dat:1:1: error: no such file"), std::string::npos)
      << missing.err;
}

TEST_F(LensCommands, ReadsTheCourseReferenceFiles) {
  for (const char* name :
       {"dgauss.50mm.dat", "fisheye.10mm.dat", "telephoto.250mm.dat", "wide.22mm.dat"}) {
    const auto result =
        testing::runProcess(lenslab(std::string("info --json ") + LENSLAB_SOURCE_DIR +
                                    "/../shared/reference/lenses/" + name),
                            scratch);
    EXPECT_EQ(result.exitCode, 0) << name << ": " << result.err;
  }
}

// Issue 41: every command opens an OpticStudio .zmx, as the viewer's doors do (they all read
// through optics::readLensFile). Edmund's #47728 asphere: Edmund gives EFL 22.5 mm.
TEST_F(LensCommands, EveryCommandOpensAZmx) {
  const std::string zmx =
      std::string(LENSLAB_SOURCE_DIR) + "/../shared/reference/import/optiland/zemax/lens2.zmx";
  ASSERT_TRUE(std::filesystem::exists(zmx)) << zmx;
  auto result = testing::runProcess(lenslab("info --json '" + zmx + "'"), scratch);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_NEAR(json.at("efl_mm").get<double>(), 22.5, 0.01);
  EXPECT_EQ(json.at("title").get<std::string>(), "47728 Asphere F/1.5");
  for (const std::string& command : {"focus '" + zmx + "' --object-distance 1000",
                                     "analyze '" + zmx + "' --only relative_illumination"}) {
    result = testing::runProcess(lenslab(command), scratch);
    EXPECT_EQ(result.exitCode, 0) << command << ": " << result.err;
  }
  // render --lens, and a scene's "string lensfile".
  const std::string world =
      "WorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n"
      "Shape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n";
  writeFile("perspective.pbrt", "LookAt 0 0 4  0 0 0  0 1 0\nCamera \"perspective\"\n" + world);
  writeFile("realistic.pbrt",
            "LookAt 0 0 4  0 0 0  0 1 0\nCamera \"realistic\" "
            "\"string lensfile\" \"" +
                zmx + "\" \"float aperturediameter\" [5]\n" + world);
  for (const std::string& command :
       {"render '" + (scratch / "perspective.pbrt").string() + "' --lens '" + zmx +
            "' --spp 2 --resolution 24x16 --out '" + (scratch / "a.png").string() + "'",
        "render '" + (scratch / "realistic.pbrt").string() +
            "' --spp 2 --resolution 24x16 --out '" + (scratch / "b.png").string() + "'"}) {
    result = testing::runProcess(lenslab(command), scratch);
    EXPECT_EQ(result.exitCode, 0) << command << ": " << result.err;
  }
  EXPECT_TRUE(std::filesystem::exists(scratch / "a.png"));
  EXPECT_TRUE(std::filesystem::exists(scratch / "b.png"));
}

}  // namespace
}  // namespace lenslab
