// lenslab's own lens format (.lens): what it reads, what it refuses (at file:line:column), and
// that it reads back exactly what it writes, aspheric terms and all.

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "optics/lens_loader.h"
#include "optics/native_lens_file.h"

namespace lenslab::optics {
namespace {

LensFileResult parse(const std::string& text) { return parseNativeLensText(text, "t.lens"); }

std::string firstError(const LensFileResult& r) {
  return r.diagnostics.empty() ? std::string("(no error)") : r.diagnostics.all().front().format();
}

// The error at `line`:`column` whose message contains `fragment`.
void expectError(const std::string& text, int line, int column, const std::string& fragment) {
  const LensFileResult r = parse(text);
  EXPECT_FALSE(r.ok()) << text;
  ASSERT_FALSE(r.diagnostics.empty()) << text;
  const Diagnostic& d = r.diagnostics.all().front();
  EXPECT_EQ(d.location.line, line) << d.format();
  EXPECT_EQ(d.location.column, column) << d.format();
  EXPECT_NE(d.message.find(fragment), std::string::npos) << d.format();
}

const std::string kDoublet =
    "lenslab-lens 1\n"
    "# a comment line\n"
    "title Achromat 100 mm f/5 # not a comment here\n"
    "source Smith, Modern Lens Design, p. 2\n"
    "published_efl_mm 100.0\n"
    "type cemented achromat # kept as written\n"
    "year 1953\n"
    "note first note\n"
    "note second note\n"
    "aperture blades 6 curvature 0.5\n"
    "surface radius 61.07 thickness 4.0 nd 1.5168 vd 64.17 diameter 21\n"
    "surface thickness 2.5 radius -44.28 nd 1.6727 vd 32.21 diameter 21  # cemented\n"
    "surface radius -129.3 thickness 2 diameter 21 conic -0.5 a4 -2.15e-06 a6 3.3E-9\n"
    "\n"
    "stop thickness 93.5 diameter 18\n";

TEST(NativeLensFile, ReadsEveryPartOfAHandWrittenFile) {
  const LensFileResult r = parse(kDoublet);
  ASSERT_TRUE(r.ok()) << firstError(r);
  const LensFile& lens = *r.lens;
  EXPECT_EQ(lens.title, "Achromat 100 mm f/5 # not a comment here");
  EXPECT_EQ(lens.source, "Smith, Modern Lens Design, p. 2");
  ASSERT_TRUE(lens.publishedEflMm);
  EXPECT_EQ(*lens.publishedEflMm, 100.0);
  EXPECT_EQ(lens.lensType, "cemented achromat # kept as written");
  EXPECT_EQ(lens.year, 1953);
  EXPECT_EQ(lens.headerComments, (std::vector<std::string>{"first note", "second note"}));
  EXPECT_EQ(lens.prescription.stopShape.kind, ApertureShape::Kind::Blades);
  EXPECT_EQ(lens.prescription.stopShape.bladeCount, 6);
  const auto& s = lens.prescription.surfaces;
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].radiusMm, 61.07);
  EXPECT_EQ(s[0].indexD, 1.5168);
  EXPECT_EQ(*s[0].abbeD, 64.17);
  EXPECT_EQ(s[1].radiusMm, -44.28);  // pairs in any order
  EXPECT_EQ(s[1].thicknessMm, 2.5);
  EXPECT_EQ(s[2].mediumIndexD(), 1.0);  // no nd: air
  EXPECT_FALSE(s[2].abbeD);
  EXPECT_EQ(s[2].profile.conic(), -0.5);
  EXPECT_EQ(s[2].profile.coefficient(4), -2.15e-06);
  EXPECT_EQ(s[2].profile.coefficient(6), 3.3e-9);
  EXPECT_EQ(s[2].profile.highestPower(), 6);
  EXPECT_TRUE(s[3].isStop());
  EXPECT_EQ(s[3].thicknessMm, 93.5);  // the last row's thickness: the film distance
  EXPECT_EQ(lens.rowLines, (std::vector<int>{11, 12, 13, 15}));
}

TEST(NativeLensFile, ReadsBackExactlyWhatItWrites) {
  LensFile lens;
  lens.title = "A test lens";
  lens.source = "nowhere";
  lens.publishedEflMm = 0.1 + 0.2;  // 0.30000000000000004: only the shortest exact form keeps it
  lens.headerComments = {"one", "", "three"};
  lens.lensType = "Tessar";
  lens.year = 1902;
  lens.prescription.stopShape.kind = ApertureShape::Kind::Blades;
  lens.prescription.stopShape.bladeCount = 7;
  lens.prescription.stopShape.rotationDeg = 12.5;
  Surface front{1.0 / 3.0 * 100.0, 5.0, 1.7, 47.123456789012345, 20.0};
  front.profile.setConic(-0.987654321);
  front.profile.setCoefficient(3, 1e-5);  // an odd term
  front.profile.setCoefficient(4, -2.1234567890123e-6);
  front.profile.setCoefficient(20, 1e-300);
  Surface flat{kFlatRadius, 1.0, 1.0, std::nullopt, 20.0};
  flat.profile.setCoefficient(4, 1e-7);  // a flat carrying terms
  lens.prescription.surfaces = {front, flat, {0.0, 30.0, 1.0, std::nullopt, 10.0}};
  const std::string text = formatNativeLensText(lens);
  const LensFileResult r = parse(text);
  ASSERT_TRUE(r.ok()) << firstError(r) << "\n" << text;
  EXPECT_EQ(r.lens->title, lens.title);
  EXPECT_EQ(r.lens->source, lens.source);
  EXPECT_EQ(r.lens->publishedEflMm, lens.publishedEflMm);
  EXPECT_EQ(r.lens->headerComments, lens.headerComments);
  EXPECT_EQ(r.lens->lensType, lens.lensType);
  EXPECT_EQ(r.lens->year, lens.year);
  EXPECT_TRUE(r.lens->prescription.stopShape == lens.prescription.stopShape);
  ASSERT_EQ(r.lens->prescription.surfaces.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Surface& a = lens.prescription.surfaces[i];
    const Surface& b = r.lens->prescription.surfaces[i];
    EXPECT_EQ(a.radiusMm, b.radiusMm) << i;
    EXPECT_EQ(a.thicknessMm, b.thicknessMm) << i;
    EXPECT_EQ(a.mediumIndexD(), b.mediumIndexD()) << i;
    EXPECT_EQ(a.abbeD, b.abbeD) << i;
    EXPECT_EQ(a.apertureDiameterMm, b.apertureDiameterMm) << i;
    EXPECT_TRUE(a.profile == b.profile) << i;
  }
  // And the text itself is stable: writing what was read gives the same bytes.
  EXPECT_EQ(formatNativeLensText(*r.lens), text);
}

TEST(NativeLensFile, RefusesWhatItCannotReadAtItsLineAndColumn) {
  const std::string v = "lenslab-lens 1\n";
  expectError("", 1, 1, "empty file");
  expectError("# only a comment\nsurface radius 1\n", 2, 1, "expected the version line");
  expectError("lenslab-lens 2\n", 1, 14, "newer lenslab");
  expectError("lenslab-lens one\n", 1, 14, "not a format version");
  expectError(v + "colour red\n", 2, 1, "unknown key 'colour'");
  // Columns count bytes from 1: "surface radius 40 thickness " is 28 characters.
  expectError(v + "surface radius 40 thickness x diameter 20\n", 2, 29, "'x' is not a number");
  expectError(v + "surface radius 40 thickness 5 diameter 20 colour 3\n", 2, 43,
              "unknown surface property 'colour'");
  expectError(v + "surface radius 40 thickness 5 diameter 20 radius 41\n", 2, 43, "given twice");
  expectError(v + "surface radius 40 thickness 5 diameter\n", 2, 40, "'diameter' needs a value");
  expectError(v + "surface radius 40 thickness 5\n", 2, 31, "needs 'diameter'");
  expectError(v + "stop radius 40 thickness 5 diameter 20\n", 2, 6, "the stop is a plane");
  expectError(v + "stop thickness 5 diameter 20 a4 1e-6\n", 2, 30, "the stop is a plane");
  expectError(v + "surface radius 0 thickness 5 diameter 20\n", 2, 9, "write 'stop'");
  expectError(v + "surface radius 40 thickness 5 diameter 20 vd 60\n", 2, 43, "'vd' without 'nd'");
  expectError(v + "surface radius 40 thickness inf diameter 20\n", 2, 29, "infinity");
  expectError(v + "surface radius 40 thickness 5 diameter 20 a21 1\n", 2, 43, "'a21'");
  expectError(v + "surface radius 40 thickness 5 diameter 20 conic nan\n", 2, 49, "NaN");
  expectError(v + "surface radius 1e999 thickness 5 diameter 20\n", 2, 16, "out of range");
  expectError(v + "title one\ntitle two\n", 3, 1, "a second 'title' (the first is on line 2)");
  expectError(v + "title\n", 2, 7, "'title' needs a text");
  expectError(v + "type\n", 2, 6, "'type' needs a text");
  expectError(v + "year 1902\nyear 1903\n", 3, 1, "a second 'year' (the first is on line 2)");
  expectError(v + "year 95\n", 2, 6, "four digits");
  expectError(v + "year -1902\n", 2, 6, "four digits");
  expectError(v + "year 1902 1903\n", 2, 6, "four digits");
  expectError(v + "year\n", 2, 6, "four digits");
  expectError(v + "source x\n", 2, 1, "no surfaces");
  expectError(v + "surface radius 40 thickness 5 nd 0.5 diameter 20\n", 2, 34, "from 1 to");
  // Validation's errors point at the row of the surface they name (line 3: surface 2).
  expectError(v + "surface radius 40 thickness 5 nd 1.5 diameter 20\n"
                  "surface radius -60 thickness 1 diameter 20 conic 200\n"
                  "stop thickness 50 diameter 10\n",
              3, 1, "no real sag");
}

TEST(NativeLensFile, TheLoaderTellsTheFormatsApartAndTheWriterRefusesWhatDatCannotHold) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lenslab-native-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "doublet.lens") << kDoublet;
    // The version line decides, whatever the extension.
    std::ofstream(dir / "doublet.txt") << kDoublet;
  }
  for (const char* name : {"doublet.lens", "doublet.txt"}) {
    const LoadedLens loaded = loadLens(dir / name);
    ASSERT_TRUE(loaded.ok()) << loaded.diagnostics.formatAll();
    EXPECT_EQ(loaded.file.title, "Achromat 100 mm f/5 # not a comment here");
    EXPECT_EQ(loaded.system->prescription().surfaces[2].profile.coefficient(4), -2.15e-06);
  }
  // A .lens without its version line gets the .lens reader's message, not the .dat reader's.
  { std::ofstream(dir / "bare.lens") << "50 5 1.5 20\n0 5 0 10\n"; }
  const LoadedLens bare = loadLens(dir / "bare.lens");
  ASSERT_FALSE(bare.ok());
  EXPECT_NE(bare.diagnostics.formatAll().find("expected the version line"), std::string::npos);

  // Saving: .lens holds the conic; .dat cannot, says which surface, and writes nothing.
  const LensFile lens = *parse(kDoublet).lens;
  std::string error;
  EXPECT_TRUE(writeLensFile(dir / "out.lens", lens, &error)) << error;
  EXPECT_TRUE(loadLens(dir / "out.lens").ok());
  EXPECT_FALSE(writeLensFile(dir / "out.dat", lens, &error));
  EXPECT_NE(error.find("surface 3 has a conic or aspheric terms"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.dat"));
  // Without the conic and terms the same lens fits pbrt's format.
  LensFile spherical = lens;
  spherical.prescription.surfaces[2].profile = AsphericProfile{};
  EXPECT_TRUE(writeLensFile(dir / "out.dat", spherical, &error)) << error;
  EXPECT_TRUE(loadLens(dir / "out.dat").ok());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

const std::string kStop = "stop thickness 50 diameter 10\n";

TEST(NativeLensFile, DesignConditionsReadAndReadBackExactly) {
  const std::string text =
      "lenslab-lens 1\n"
      "design_wavelengths_nm 656.2725 587.5618 486.1327 primary 587.5618\n"
      "design_fields real_image_height_mm 0 8 13.6\n"
      "design_aperture f_number 2.1\n" +
      kStop;
  const LensFileResult r = parse(text);
  ASSERT_TRUE(r.ok()) << firstError(r);
  const DesignConditions& design = r.lens->design;
  EXPECT_EQ(design.wavelengths.nanometres, (std::vector<double>{656.2725, 587.5618, 486.1327}));
  EXPECT_EQ(design.wavelengths.primaryIndex, 1);
  EXPECT_EQ(design.fields.kind, FieldKind::RealImageHeightMm);
  EXPECT_EQ(design.fields.values, (std::vector<double>{0.0, 8.0, 13.6}));
  ASSERT_TRUE(design.aperture);
  EXPECT_EQ(design.aperture->kind, ApertureKind::ImageFNumber);
  EXPECT_EQ(design.aperture->value, 2.1);
  EXPECT_EQ(formatNativeLensText(*r.lens), text);

  for (const std::string line : {"design_fields angle_deg 0 20\n", "design_aperture epd_mm 12.5\n",
                                 "design_aperture stop\n"}) {
    const std::string other = "lenslab-lens 1\n" + line + kStop;
    const LensFileResult again = parse(other);
    ASSERT_TRUE(again.ok()) << firstError(again);
    EXPECT_EQ(formatNativeLensText(*again.lens), other);
  }
}

TEST(NativeLensFile, RefusesMalformedDesignConditionsAtTheirColumn) {
  expectError("lenslab-lens 1\ndesign_fields degrees 0 20\n" + kStop, 2, 15, "field kind");
  expectError("lenslab-lens 1\ndesign_fields angle_deg 0 x\n" + kStop, 2, 27, "not a finite");
  expectError("lenslab-lens 1\ndesign_wavelengths_nm 486 -587\n" + kStop, 2, 27, "above 0");
  expectError("lenslab-lens 1\ndesign_wavelengths_nm 486 587 primary 550\n" + kStop, 2, 39,
              "not one of");
  expectError("lenslab-lens 1\ndesign_aperture f_number\n" + kStop, 2, 17, "one value");
  expectError("lenslab-lens 1\ndesign_aperture stop 4\n" + kStop, 2, 22, "takes no value");
  expectError("lenslab-lens 1\ndesign_aperture f_number 2\ndesign_aperture f_number 3\n" + kStop, 3,
              1, "a second");
}

}  // namespace
}  // namespace lenslab::optics
