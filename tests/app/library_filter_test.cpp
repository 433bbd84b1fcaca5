// The library browser's entries and filters (issue 42), against a fixture folder whose lenses
// have known types, years and focal lengths. Every lens is a plano-convex singlet, front surface
// curved and rear flat, whose focal length is R / (n - 1) whatever its thickness (the thick-lens
// equation's thickness term has 1/R2 = 0): R 25 mm in n 1.5 is f = 50 mm exactly. The counts each
// filter keeps are counted by hand from the table below, not by the code.
//
//   file          type           year  f (mm)  aspheric surfaces  source
//   a-dg.lens     double-Gauss   1953     50    0                  US 2,532,751 (Tronnier)
//   b-tele.lens   telephoto      1970    200    0                  US 3,000,000 (Smith)
//   c-phone.lens  smartphone     2019      4    1 (a4)             CN 110,000,000
//   d-dg.lens     Double-Gauss   1989     85    1 (conic and a6)   JP 1989-123
//   e-fish.lens   fisheye        -        10    0                  -
//   f-old.dat     -              -       100    0                  -
//   g-broken.lens (does not parse)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "app/library/library_entry.h"
#include "app/library/library_filter.h"
#include "optics/lens_loader.h"
#include "support/run_process.h"
#include "support/singlet_lens_text.h"

namespace lenslab::app {
namespace {

std::filesystem::path writeLibraryFixture() {
  const auto folder = testing::makeTestDirectory("library-fixture");
  std::ofstream(folder / "a-dg.lens") << testing::planoConvexLensText(
      "title Gauss fifty\nsource US 2,532,751 (Tronnier)\ntype double-Gauss\nyear 1953\n", 25.0, "",
      20.0);
  std::ofstream(folder / "b-tele.lens") << testing::planoConvexLensText(
      "title Long one\nsource US 3,000,000 (Smith)\ntype telephoto\nyear 1970\n", 100.0, "", 40.0);
  std::ofstream(folder / "c-phone.lens") << testing::planoConvexLensText(
      "title Phone camera\nsource CN 110,000,000\ntype smartphone\nyear 2019\n", 2.0, " a4 -0.001",
      2.0);
  std::ofstream(folder / "d-dg.lens") << testing::planoConvexLensText(
      "title Gauss eighty-five\nsource JP 1989-123\ntype Double-Gauss\nyear 1989\n", 42.5,
      " conic -0.5 a6 1e-9", 30.0);
  std::ofstream(folder / "e-fish.lens")
      << testing::planoConvexLensText("title Fish\ntype fisheye\n", 5.0, "", 6.0);
  // pbrt's columns: radius, thickness, n (0 for the stop's air), aperture diameter.
  std::ofstream(folder / "f-old.dat") << "# An old singlet, 100 mm\n"
                                         "0 1 0 10\n"
                                         "50 2 1.5 20\n"
                                         "inf 100 1 20\n";
  std::ofstream(folder / "g-broken.lens") << "lenslab-lens 1\nsurface radius\n";
  std::ofstream(folder / "notes.md") << "not a lens\n";
  return folder;
}

std::vector<LibraryEntry> readLibraryFixture(const std::filesystem::path& folder) {
  std::vector<LibraryEntry> entries;
  for (const auto& path : listLibraryFiles(folder)) entries.push_back(readLibraryEntry(path));
  return entries;
}

class LibraryFixture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    entries_ = new std::vector(readLibraryFixture(writeLibraryFixture()));
  }
  static void TearDownTestSuite() { delete entries_; }
  static const std::vector<LibraryEntry>& entries() { return *entries_; }
  static std::size_t count(const LibraryFilter& filter) {
    return filterLibrary(entries(), filter).size();
  }
  static std::vector<std::string> files(const LibraryFilter& filter) {
    std::vector<std::string> names;
    for (const std::size_t i : filterLibrary(entries(), filter))
      names.push_back(entries()[i].fileName);
    return names;
  }
  static const LibraryEntry& entry(const std::string& fileName) {
    for (const LibraryEntry& e : entries())
      if (e.fileName == fileName) return e;
    throw std::runtime_error("no entry " + fileName);
  }
  static inline std::vector<LibraryEntry>* entries_ = nullptr;
};

TEST_F(LibraryFixture, ListsEveryLensFileInNameOrderAndNothingElse) {
  std::vector<std::string> names;
  for (const LibraryEntry& e : entries()) names.push_back(e.fileName);
  EXPECT_EQ(names,
            (std::vector<std::string>{"a-dg.lens", "b-tele.lens", "c-phone.lens", "d-dg.lens",
                                      "e-fish.lens", "f-old.dat", "g-broken.lens"}));
  EXPECT_FALSE(entry("g-broken.lens").usable());
  // Where and what: the reader's message at the file's line.
  EXPECT_NE(entry("g-broken.lens").error.find("g-broken.lens:2:"), std::string::npos)
      << entry("g-broken.lens").error;
  EXPECT_TRUE(entry("f-old.dat").usable());
}

TEST_F(LibraryFixture, EntriesCarryTheFilesWordsAndTheHandComputedFocalLengths) {
  // f = R / (n - 1) for a plano-convex lens, exactly.
  EXPECT_NEAR(*entry("a-dg.lens").eflMm, 50.0, 1e-9);
  EXPECT_NEAR(*entry("b-tele.lens").eflMm, 200.0, 1e-9);
  EXPECT_NEAR(*entry("c-phone.lens").eflMm, 4.0, 1e-9);
  EXPECT_NEAR(*entry("d-dg.lens").eflMm, 85.0, 1e-9);
  EXPECT_NEAR(*entry("e-fish.lens").eflMm, 10.0, 1e-9);
  EXPECT_NEAR(*entry("f-old.dat").eflMm, 100.0, 1e-9);
  EXPECT_EQ(entry("a-dg.lens").name, "Gauss fifty");
  EXPECT_EQ(entry("f-old.dat").name, "An old singlet, 100 mm");  // a .dat's first comment
  EXPECT_EQ(entry("a-dg.lens").type, "double-Gauss");
  EXPECT_EQ(entry("a-dg.lens").year, 1953);
  EXPECT_FALSE(entry("e-fish.lens").year.has_value());
  EXPECT_EQ(entry("c-phone.lens").asphericSurfaces, 1);
  EXPECT_EQ(entry("d-dg.lens").asphericSurfaces, 1);
  EXPECT_EQ(entry("a-dg.lens").asphericSurfaces, 0);
  for (const char* file : {"a-dg.lens", "c-phone.lens", "f-old.dat"})
    EXPECT_EQ(entry(file).elements, 1) << file;
  // The stop is 1 mm in front of the lens, a disc of half the lens's diameter: the paraxial
  // f-number is f over that disc's diameter (the entrance pupil of a stop in front of the lens
  // is the stop itself): 50 / 10 = 5.
  EXPECT_NEAR(*entry("a-dg.lens").fNumber, 5.0, 1e-6);
  // The same content gives the same key; another content another.
  EXPECT_NE(entry("a-dg.lens").contentHash, entry("d-dg.lens").contentHash);
  EXPECT_EQ(contentHash("abc"), contentHash(std::string("abc")));
}

TEST_F(LibraryFixture, NoFilterShowsAll) { EXPECT_EQ(count({}), 7u); }

TEST_F(LibraryFixture, TypeFilterIgnoresCase) {
  LibraryFilter filter;
  filter.type = "double-Gauss";
  EXPECT_EQ(files(filter), (std::vector<std::string>{"a-dg.lens", "d-dg.lens"}));
  filter.type = "FISHEYE";
  EXPECT_EQ(count(filter), 1u);
  filter.type = "zoom";
  EXPECT_EQ(count(filter), 0u);
  // The choices: each type once (double-Gauss in its first spelling), sorted without case.
  EXPECT_EQ(libraryTypes(entries()),
            (std::vector<std::string>{"double-Gauss", "fisheye", "smartphone", "telephoto"}));
}

TEST_F(LibraryFixture, FocalLengthRangeIsInclusiveAndDropsLensesWithout) {
  LibraryFilter filter;
  filter.minEflMm = 40.0;
  filter.maxEflMm = 100.0;
  // 50, 85 and 100 (its end); the broken file has no focal length.
  EXPECT_EQ(files(filter), (std::vector<std::string>{"a-dg.lens", "d-dg.lens", "f-old.dat"}));
  filter.minEflMm = 0.0;
  filter.maxEflMm = 60.0;
  EXPECT_EQ(files(filter), (std::vector<std::string>{"a-dg.lens", "c-phone.lens", "e-fish.lens"}));
  filter.minEflMm = std::nullopt;  // open below: up to 10 mm
  filter.maxEflMm = 10.0;
  EXPECT_EQ(count(filter), 2u);
}

TEST_F(LibraryFixture, YearRangeDropsFilesWithoutAYear) {
  LibraryFilter filter;
  filter.minYear = 1950;
  filter.maxYear = 1990;
  EXPECT_EQ(files(filter), (std::vector<std::string>{"a-dg.lens", "b-tele.lens", "d-dg.lens"}));
  filter.minYear = 1990;
  filter.maxYear = std::nullopt;
  EXPECT_EQ(files(filter), (std::vector<std::string>{"c-phone.lens"}));
}

TEST_F(LibraryFixture, AsphericFilterKeepsOnlyLensesItKnows) {
  LibraryFilter filter;
  filter.aspheric = AsphericChoice::With;
  EXPECT_EQ(files(filter), (std::vector<std::string>{"c-phone.lens", "d-dg.lens"}));
  filter.aspheric = AsphericChoice::Without;
  // The broken file's surfaces are unknown: neither with nor without.
  EXPECT_EQ(files(filter),
            (std::vector<std::string>{"a-dg.lens", "b-tele.lens", "e-fish.lens", "f-old.dat"}));
}

TEST_F(LibraryFixture, SearchFindsEveryWordInNameTypeSourceOrFileName) {
  LibraryFilter filter;
  filter.search = "gauss";  // two names, two types
  EXPECT_EQ(count(filter), 2u);
  filter.search = "SMITH";  // a source, without case
  EXPECT_EQ(files(filter), (std::vector<std::string>{"b-tele.lens"}));
  filter.search = "gauss 1989";  // both words: the name and the source of one
  EXPECT_EQ(files(filter), (std::vector<std::string>{"d-dg.lens"}));
  filter.search = ".dat";  // the file name
  EXPECT_EQ(files(filter), (std::vector<std::string>{"f-old.dat"}));
  filter.search = "nothing like it";
  EXPECT_EQ(count(filter), 0u);
}

TEST_F(LibraryFixture, FiltersCombine) {
  LibraryFilter filter;
  filter.type = "double-gauss";
  filter.aspheric = AsphericChoice::With;
  EXPECT_EQ(files(filter), (std::vector<std::string>{"d-dg.lens"}));
  filter = {};
  filter.minEflMm = 5.0;
  filter.maxEflMm = 150.0;
  filter.minYear = 1900;
  filter.maxYear = 2000;
  // "us" is in the US patents' sources and inside "Gauss": a, b and d; 5-150 mm drops b (200 mm),
  // the years c (2019), e and f (none).
  filter.search = "us";
  EXPECT_EQ(files(filter), (std::vector<std::string>{"a-dg.lens", "d-dg.lens"}));
}

TEST(LibraryEntry, ElementsArePiecesOfGlass) {
  // A cemented doublet (crown, then flint, then air), the stop, and a singlet: three elements.
  optics::Prescription lens;
  const auto surface = [](double radius, double index) {
    optics::Surface s;
    s.radiusMm = radius;
    s.thicknessMm = 2.0;
    s.indexD = index;
    s.apertureDiameterMm = 10.0;
    return s;
  };
  lens.surfaces = {surface(30, 1.5), surface(-20, 1.7), surface(-80, 1.0),
                   surface(0, 0.0),  surface(40, 1.6),  surface(-40, 1.0)};
  EXPECT_EQ(countElements(lens), 3);
  lens.surfaces[1].profile.setConic(-1.0);
  EXPECT_EQ(countAsphericSurfaces(lens), 1);
}

}  // namespace
}  // namespace lenslab::app
