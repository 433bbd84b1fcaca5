// The pbrt lens-file format: what it must accept, what it must refuse (with file:line:column),
// and that lenslab reads what it writes.

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "test_lenses.h"

namespace lenslab::optics {
namespace {

const char* kFourRows =
    "# a test lens\n"
    "50 5 1.5 20\n"
    "0 5 0 10\n"
    "-50 40 1 20\n";

LensFileResult parseDat(const std::string& text) { return parseLensText(text, "t.dat"); }

std::string firstDatError(const LensFileResult& r) {
  return r.diagnostics.empty() ? std::string("(no error)") : r.diagnostics.all().front().format();
}

TEST(LensFile, ReadsPbrtRowsAndComments) {
  const auto r = parseDat(kFourRows);
  ASSERT_TRUE(r.ok()) << firstDatError(r);
  const auto& s = r.lens->prescription.surfaces;
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].radiusMm, 50.0);
  EXPECT_EQ(s[1].isStop(), true);
  EXPECT_EQ(s[1].mediumIndexD(), 1.0);  // n 0 means air
  EXPECT_EQ(s[2].thicknessMm, 40.0);
  ASSERT_EQ(r.lens->headerComments.size(), 1u);
  EXPECT_EQ(r.lens->headerComments[0], "a test lens");
}

TEST(LensFile, AcceptsCrlfAndNoFinalNewline) {
  const auto crlf = parseDat("# x\r\n50\t5\t1.5\t20\r\n0 5 0 10\r\n-50 40 1 20");
  ASSERT_TRUE(crlf.ok()) << firstDatError(crlf);
  ASSERT_EQ(crlf.lens->prescription.surfaces.size(), 3u);
  // pbrt drops a last number without trailing whitespace; lenslab keeps it.
  EXPECT_EQ(crlf.lens->prescription.surfaces[2].apertureDiameterMm, 20.0);
}

TEST(LensFile, SkipsAUtf8ByteOrderMark) {
  const auto r = parseDat("\xEF\xBB\xBF# x\n" + std::string(kFourRows));
  ASSERT_TRUE(r.ok()) << firstDatError(r);
  EXPECT_EQ(r.lens->prescription.surfaces.size(), 3u);
  EXPECT_EQ(r.lens->headerComments.front(), "x");
  // Right before a number, too; columns count from after the mark.
  const auto row = parseDat(
      "\xEF\xBB\xBF"
      "50 5 1.5 20\n0 5 0 10\n-50 40 1 20\n");
  ASSERT_TRUE(row.ok()) << firstDatError(row);
  EXPECT_EQ(row.lens->prescription.surfaces[0].radiusMm, 50.0);
  const auto bad = parseDat(
      "\xEF\xBB\xBF"
      "5x 5 1.5 20\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.diagnostics.all().front().location.column, 1) << firstDatError(bad);
}

TEST(LensFile, AcceptsLoneCarriageReturnLineEndings) {
  // Classic Mac OS text: rows end in a CR alone.
  const auto r = parseDat("# old Mac\r50 5 1.5 20\r0 5 0 10\r-50 40 1 20\r");
  ASSERT_TRUE(r.ok()) << firstDatError(r);
  ASSERT_EQ(r.lens->prescription.surfaces.size(), 3u);
  EXPECT_EQ(r.lens->prescription.surfaces[2].thicknessMm, 40.0);
  EXPECT_EQ(r.lens->headerComments, std::vector<std::string>{"old Mac"});
  EXPECT_EQ(r.lens->rowLines, (std::vector<int>{2, 3, 4}));
  // Errors count those lines, and a mix of endings is fine.
  const auto bad = parseDat("50 5 1.5 20\r\n0 5 0 10\r-50 4x 1 20\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.diagnostics.all().front().location.line, 3) << firstDatError(bad);
  EXPECT_EQ(bad.diagnostics.all().front().location.column, 5) << firstDatError(bad);
}

TEST(LensFile, AcceptsStrayQuotesInComments) {
  const auto r = parseDat("# US patent 2,673,491 Tronnier\"\t\t\n# Modern Lens Design, p.312\"\n" +
                          std::string(kFourRows));
  ASSERT_TRUE(r.ok()) << firstDatError(r);
  EXPECT_EQ(r.lens->prescription.surfaces.size(), 3u);
}

TEST(LensFile, FifthColumnIsTheAbbeNumberAndInfIsAFlatSurface) {
  const auto r = parseDat("50 5 1.67 20 47.1\ninf 1 1 20\n0 5 0 10\n-50 40 1 20\n");
  ASSERT_TRUE(r.ok()) << firstDatError(r);
  const auto& s = r.lens->prescription.surfaces;
  ASSERT_TRUE(s[0].abbeD.has_value());
  EXPECT_EQ(*s[0].abbeD, 47.1);
  EXPECT_FALSE(s[2].abbeD.has_value());
  EXPECT_TRUE(s[1].isFlat());
  EXPECT_FALSE(s[1].isStop());
}

TEST(LensFile, ReadsTheCourseReferenceFiles) {
  for (const auto& lens : testing::kCourseLenses) {
    const auto r = readLensFile(testing::referenceLensDir() / lens.file);
    ASSERT_TRUE(r.ok()) << firstDatError(r);
    EXPECT_GE(r.lens->prescription.surfaces.size(), 7u);
  }
}

TEST(LensFile, WritesWhatItReadsIdentically) {
  Prescription p;
  p.surfaces = {{29.475, 3.76, 1.67, 47.1, 25.2},
                {kFlatRadius, 0.12, 1.0, std::nullopt, 25.2},
                {0.0, 4.5, 0.0, std::nullopt, 17.1},
                {-1.0 / 3.0, 0.1 + 0.2, 1.603, 38.0, 0.6},
                {-39.73, 36.77, 1.0, std::nullopt, 20.0}};
  const std::string text = formatLensText(p, {"round trip", "second line"});
  EXPECT_TRUE(parseDat(text).ok()) << firstDatError(parseDat(text));
  p.surfaces[3] = {-14.495, 1.0 / 3.0, 1.603, 38.0, 17.0};
  const auto again = parseDat(formatLensText(p, {"round trip"}));
  ASSERT_TRUE(again.ok()) << firstDatError(again) << "\n" << formatLensText(p);
  const auto& s = again.lens->prescription.surfaces;
  ASSERT_EQ(s.size(), p.surfaces.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(s[i].radiusMm, p.surfaces[i].radiusMm) << i;
    EXPECT_EQ(s[i].thicknessMm, p.surfaces[i].thicknessMm) << i;
    EXPECT_EQ(s[i].indexD, p.surfaces[i].indexD) << i;
    EXPECT_EQ(s[i].abbeD, p.surfaces[i].abbeD) << i;
    EXPECT_EQ(s[i].apertureDiameterMm, p.surfaces[i].apertureDiameterMm) << i;
  }
  EXPECT_EQ(again.lens->headerComments.front(), "round trip");
  // And the text itself is a fixed point of read-then-write, header comments included.
  const std::string once = formatLensText(p, {"round trip", "two"});
  const auto reread = parseDat(once);
  ASSERT_TRUE(reread.ok());
  EXPECT_EQ(reread.lens->headerComments, (std::vector<std::string>{"round trip", "two"}));
  EXPECT_EQ(formatLensText(reread.lens->prescription, reread.lens->headerComments), once);
  EXPECT_EQ(formatLensText(again.lens->prescription, {"round trip"}),
            formatLensText(p, {"round trip"}));
}

TEST(LensFile, WritesAndReadsAFile) {
  const auto dir = std::filesystem::temp_directory_path() / "lenslab_lens_file_test";
  std::filesystem::create_directories(dir);
  const Prescription p = testing::loadPrescription(testing::referenceLensDir() / "wide.22mm.dat");
  std::string error;
  ASSERT_TRUE(writeLensFile(dir / "wide.dat", p, {"copy"}, &error)) << error;
  const Prescription q = testing::loadPrescription(dir / "wide.dat");
  ASSERT_EQ(q.surfaces.size(), p.surfaces.size());
  for (std::size_t i = 0; i < q.surfaces.size(); ++i)
    EXPECT_EQ(q.surfaces[i].radiusMm, p.surfaces[i].radiusMm);
}

struct BadCase {
  const char* text;
  int line, column;
  const char* fragment;
};

TEST(LensFile, BadInputGivesFileLineColumnErrors) {
  const BadCase cases[] = {
      {"50 5 1.5 20\n0 5 x 10\n-50 40 1 20\n", 2, 5, "not a number"},
      {"50 5 1.5 20\n0 5 1.5e 10\n-50 40 1 20\n", 2, 5, "not a number"},
      {"50 5 1.5 20\n0 5 0\n-50 40 1 20\n", 2, 6, "short row"},
      {"50 5 1.5 20 40 7\n0 5 0 10\n-50 40 1 20\n", 1, 16, "too many"},
      {"", 1, 1, "empty"},
      {"# only a comment\n", 1, 1, "no lens surfaces"},
      {"50 5 nan 20\n0 5 0 10\n-50 40 1 20\n", 1, 6, "NaN"},
      {"50 inf 1.5 20\n0 5 0 10\n-50 40 1 20\n", 1, 4, "infinity"},
      {"50 5 1.5 20\n-50 40 1 20\n", 1, 1, "no aperture stop"},
      {"50 5 1.5 20\n0 5 0 10\n0 5 0 10\n-50 40 1 20\n", 3, 1, "second aperture stop"},
      {"50 5 1.5 20\n0 5 0 10\n\x01\x02\x03\x04\n", 3, 1, "binary"},
      {"50 5 1.5 20\n0 5 0 -3\n-50 40 1 20\n", 2, 1, "aperture diameter"},
      {"50 5 0.5 20\n0 5 0 10\n-50 40 1 20\n", 1, 1, "below 1"},
      // Absurd magnitudes are refused at the token, not traced into nonsense.
      {"1e300 5 1.5 20\n0 5 0 10\n-50 40 1 20\n", 1, 1, "beyond any real lens"},
      {"50 5 1.5 20\n0 5 0 10\n-50 1e300 1 20\n", 3, 5, "thickness 1e300 is beyond"},
      {"50 -2e6 1.5 20\n0 5 0 10\n-50 40 1 20\n", 1, 4, "beyond any real lens"},
      {"50 5 1.5 20\n0 5 0 2e5\n-50 40 1 20\n", 2, 7, "aperture diameter 2e5 is beyond"},
      {"50 5 1e3 20\n0 5 0 10\n-50 40 1 20\n", 1, 6, "refractive index 1e3 is beyond"},
      // V_d: at its own column, on its row (issue 23: zero, negative, NaN, absurd).
      {"50 5 1.5 20 0\n0 5 0 10\n-50 40 1 20\n", 1, 13, "Abbe number 0 must be positive"},
      {"50 5 1.5 20\n0 5 0 10\n-50 40 1.6 20 -30\n", 3, 15, "Abbe number -30 must be positive"},
      {"50 5 1.5 20   nan\n0 5 0 10\n-50 40 1 20\n", 1, 15, "NaN is not allowed"},
      {"50 5 1.5 20 inf\n0 5 0 10\n-50 40 1 20\n", 1, 13, "infinity is not allowed"},
      {"50 5 1.5 20 40\n0 5 0 10\n-50 40 1.5 20 151\n", 3, 15,
       "Abbe number 151 is beyond any real glass (at most 150)"},
      // Validation errors name the surface counted from 1, as the viewer's table does.
      {"50 5 1.5 20\n0 5 0 -3\n-50 40 1 20\n", 2, 1, "surface 2: aperture diameter"},
      {"12 1 1.5 20\n-12 5 1 20\n0 40 0 10\n", 2, 1,
       "surface 2: crosses the previous surface (surface 1)"},
  };
  for (const auto& c : cases) {
    const std::string text(c.text);
    const auto r = parseDat(text);
    EXPECT_FALSE(r.ok()) << c.text;
    ASSERT_FALSE(r.diagnostics.empty()) << c.text;
    const auto& e = r.diagnostics.all().front();
    EXPECT_EQ(e.location.line, c.line) << e.format();
    EXPECT_EQ(e.location.column, c.column) << e.format();
    EXPECT_NE(e.message.find(c.fragment), std::string::npos) << e.format();
    EXPECT_EQ(e.format().rfind("t.dat:" + std::to_string(c.line) + ":", 0), 0u) << e.format();
  }
}

TEST(LensFile, BundledLensesNameTheirSources) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(testing::bundledLensDir())) {
    if (entry.path().extension() != ".dat") continue;
    ++files;
    const auto r = readLensFile(entry.path());
    ASSERT_TRUE(r.ok()) << firstDatError(r);
    std::string header;
    for (const std::string& line : r.lens->headerComments) header += line + "\n";
    EXPECT_TRUE(header.find("Source") != std::string::npos ||
                header.find("patent") != std::string::npos)
        << entry.path() << ":\n"
        << header;
  }
  EXPECT_GE(files, 9);
  // The fisheye is the Muller design in Smith's Modern Lens Design, p. 164 (as pbrt's file
  // says); the patent number it used to cite could not be confirmed and is gone.
  const auto fisheye = readLensFile(testing::bundledLensDir() / "fisheye-10mm.dat");
  ASSERT_TRUE(fisheye.ok());
  std::string header;
  for (const std::string& line : fisheye.lens->headerComments) header += line + "\n";
  EXPECT_NE(header.find("Modern Lens Design"), std::string::npos) << header;
  EXPECT_NE(header.find("p. 164"), std::string::npos) << header;
  EXPECT_EQ(header.find("4,747,675"), std::string::npos) << header;
}

TEST(LensFile, EmbeddedNulIsBinary) {
  const std::string text("50 5 1.5 20\n0 5\0 0 10\n", 22);
  const auto r = parseDat(text);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.all().front().location.line, 2);
  EXPECT_EQ(r.diagnostics.all().front().location.column, 4);
}

TEST(LensFile, MissingFileAndDirectoryAreErrors) {
  const auto missing = readLensFile("/nonexistent/lens.dat");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.diagnostics.all().front().format(),
            "/nonexistent/lens.dat:1:1: error: no such file");
  EXPECT_FALSE(readLensFile(std::filesystem::temp_directory_path()).ok());
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

// Random text made of lens-file characters and junk: always a lens or a located error.
TEST(LensFile, RandomTextIsALensOrALocatedError) {
  std::mt19937 rng(17);
  const std::string alphabet = "0123456789 .-+e\t\n\r#\"infa\x01\xff";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::uniform_int_distribution<int> length(0, 200);
  for (int i = 0; i < 3000; ++i) {
    std::string text;
    for (int n = length(rng); n > 0; --n) text += alphabet[pick(rng)];
    const auto r = parseLensText(text, "r.dat");
    if (r.ok()) {
      EXPECT_TRUE(r.diagnostics.empty());
      EXPECT_TRUE(LensSystem::build(r.lens->prescription).ok());
    } else {
      ASSERT_FALSE(r.diagnostics.empty());
      EXPECT_GE(r.diagnostics.all().front().location.line, 1);
      EXPECT_GE(r.diagnostics.all().front().location.column, 1);
    }
  }
}

// Flat surfaces 1 mm apart, glass and air by turns, the stop in the middle: nothing crosses, so
// only the count can make it an error.
std::string flatSurfaces(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    text += i == count / 2 ? "0\t1\t0\t10\n" : (i % 2 ? "inf\t1\t1\t20\n" : "inf\t1\t1.5\t20\n");
  }
  return text;
}

TEST(LensFile, AtMost256SurfacesAndTheNextIsAnErrorAtItsRow) {
  const auto most = parseDat(flatSurfaces(256));
  ASSERT_TRUE(most.lens.has_value()) << most.diagnostics.formatAll();
  EXPECT_EQ(most.lens->prescription.surfaces.size(), 256u);
  const auto tooMany = parseDat(flatSurfaces(10'000));
  EXPECT_FALSE(tooMany.lens.has_value());
  ASSERT_EQ(tooMany.diagnostics.all().size(), 1u);
  EXPECT_EQ(tooMany.diagnostics.formatAll(),
            "t.dat:257:1: error: too many surfaces: a lens file holds at most 256\n");
}

}  // namespace
}  // namespace lenslab::optics
