// The bundled glass catalogues (optics/glass/glass_catalog.h) against the makers' own numbers and
// a commercial program's listing, and the catalogue's lookup, completion and load errors.

#include "optics/glass/glass_catalog.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "glass_test_support.h"
#include "optics/glass/glass_catalog_loader.h"

namespace lenslab::optics {
namespace {

namespace fs = std::filesystem;
using test::bundledGlassCatalog;

std::string fileText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

const CatalogGlass& glass(std::string_view name, std::string_view maker = {}) {
  const GlassLookup found = bundledGlassCatalog().lookup(name, maker);
  if (!found) throw std::runtime_error(found.error);
  return *found.glass;
}

TEST(GlassCatalog, LoadsEveryBundledGlass) {
  const auto start = std::chrono::steady_clock::now();
  const GlassCatalogLoad load = loadGlassCatalog(LENSLAB_BUNDLED_GLASS_DIR);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "full glass catalogue loaded in " << ms << " ms\n";
  for (const std::string& error : load.errors) ADD_FAILURE() << error;
  ASSERT_TRUE(load.catalog);
  EXPECT_EQ(load.catalog->size(), 1735u);  // ../shared/data/README.md
  const std::vector<std::string> makers = {"SCHOTT",    "OHARA",   "HOYA",     "CDGM", "HIKARI",
                                           "SUMITA",    "LZOS",    "CRYSTRAN", "AMI",  "VITRON",
                                           "LIGHTPATH", "CORNING", "MISC"};
  EXPECT_EQ(load.catalog->makers(), makers);
}

TEST(GlassCatalog, BundledFilesAreTheReferenceCopy) {
  for (const auto& entry : fs::directory_iterator(LENSLAB_SHARED_GLASS_DIR)) {
    const fs::path bundled = fs::path(LENSLAB_BUNDLED_GLASS_DIR) / entry.path().filename();
    EXPECT_EQ(fileText(bundled), fileText(entry.path())) << bundled;
  }
}

// n_d and V_d from each formula against the maker's catalogue values (../shared/data/README.md:
// within 5.5e-6 and 0.01; SUMITA prints rounded values up to 3.8e-5 and 0.23 from its formula).
TEST(GlassCatalog, ComputedAbbeDataMatchTheMakersCatalogues) {
  const std::map<std::string, std::pair<double, double>> tolerance = {
      {"SCHOTT", {5.5e-6, 0.01}}, {"OHARA", {5.5e-6, 0.01}}, {"HIKARI", {5.5e-6, 0.01}},
      {"CDGM", {5.5e-6, 0.01}},   {"HOYA", {5.5e-6, 0.01}},  {"SUMITA", {3.8e-5, 0.23}}};
  std::map<std::string, int> checked;
  for (const CatalogGlass& g : bundledGlassCatalog().glasses()) {
    const auto limits = tolerance.find(g.maker);
    if (limits == tolerance.end() || !g.catalogNd || !g.catalogVd) continue;
    // DURAN is a single measured point at 587.6 nm: no F and C lines to compute V_d from.
    if (!g.formula.covers(kCatalogFLineNm) || !g.formula.covers(kCatalogCLineNm)) continue;
    // SCHOTT's BOROFLOAT33 lists 1.471/65.41, which its own formula does not give (README).
    if (g.name == "BOROFLOAT33") continue;
    ASSERT_TRUE(g.nd && g.vd) << g.maker << " " << g.name;
    EXPECT_LE(std::abs(*g.nd - *g.catalogNd), limits->second.first + 1e-12)
        << g.maker << " " << g.name << " nd " << *g.nd << " listed " << *g.catalogNd;
    EXPECT_LE(std::abs(*g.vd - *g.catalogVd), limits->second.second + 1e-9)
        << g.maker << " " << g.name << " vd " << *g.vd << " listed " << *g.catalogVd;
    ++checked[g.maker];
  }
  // Every maker's catalogue was checked, most of it (so the test cannot pass on nothing).
  EXPECT_GE(checked["SCHOTT"], 150);
  EXPECT_GE(checked["OHARA"], 400);
  EXPECT_GE(checked["HIKARI"], 300);
  EXPECT_GE(checked["CDGM"], 300);
  EXPECT_GE(checked["HOYA"], 180);
  EXPECT_GE(checked["SUMITA"], 170);
}

TEST(GlassCatalog, WellKnownGlasses) {
  // The makers' data sheets (../shared/data/README.md): n_d to 6 decimals, V_d to 3.
  struct Known {
    const char* name;
    double nd, vd;
  };
  for (const Known& k : {Known{"N-BK7", 1.516800, 64.167}, Known{"N-SF11", 1.784720, 25.680},
                         Known{"S-LAH66", 1.772499, 49.598}}) {
    const CatalogGlass& g = glass(k.name);
    EXPECT_NEAR(*g.nd, k.nd, 5e-7) << k.name;
    EXPECT_NEAR(*g.vd, k.vd, 5e-4) << k.name;
  }
  EXPECT_EQ(glass("N-BK7").maker, "SCHOTT");
  EXPECT_EQ(glass("S-LAH66").maker, "OHARA");
}

TEST(GlassCatalog, SchottIndicesMatchCodeV) {
  // CODE V 10.8's "REFRACTIVE INDICES" for its double Gauss with Schott glasses
  // (../shared/reference/import/ray-optics/codev/ag_dblgauss.lis), at 656.3, 587.6, 486.1 nm.
  struct Listed {
    const char* name;
    double n[3];
  };
  const double wavelengthsNm[3] = {656.3, 587.6, 486.1};
  for (const Listed& l : {Listed{"N-SSK2", {1.618769, 1.622292, 1.630455}},
                          Listed{"N-SK2", {1.604134, 1.607379, 1.614860}},
                          Listed{"F5", {1.598744, 1.603417, 1.614617}},
                          Listed{"N-SK16", {1.617271, 1.620408, 1.627559}}}) {
    const CatalogGlass& g = glass(l.name, "schott");
    for (int i = 0; i < 3; ++i) {
      const IndexAtWavelength n = refractiveIndexAt(g, wavelengthsNm[i]);
      ASSERT_TRUE(n) << n.error;
      EXPECT_NEAR(*n.index, l.n[i], 7e-7) << l.name << " at " << wavelengthsNm[i] << " nm";
    }
  }
}

TEST(GlassCatalog, InfraredMaterialsHaveNoAbbeNumber) {
  const CatalogGlass& ge = glass("Ge", "misc");
  EXPECT_FALSE(ge.nd);
  EXPECT_FALSE(ge.vd);
  EXPECT_FALSE(refractiveIndexAt(ge.formula, kCatalogDLineNm, ge.name));
}

TEST(GlassCatalog, NamesMatchWithoutCaseHyphensSpacesOrUnderscores) {
  const CatalogGlass* nbk7 = &glass("N-BK7");
  for (const char* spelling : {"NBK7", "n-bk7", "n bk7", "N_BK7", " N - BK7 "}) {
    const GlassLookup found = bundledGlassCatalog().lookup(spelling);
    EXPECT_EQ(found.glass, nbk7) << spelling;
    EXPECT_FALSE(found.ambiguous()) << spelling;
  }
  EXPECT_EQ(bundledGlassCatalog().lookup("nbk7", "Schott").glass, nbk7);
  EXPECT_EQ(glass("fused silica").name, "fused_silica");
}

TEST(GlassCatalog, AmbiguousNamesSayWhichMakerIsUsed) {
  const GlassLookup f5 = bundledGlassCatalog().lookup("F5");
  ASSERT_TRUE(f5);
  EXPECT_TRUE(f5.ambiguous());
  EXPECT_EQ(f5.makers, (std::vector<std::string>{"SCHOTT", "CDGM", "HIKARI"}));
  EXPECT_EQ(f5.glass->maker, "SCHOTT");
  EXPECT_EQ(f5.choiceNote(), "F5 is in SCHOTT, CDGM, HIKARI; using SCHOTT's");
  // HOYA comes before HIKARI in the default order; a maker given picks its glass.
  EXPECT_EQ(bundledGlassCatalog().lookup("E-F1").glass->maker, "HOYA");
  const GlassLookup hikari = bundledGlassCatalog().lookup("E-F1", "hikari");
  EXPECT_EQ(hikari.glass->maker, "HIKARI");
  EXPECT_FALSE(hikari.ambiguous());
  EXPECT_EQ(hikari.choiceNote(), "");
}

TEST(GlassCatalog, UnknownNamesAreErrorsWithTheNearestNames) {
  const GlassLookup typo = bundledGlassCatalog().lookup("NBK8");
  EXPECT_FALSE(typo);
  EXPECT_EQ(typo.glass, nullptr);
  EXPECT_EQ(typo.error, "no glass catalogue has a glass named \"NBK8\" (nearest: BK8, N-BK7, BF8)");
  EXPECT_EQ(typo.suggestions.size(), 3u);
  const GlassLookup nonsense = bundledGlassCatalog().lookup("unobtainium");
  EXPECT_FALSE(nonsense);
  EXPECT_EQ(nonsense.error, "no glass catalogue has a glass named \"unobtainium\"");
  const GlassLookup wrongMaker = bundledGlassCatalog().lookup("N-BK7", "OHARA");
  EXPECT_FALSE(wrongMaker);
  EXPECT_EQ(wrongMaker.error.rfind("OHARA's catalogue has no glass named \"N-BK7\"", 0), 0u)
      << wrongMaker.error;
  const GlassLookup noMaker = bundledGlassCatalog().lookup("N-BK7", "Acme");
  EXPECT_FALSE(noMaker);
  EXPECT_EQ(
      noMaker.error.rfind("no glass catalogue from a maker named \"Acme\" (makers: SCHOTT, ", 0),
      0u)
      << noMaker.error;
}

TEST(GlassCatalog, CompletionListsNamesStartingWithThePrefix) {
  const auto nbk = bundledGlassCatalog().complete("n-bk");
  std::vector<std::string> names;
  for (const CatalogGlass* g : nbk) names.push_back(g->name);
  EXPECT_EQ(names, (std::vector<std::string>{"N-BK10", "N-BK7", "N-BK7HT", "N-BK7HTi"}));
  const auto slah = bundledGlassCatalog().complete("slah6", "ohara", 5);
  ASSERT_EQ(slah.size(), 5u);
  for (const CatalogGlass* g : slah) {
    EXPECT_EQ(g->name.rfind("S-LAH6", 0), 0u) << g->name;
    EXPECT_EQ(g->maker, "OHARA");
  }
  EXPECT_TRUE(
      std::is_sorted(slah.begin(), slah.end(), [](auto* a, auto* b) { return a->name < b->name; }));
  EXPECT_EQ(bundledGlassCatalog().complete("", {}, 7).size(), 7u);
  EXPECT_TRUE(bundledGlassCatalog().complete("zzz").empty());
}

// A catalogue directory with one file, for the load errors.
class BadCatalog : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        fs::temp_directory_path() /
        ("lenslab-glass-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  // Loads a catalogue whose only file, bad.csv, has the header and `rows`.
  GlassCatalogLoad load(const std::string& rows,
                        const std::string& header =
                            "name,group,formula_id,formula,coefficients,lmin_um,lmax_um,nd,vd,"
                            "nd_cat,vd_cat,code,status,T_K\n") {
    std::ofstream(directory_ / "bad.csv") << header << rows;
    return loadGlassCatalog(directory_);
  }

  fs::path directory_;
};

TEST_F(BadCatalog, AGoodRowLoads) {
  // A quoted field may hold a comma (and "" a quote); a blank line and CR LF endings are fine.
  const GlassCatalogLoad good =
      load("G1,\"a, \"\"b\"\"\",2,sellmeier2,0 1 0.01,0.3,2.5,,,,,,,\r\n\r\n");
  for (const std::string& error : good.errors) ADD_FAILURE() << error;
  ASSERT_TRUE(good.catalog);
  ASSERT_EQ(good.catalog->size(), 1u);
  EXPECT_EQ(good.catalog->glasses()[0].maker, "BAD");
  EXPECT_EQ(good.catalog->glasses()[0].group, "a, \"b\"");
  // n^2 - 1 = 1 * lambda^2 / (lambda^2 - 0.01), the formula 2 row above, at the d line.
  const double l2 = 0.5875618 * 0.5875618;
  EXPECT_NEAR(*good.catalog->glasses()[0].nd, std::sqrt(1.0 + l2 / (l2 - 0.01)), 1e-14);
}

TEST_F(BadCatalog, ADirectoryWithoutCataloguesIsAnError) {
  const GlassCatalogLoad empty = loadGlassCatalog(directory_);
  EXPECT_FALSE(empty.catalog);
  ASSERT_EQ(empty.errors.size(), 1u);
  EXPECT_EQ(empty.errors[0], directory_.string() + ": no glass catalogue (*.csv) there");
}

TEST_F(BadCatalog, ErrorsSayFileLineAndColumn) {
  // Columns: "G1,optical,2,sellmeier2,0 1 0.01," is 33 characters, so lmin_um starts at 34; the
  // coefficients field starts at 25 and its third word at 25 + 4 = 29; formula_id at 12.
  const std::string good = "G1,optical,2,sellmeier2,0 1 0.01,0.3,2.5,,,,,,,\n";
  auto expectOnly = [](const GlassCatalogLoad& l, const std::string& error) {
    EXPECT_FALSE(l.catalog);
    EXPECT_EQ(l.errors, std::vector<std::string>{error});
  };
  expectOnly(load(good + "G2,optical,2,sellmeier2,0 1 0.01,x3,2.5,,,,,,,\n"),
             "bad.csv:3:34: lmin_um \"x3\" is not a number");
  expectOnly(load(good + "G2,optical,2,sellmeier2,0 1 O.01,0.3,2.5,,,,,,,\n"),
             "bad.csv:3:29: coefficient \"O.01\" is not a number");
  expectOnly(load("G2,optical,12,sellmeier2,0 1 0.01,0.3,2.5,,,,,,,\n"),
             "bad.csv:2:12: unknown formula id \"12\" (1-9 or tab, data/glass/README.md)");
  // One field short: the error is at the end of the line (its 47 characters, so column 48).
  expectOnly(load("G2,optical,2,sellmeier2,0 1 0.01,0.3,2.5,,,,,,\n"),
             "bad.csv:2:47: 13 fields where the header has 14");
  expectOnly(load("G2,optical,2,\"sellmeier2,0 1 0.01,0.3,2.5,,,,,,,\n"),
             "bad.csv:2:14: a quoted field is not closed on its line");
  expectOnly(load("G2,optical,tab,tabulated,0.5 1.5 0.4,0.4,0.5,,,,,,,\n"),
             "bad.csv:2:26: a table needs pairs of wavelength and index");
  // "G2,optical,tab,tabulated,0.4 1.5 0.5 1.4," is 41 characters: lmin_um at 42.
  expectOnly(load("G2,optical,tab,tabulated,0.4 1.5 0.5 1.4,0.3,0.5,,,,,,,\n"),
             "bad.csv:2:42: the range 0.3-0.5 um reaches beyond the table's 0.4-0.5 um");
  const GlassCatalogLoad missing = load("", "name,group,formula_id\n");
  EXPECT_FALSE(missing.catalog);
  ASSERT_FALSE(missing.errors.empty());
  EXPECT_EQ(missing.errors[0], "bad.csv:1:1: no column \"formula\"");
}

TEST(GlassCatalog, TheDefaultCatalogueIsLoadedOnceForAllThreads) {
  std::vector<const GlassCatalogLoad*> seen(8, nullptr);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    threads.emplace_back([&seen, i] { seen[i] = &defaultGlassCatalog(); });
  }
  for (std::thread& thread : threads) thread.join();
  for (const GlassCatalogLoad* load : seen) EXPECT_EQ(load, seen[0]);
  // The test binary is not the lenslab binary of the build tree: the `glass` resource is found
  // only if lenslab is installed in the configured prefix. Either way the answer is definite.
  if (seen[0]->catalog) {
    EXPECT_EQ(seen[0]->catalog->size(), 1735u);
  } else {
    ASSERT_EQ(seen[0]->errors.size(), 1u);
    EXPECT_NE(seen[0]->errors[0].find("glass catalogues"), std::string::npos);
  }
}

TEST(GlassCatalog, MissingDirectoryIsAnError) {
  const GlassCatalogLoad none = loadGlassCatalog("/nonexistent/lenslab-glass");
  EXPECT_FALSE(none.catalog);
  ASSERT_EQ(none.errors.size(), 1u);
  EXPECT_NE(none.errors[0].find("/nonexistent/lenslab-glass"), std::string::npos);
}

}  // namespace
}  // namespace lenslab::optics
