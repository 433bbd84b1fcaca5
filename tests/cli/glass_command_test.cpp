// `lenslab glass`, run as a real process: a catalogue glass's figures against its maker's
// published numbers and an independent evaluation of its datasheet formula, the list against the
// catalogue file, and the bad input (an unknown name, a wavelength outside the formula's range).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/headless_lenslab.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

class GlassCommand : public ::testing::Test {
 protected:
  std::filesystem::path scratch = testing::makeTestDirectory("glass-command");

  testing::ProcessResult run(const std::string& arguments) {
    return testing::runProcess(lenslab("glass " + arguments), scratch);
  }
};

// N-BK7 by SCHOTT's datasheet: n^2 - 1 = sum B_i L^2 / (L^2 - C_i), L in micrometres, with the
// coefficients the datasheet prints. Written out here, not taken from lenslab's formula code.
double schottNbk7Index(double wavelengthNm) {
  const double b[3] = {1.03961212, 0.231792344, 1.01046945};
  const double c[3] = {0.00600069867, 0.0200179144, 103.560653};
  const double l2 = (wavelengthNm / 1000.0) * (wavelengthNm / 1000.0);
  double n2 = 1.0;
  for (int i = 0; i < 3; ++i) n2 += b[i] * l2 / (l2 - c[i]);
  return std::sqrt(n2);
}

TEST_F(GlassCommand, NBk7IndicesMatchSchottsPublishedFigures) {
  const auto result = run("N-BK7 --wavelength 587.5618 486.1327 656.2725 --json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("name").get<std::string>(), "N-BK7");
  EXPECT_EQ(json.at("maker").get<std::string>(), "SCHOTT");
  EXPECT_EQ(json.at("formula").at("kind").get<std::string>(), "sellmeier2");
  EXPECT_DOUBLE_EQ(json.at("range_nm").at("min").get<double>(), 300.0);
  EXPECT_DOUBLE_EQ(json.at("range_nm").at("max").get<double>(), 2500.0);
  const auto& indices = json.at("indices");
  ASSERT_EQ(indices.size(), 3u);
  // SCHOTT's data sheet: n_d = 1.5168, V_d = 64.17.
  EXPECT_NEAR(indices.at(0).at("n").get<double>(), 1.5168, 1e-5);
  EXPECT_NEAR(json.at("n_d").get<double>(), 1.5168, 1e-5);
  EXPECT_NEAR(json.at("v_d").get<double>(), 64.17, 0.01);
  EXPECT_NEAR(json.at("catalog_n_d").get<double>(), 1.5168, 1e-12);
  EXPECT_NEAR(json.at("catalog_v_d").get<double>(), 64.17, 1e-12);
  // F and C lines against the datasheet's Sellmeier formula evaluated above.
  EXPECT_DOUBLE_EQ(indices.at(1).at("wavelength_nm").get<double>(), 486.1327);
  EXPECT_NEAR(indices.at(1).at("n").get<double>(), schottNbk7Index(486.1327), 1e-9);
  EXPECT_DOUBLE_EQ(indices.at(2).at("wavelength_nm").get<double>(), 656.2725);
  EXPECT_NEAR(indices.at(2).at("n").get<double>(), schottNbk7Index(656.2725), 1e-9);
}

TEST_F(GlassCommand, TextGivesTheFormulaRangeAndIndices) {
  const auto result = run("N-BK7 --wavelength 486.1327");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string& out = result.out;
  EXPECT_NE(out.find("N-BK7 (SCHOTT, optical)"), std::string::npos) << out;
  EXPECT_NE(out.find("sellmeier2"), std::string::npos) << out;
  EXPECT_NE(out.find("1.03961212"), std::string::npos) << out;
  EXPECT_NE(out.find("300-2500 nm"), std::string::npos) << out;
  EXPECT_NE(out.find("(catalogue: 1.5168)"), std::string::npos) << out;
  char expected[64];
  std::snprintf(expected, sizeof expected, "n at 486.1327 nm     %.6f", schottNbk7Index(486.1327));
  EXPECT_NE(out.find(expected), std::string::npos) << out;
}

TEST_F(GlassCommand, NamesMatchWithoutCaseHyphensOrSpaces) {
  for (const std::string name : {"nbk7", "'n bk7'", "N-BK7"}) {
    const auto result = run(name + " --json");
    ASSERT_EQ(result.exitCode, 0) << name << ": " << result.err;
    const auto json = nlohmann::json::parse(result.out);
    EXPECT_EQ(json.at("name").get<std::string>(), "N-BK7") << name;
    EXPECT_EQ(json.at("maker").get<std::string>(), "SCHOTT") << name;
  }
}

TEST_F(GlassCommand, ANameInSeveralCataloguesSaysWhichMakerAndMakerChooses) {
  auto result = run("F5 --json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("maker").get<std::string>(), "SCHOTT");
  EXPECT_EQ(json.at("makers"), nlohmann::json({"SCHOTT", "CDGM", "HIKARI"}));
  EXPECT_EQ(json.at("note").get<std::string>(), "F5 is in SCHOTT, CDGM, HIKARI; using SCHOTT's");
  result = run("F5");
  EXPECT_NE(result.out.find("F5 is in SCHOTT, CDGM, HIKARI; using SCHOTT's (--maker chooses)"),
            std::string::npos)
      << result.out;

  // CDGM's F5 (cdgm.csv lists n_d 1.624353), chosen in any case.
  result = run("F5 --maker cdgm --json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("maker").get<std::string>(), "CDGM");
  EXPECT_TRUE(json.at("note").is_null());
  EXPECT_NEAR(json.at("n_d").get<double>(), 1.624353, 1e-5);
}

// The glasses of a catalogue file: its lines after the header, counted here from the file.
std::size_t catalogueRows(const std::string& file) {
  std::ifstream in(std::string(LENSLAB_SOURCE_DIR) + "/data/glass/" + file);
  std::string line;
  std::size_t rows = 0;
  std::getline(in, line);  // the header
  while (std::getline(in, line))
    if (!line.empty()) ++rows;
  return rows;
}

TEST_F(GlassCommand, ListOfAMakerHasEveryRowOfItsCatalogue) {
  const std::size_t rows = catalogueRows("ohara.csv");
  ASSERT_GT(rows, 100u);
  auto result = run("--list --maker OHARA --json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("count").get<std::size_t>(), rows);
  ASSERT_EQ(json.at("glasses").size(), rows);
  for (const auto& glass : json.at("glasses")) {
    EXPECT_EQ(glass.at("maker").get<std::string>(), "OHARA");
    EXPECT_TRUE(glass.at("name").is_string());
    EXPECT_TRUE(glass.at("n_d").is_number() || glass.at("n_d").is_null());
  }
  // The text: a header line, a line per glass, and the count.
  result = run("--list --maker ohara");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::size_t lines = 0;
  for (const char c : result.out) lines += c == '\n';
  EXPECT_EQ(lines, rows + 2);
  EXPECT_NE(result.out.find("(" + std::to_string(rows) + " glasses of OHARA"), std::string::npos);
}

TEST_F(GlassCommand, AnUnknownNameIsAnErrorWithTheNearestNames) {
  auto result = run("NBK8 --json");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_NE(result.err.find("\"NBK8\""), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("nearest: "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("N-BK7"), std::string::npos) << result.err;

  result = run("N-BK7 --maker Acme");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("\"Acme\""), std::string::npos) << result.err;
  result = run("--list --maker Acme");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("\"Acme\" (makers: SCHOTT"), std::string::npos) << result.err;
}

TEST_F(GlassCommand, AWavelengthOutsideTheFormulasRangeIsAnError) {
  for (const std::string json : {"", " --json"}) {
    const auto result = run("N-BK7 --wavelength 587.5618 200" + json);
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(result.out.empty()) << result.out;  // no index printed, extrapolated or not
    EXPECT_NE(result.err.find("N-BK7: 200 nm is outside its dispersion formula's range, "
                              "300-2500 nm"),
              std::string::npos)
        << result.err;
  }
}

TEST_F(GlassCommand, AnInfraredMaterialHasNoNdAndNoNaN) {
  // Germanium (CRYSTRAN's measured table, 2.058-13.02 um, before MISC's formula) misses the d
  // line: no n_d or V_d, and null in the JSON.
  const auto result = run("Ge --wavelength 10000 --json");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json.at("maker").get<std::string>(), "CRYSTRAN");
  EXPECT_TRUE(json.at("n_d").is_null());
  EXPECT_TRUE(json.at("v_d").is_null());
  // Germanium near 10 um: about 4.00 (the handbooks give 4.003 at 10.6 um).
  EXPECT_NEAR(json.at("indices").at(0).at("n").get<double>(), 4.00, 0.01);
  EXPECT_EQ(result.out.find("NaN"), std::string::npos);
}

TEST_F(GlassCommand, UsageErrors) {
  EXPECT_EQ(run("").exitCode, 2);
  EXPECT_EQ(run("N-BK7 --list").exitCode, 2);
  EXPECT_EQ(run("--list --wavelength 500").exitCode, 2);
  EXPECT_EQ(run("N-BK7 --wavelength nan").exitCode, 2);
  EXPECT_EQ(run("N-BK7 --wavelength -5").exitCode, 2);
}

}  // namespace
}  // namespace lenslab
