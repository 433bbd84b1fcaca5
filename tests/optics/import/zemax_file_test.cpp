#include "optics/import/zemax_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "optics/import/text_encoding.h"
#include "optics/lens_system.h"
#include "support/bundled_glass.h"

namespace lenslab::optics {
namespace {

const std::filesystem::path kReference = LENSLAB_IMPORT_REFERENCE_DIR;

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << "cannot read " << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The reference file's text as UTF-8 (decoded by the code under test's decoder only where a test
// is about the reader, not the decoder).
std::string referenceText(const std::string& name) {
  return decodeText(readBytes(kReference / name)).text;
}

LensFileResult readReference(const std::string& name) { return readLensFile(kReference / name); }

// The 1-based line of the first line of `text` that contains `needle` (0 when none): the test's
// own look at the file, independent of the reader.
int lineContaining(const std::string& text, const std::string& needle, int occurrence = 1) {
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
    if (line.find(needle) != std::string::npos && --occurrence == 0) return number;
  return 0;
}

bool hasDiagnostic(const LensFileResult& result, Severity severity, int line,
                   const std::string& words) {
  for (const Diagnostic& d : result.diagnostics.all())
    if (d.severity == severity && d.location.line == line &&
        d.message.find(words) != std::string::npos)
      return true;
  return false;
}

// First-order data at the file's primary wavelength.
FirstOrderData firstOrderAtPrimary(const LensFile& lens) {
  const BuildResult built = LensSystem::build(lens.prescription);
  EXPECT_TRUE(built.ok());
  if (!built.ok()) return {};
  const DesignWavelengths& waves = lens.design.wavelengths;
  EXPECT_FALSE(waves.empty());
  const double primaryNm = waves.empty()
                               ? LensSystem::kDefaultWavelengthNm
                               : waves.nanometres[static_cast<std::size_t>(waves.primaryIndex)];
  const std::optional<FirstOrderData> first = built.system->firstOrderAt(primaryNm);
  EXPECT_TRUE(first.has_value());
  return first.value_or(FirstOrderData{});
}

// --- Published and recomputed focal lengths (../shared/reference/import/SOURCES.md) ---

TEST(ZemaxFile, EdmundAsphereLens2MatchesItsFocalLength) {
  // UTF-16 LE; EVENASPH PARM 1-8 with the stop on the asphere, Ohara L-BAL35, 587.6 nm.
  const LensFileResult result = readReference("optiland/zemax/lens2.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  EXPECT_EQ(lens.title, "47728 Asphere F/1.5");
  const FirstOrderData first = firstOrderAtPrimary(lens);
  EXPECT_NEAR(first.eflMm, 22.4994, 5e-4);   // SOURCES.md, recomputed (Edmund: 22.5)
  EXPECT_NEAR(first.bflMm, 19.98226, 5e-4);  // the last DISZ, a paraxial focus
  // The stop stays on the aspheric front surface: a stop row at its vertex, in front of it.
  ASSERT_EQ(lens.prescription.surfaces.size(), 3u);
  EXPECT_TRUE(lens.prescription.surfaces[0].isStop());
  EXPECT_NEAR(first.entrancePupil.positionMm, 0.0, 1e-12);
  EXPECT_NEAR(lens.prescription.surfaces[0].apertureDiameterMm, 13.5, 1e-12);
  const Surface& asphere = lens.prescription.surfaces[1];
  EXPECT_DOUBLE_EQ(asphere.profile.conic(), -2.3641429999999999);
  EXPECT_DOUBLE_EQ(asphere.profile.coefficient(4), 9.556697e-05);
  EXPECT_DOUBLE_EQ(asphere.profile.coefficient(10), -2.9989079999999998e-12);
  ASSERT_TRUE(asphere.glass);
  EXPECT_EQ(asphere.glass->name, "L-BAL35");
  EXPECT_EQ(asphere.glass->maker, "OHARA");
  EXPECT_EQ(lens.headerComments, (std::vector<std::string>{"Lens Asphere 15mm F/1.5 UNCTD"}));
  ASSERT_TRUE(lens.design.aperture);
  EXPECT_EQ(lens.design.aperture->kind, ApertureKind::EntrancePupilDiameterMm);
  EXPECT_EQ(lens.design.aperture->value, 15.0);
}

TEST(ZemaxFile, ThorlabsLatin1AsphereAt780nm) {
  const std::string name = "optiland/zemax/lens_thorlabs_iso_8859_1.zmx";
  const LensFileResult result = readReference(name);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  // The 0xD8 of the file is 'Ø' in the title, and the guess is in the log.
  EXPECT_NE(lens.title.find("\xC3\x98"), std::string::npos) << lens.title;
  EXPECT_TRUE(hasDiagnostic(result, Severity::Note, 0, "Latin-1"));
  ASSERT_EQ(lens.design.wavelengths.nanometres.size(), 1u);  // FTYP's count, not the 24 WAVM
  EXPECT_DOUBLE_EQ(lens.design.wavelengths.nanometres[0], 780.0);
  const FirstOrderData first = firstOrderAtPrimary(lens);
  EXPECT_NEAR(first.eflMm, 14.9956, 5e-4);  // Thorlabs AL1815-C: 15 mm at 780 nm
  EXPECT_NEAR(first.bflMm, 11.5063, 5e-4);
  // The note OpticStudio cut after 200 characters ("...TECHSUPPORT@THORL" + "ABS.COM") is whole.
  ASSERT_FALSE(lens.headerComments.empty());
  EXPECT_EQ(lens.headerComments[0].substr(0, 26), "FOR INFORMATION ONLY, NOT ");
  EXPECT_EQ(lens.headerComments[0].size(), 207u) << lens.headerComments[0];
  EXPECT_NE(lens.headerComments[0].find("TECHSUPPORT@THORLABS.COM"), std::string::npos);
  // Coatings are ignored, with one note at the first.
  EXPECT_TRUE(hasDiagnostic(result, Severity::Note, lineContaining(referenceText(name), "  COAT "),
                            "coatings (COAT THORC, and any others) are ignored"));
}

TEST(ZemaxFile, EdmundAchromatPairWithLegacyBk7) {
  // GLAS BK7: no catalogue lenslab has holds it; its successor N-BK7 with a warning naming both.
  const std::string name = "ray-optics/zemax/zmax_55278.zmx";
  const LensFileResult result = readReference(name);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const std::string text = referenceText(name);
  EXPECT_TRUE(hasDiagnostic(result, Severity::Warning, lineContaining(text, "GLAS BK7"),
                            "glass BK7 is in no catalogue lenslab has; substituting N-BK7"));
  const FirstOrderData first = firstOrderAtPrimary(*result.lens);
  EXPECT_NEAR(first.eflMm, 52.2429, 5e-4);  // Edmund 52.24
  EXPECT_NEAR(first.bflMm, 43.7077, 5e-4);
  EXPECT_EQ(result.lens->design.wavelengths.primaryIndex, 1);
}

TEST(ZemaxFile, ClarkDoubleGaussWithPickups) {
  const LensFileResult result = readReference("ray-optics/zemax/US00583336-2-scaled.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  EXPECT_NEAR(firstOrderAtPrimary(lens).eflMm, 49.3890, 5e-4);
  ASSERT_TRUE(lens.design.aperture);
  EXPECT_EQ(lens.design.aperture->kind, ApertureKind::ImageFNumber);
  EXPECT_EQ(lens.design.aperture->value, 4.5);
  EXPECT_EQ(lens.design.fields.kind, FieldKind::ObjectAngleDeg);
  EXPECT_EQ(lens.design.fields.values, (std::vector<double>{0.0, 17.0, 24.0}));
}

// A paraxial y-nu trace written out here, independent of LensSystem: the focal length of surfaces
// with curvatures c (1/mm), gaps t (mm) and the index after each.
double eflByHand(const std::vector<double>& c, const std::vector<double>& t,
                 const std::vector<double>& n) {
  double y = 1.0, nu = 0.0, index = 1.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    nu -= y * (n[i] - index) * c[i];
    index = n[i];
    if (i + 1 < c.size()) y += t[i] * nu / index;
  }
  return -1.0 / nu;
}

TEST(ZemaxFile, PlaceholderGlassNumbersAreNotIndices) {
  // Every GLAS line carries 1.5 and 40 (placeholders); the catalogues' own indices count. The
  // focal length by hand, with the makers' catalogue n_d (nd_cat in data/glass/, d line, the
  // primary wavelength): J-LAK14 (HIKARI) 1.6968, L-TIM28 (OHARA, for L-TIM28_MOLD) 1.689479,
  // SF11 (SCHOTT, first in GCAT; HIKARI's is the same to 1e-6) 1.78472, TAF3 (HOYA) 1.8042,
  // TAFD30 (HOYA) 1.883. The asphere's terms do not change a paraxial focal length.
  const std::string name = "ray-optics/zemax/US08427765-1.ZMX";  // upper-case extension
  const LensFileResult result = readReference(name);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const std::vector<double> c = {7.766990291262135200E-002,
                                 2.824858757062146900E-002,
                                 7.230657989877079000E-002,
                                 1.117818019226470000E-001,
                                 0.0,
                                 -1.204819277108433600E-001,
                                 -1.866019779809665800E-002,
                                 -2.668801708033093100E-002,
                                 -8.501232678738417100E-002,
                                 4.847309743092583300E-003,
                                 -3.770739064856711700E-002};
  const std::vector<double> t = {3.34, 0.29, 1.85, 4.25, 5.4, 0.65, 0.22, 3.62, 0.12, 3.5};
  const std::vector<double> n = {1.6968, 1.0,    1.689479, 1.0,   1.0, 1.78472,
                                 1.0,    1.8042, 1.0,      1.883, 1.0};
  const FirstOrderData first = firstOrderAtPrimary(*result.lens);
  EXPECT_NEAR(first.eflMm, eflByHand(c, t, n), 1e-4);
  const std::string text = referenceText(name);
  EXPECT_TRUE(hasDiagnostic(result, Severity::Warning, lineContaining(text, "L-TIM28_MOLD"),
                            "substituting L-TIM28 (OHARA"));
  const std::vector<Surface>& rows = result.lens->prescription.surfaces;
  ASSERT_TRUE(rows[5].glass);
  EXPECT_EQ(rows[5].glass->name, "SF11");
  EXPECT_EQ(rows[5].glass->maker, "SCHOTT");  // GCAT SCHOTT HIKARI ...: SCHOTT's, not HIKARI's
  EXPECT_TRUE(hasDiagnostic(result, Severity::Note, lineContaining(text, "GLAS SF11"),
                            "SF11 is in SCHOTT, HIKARI; using SCHOTT's"));
  // Design conditions: three wavelengths (FTYP), the second primary; real image heights; F/2.1.
  const DesignConditions& design = result.lens->design;
  ASSERT_EQ(design.wavelengths.nanometres.size(), 3u);
  EXPECT_NEAR(design.wavelengths.nanometres[0], 486.1327, 1e-9);
  EXPECT_NEAR(design.wavelengths.nanometres[1], 587.5618, 1e-9);
  EXPECT_NEAR(design.wavelengths.nanometres[2], 656.2725, 1e-9);
  EXPECT_EQ(design.wavelengths.primaryIndex, 1);
  EXPECT_EQ(design.fields.kind, FieldKind::RealImageHeightMm);
  EXPECT_EQ(design.fields.values, (std::vector<double>{0.0, 8.0, 13.6}));
  ASSERT_TRUE(design.aperture);
  EXPECT_EQ(design.aperture->kind, ApertureKind::ImageFNumber);
  EXPECT_EQ(design.aperture->value, 2.1);
}

TEST(ZemaxFile, CatalogueOrderAndNames) {
  // SF11 is in SCHOTT and HIKARI: the file's GCAT order decides, either way round.
  LensFileResult result = parseZemaxText(
      "GCAT HIKARI SCHOTT\nSURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 5\nSURF 2\n"
      "  CURV 0.02\n  DISZ 4\n  GLAS SF11 0 0 1.5 40\n  DIAM 6\nSURF 3\n  CURV -0.02\n"
      "  DISZ 48\n  DIAM 6\nSURF 4\n",
      "singlet.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->prescription.surfaces[1].glass->maker, "HIKARI");
  EXPECT_TRUE(
      hasDiagnostic(result, Severity::Note, 10, "SF11 is in HIKARI, SCHOTT; using HIKARI's"));
  // No GCAT: lenslab's maker order (SCHOTT first), said so.
  result = parseZemaxText(
      "SURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 5\nSURF 2\n  CURV 0.02\n  DISZ 4\n"
      "  GLAS SF11\n  DIAM 6\nSURF 3\n  CURV -0.02\n  DISZ 48\n  DIAM 6\nSURF 4\n",
      "singlet.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->prescription.surfaces[1].glass->maker, "SCHOTT");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Note, 9, "the file has no GCAT"));
  // SUMITA_AUG2011 is OpticStudio's name of Sumita's catalogue: K-FK5 is found in it, silently.
  result = parseZemaxText(
      "GCAT SUMITA_AUG2011\nSURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 5\nSURF 2\n"
      "  CURV 0.02\n  DISZ 4\n  GLAS K-FK5 0 0 1.5 40\n  DIAM 6\nSURF 3\n  CURV -0.02\n"
      "  DISZ 48\n  DIAM 6\nSURF 4\n",
      "singlet.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->prescription.surfaces[1].glass->maker, "SUMITA");
  EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.formatAll();
  // A glass outside the file's catalogues is used with a warning naming its maker.
  result = parseZemaxText(
      "GCAT SCHOTT\nSURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 5\nSURF 2\n"
      "  CURV 0.02\n  DISZ 4\n  GLAS S-LAH64\n  DIAM 6\nSURF 3\n  CURV -0.02\n"
      "  DISZ 48\n  DIAM 6\nSURF 4\n",
      "singlet.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_TRUE(hasDiagnostic(result, Severity::Warning, 10,
                            "glass S-LAH64 is not in the file's catalogues (GCAT SCHOTT)"));
  EXPECT_TRUE(hasDiagnostic(result, Severity::Warning, 10, "using S-LAH64 (OHARA"));
}

TEST(ZemaxFile, InchFileIsTheSameLensIn25Point4TimesTheMillimetres) {
  const std::string name = "optiland/zemax/circular_aperture_example_without_aperture.zmx";
  const std::string text = referenceText(name);
  const LensFileResult inches = parseZemaxText(text, name);
  ASSERT_TRUE(inches.ok()) << inches.diagnostics.formatAll();
  std::string asMillimetres = text;
  asMillimetres.replace(asMillimetres.find("UNIT IN"), 7, "UNIT MM");
  const LensFileResult millimetres = parseZemaxText(asMillimetres, name);
  ASSERT_TRUE(millimetres.ok()) << millimetres.diagnostics.formatAll();
  const FirstOrderData a = firstOrderAtPrimary(*inches.lens);
  const FirstOrderData b = firstOrderAtPrimary(*millimetres.lens);
  EXPECT_NEAR(a.eflMm, 25.4 * b.eflMm, 1e-9 * a.eflMm);
  EXPECT_NEAR(a.bflMm, 25.4 * b.bflMm, 1e-9 * std::abs(a.bflMm));
  // The entrance pupil 0.36 in; the fields are angles and stay as written.
  ASSERT_TRUE(inches.lens->design.aperture);
  EXPECT_NEAR(inches.lens->design.aperture->value, 0.36 * 25.4, 1e-12);
  EXPECT_EQ(inches.lens->design.fields.values, (std::vector<double>{0.0, 35.0, 50.0}));
}

TEST(ZemaxFile, AsphericCoefficientsScaleWithTheUnit) {
  // One EVENASPH surface in centimetres: z(r) = c r^2 / (1 + ...) + a1 r^2 + a2 r^4 in cm. In mm
  // the r^2i term's coefficient is a_i * 10^(1 - 2i); checked as the sag at r = 5 mm = 0.5 cm.
  const std::string text =
      "UNIT CM\nENPD 1\nSURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 1\nSURF 2\n  TYPE "
      "EVENASPH\n"
      "  CURV 0.1\n  PARM 1 0.01\n  PARM 2 0.002\n  PARM 3 -0.0004\n  DISZ 0.5\n  GLAS ___BLANK 1 "
      "0 1.5 60\n  DIAM 1.2\nSURF 3\n  CURV -0.05\n  DISZ 5\n  DIAM 1.2\nSURF 4\n";
  const LensFileResult result = parseZemaxText(text, "cm.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const Surface& asphere = result.lens->prescription.surfaces[1];
  EXPECT_DOUBLE_EQ(asphere.radiusMm, 100.0);
  EXPECT_DOUBLE_EQ(asphere.thicknessMm, 5.0);
  EXPECT_DOUBLE_EQ(asphere.apertureDiameterMm, 24.0);
  const double rCm = 0.5;
  const double sagCm = 0.1 * rCm * rCm / (1.0 + std::sqrt(1.0 - 0.01 * rCm * rCm)) +
                       0.01 * std::pow(rCm, 2) + 0.002 * std::pow(rCm, 4) -
                       0.0004 * std::pow(rCm, 6);
  const std::optional<double> sagMm = optics::sagMm(asphere.curvaturePerMm(), asphere.profile, 5.0);
  ASSERT_TRUE(sagMm);
  EXPECT_NEAR(*sagMm, 10.0 * sagCm, 1e-12);
  // A ___BLANK model glass: the numbers on its line.
  EXPECT_EQ(asphere.indexD, 1.5);
  EXPECT_EQ(asphere.abbeD, 60.0);
  EXPECT_FALSE(asphere.glass);
}

// --- Encodings ---

TEST(ZemaxFile, Utf16BigEndianReadsAsTheLittleEndianFile) {
  const std::string little = readBytes(kReference / "optiland/zemax/lens2.zmx");
  ASSERT_EQ(little.substr(0, 2), std::string("\xFF\xFE"));
  std::string big = little;
  for (std::size_t i = 0; i + 1 < big.size(); i += 2) std::swap(big[i], big[i + 1]);
  const LensFileResult a = parseZemaxBytes(little, "lens2.zmx");
  const LensFileResult b = parseZemaxBytes(big, "lens2-be.zmx");
  ASSERT_TRUE(a.ok()) << a.diagnostics.formatAll();
  ASSERT_TRUE(b.ok()) << b.diagnostics.formatAll();
  EXPECT_EQ(b.lens->title, a.lens->title);
  ASSERT_EQ(b.lens->prescription.surfaces.size(), a.lens->prescription.surfaces.size());
  for (std::size_t i = 0; i < a.lens->prescription.surfaces.size(); ++i) {
    EXPECT_EQ(b.lens->prescription.surfaces[i].radiusMm, a.lens->prescription.surfaces[i].radiusMm);
    EXPECT_EQ(b.lens->prescription.surfaces[i].profile, a.lens->prescription.surfaces[i].profile);
  }
  EXPECT_EQ(b.lens->rowLines, a.lens->rowLines);
}

TEST(ZemaxFile, AsciiTripletWithoutDiametersGetsThemDerived) {
  // Written by a program: ASCII, LF, no mark, and no DIAM at all; the clear apertures come from
  // the design (ENPD 8.33, fields to 12 degrees). The GLAS lines carry n_d values that are not the
  // catalogue's (N-SK16 1.62070 for 1.62041): the catalogue's count. Focal length by hand with
  // the makers' n_d (nd_cat): N-SK16 1.62041, N-SF2 1.64769, N-LAK9 1.691; the stop (SURF 5) is
  // a flat surface in air.
  const std::string name = "optiland/zemax/lens1.zmx";
  const std::string bytes = readBytes(kReference / name);
  ASSERT_EQ(decodeText(bytes).encoding, TextEncoding::Ascii);
  ASSERT_EQ(bytes.find('\r'), std::string::npos);
  const LensFileResult result = readReference(name);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  const std::vector<double> c = {
      0.08038721978664398, -0.0055170138366520405, -0.08089042454957962, 0.09821353852748871, 0.0,
      0.03927339240908623, -0.08959288895130157};
  const std::vector<double> t = {5.514017105102539,  2.6377501487731934, 1.017357349395752,
                                 0.7544687986373901, 1.6761058568954468, 1.6096280813217163};
  const std::vector<double> n = {1.62041, 1.0, 1.64769, 1.0, 1.0, 1.691, 1.0};
  const FirstOrderData first = firstOrderAtPrimary(lens);
  EXPECT_NEAR(first.eflMm, eflByHand(c, t, n), 5e-4);
  // The stop sized for the stated entrance pupil: f-number EFL / 8.3333.
  ASSERT_TRUE(lens.design.aperture);
  EXPECT_EQ(lens.design.aperture->kind, ApertureKind::EntrancePupilDiameterMm);
  EXPECT_NEAR(first.entrancePupil.diameterMm, 8.333333969116211, 1e-6);
  EXPECT_EQ(lens.design.wavelengths.primaryIndex, 1);
  EXPECT_EQ(lens.design.fields.values,
            (std::vector<double>{0.0, 8.485281610363037, 12.000000333930423}));
  for (const Surface& surface : lens.prescription.surfaces)
    EXPECT_GT(surface.apertureDiameterMm, 0.0);
}

TEST(ZemaxFile, FloatingStopTooLargeForItsLensIsRefused) {
  // FLOA: the stop's DIAM 8.5 is the aperture. 10 mm behind a biconvex lens of radius 20, a 17 mm
  // beam would need rays beyond the lens's own radius: the derivation of the other surfaces'
  // diameters says so, at the first surface.
  const std::string name = "optiland/zemax/lens_floa.zmx";
  const LensFileResult result = readReference(name);
  EXPECT_FALSE(result.ok());
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, lineContaining(referenceText(name), "SURF 1"),
                            "does not pass the lens"))
      << result.diagnostics.formatAll();
}

TEST(ZemaxFile, CutUtf16FileIsAnError) {
  std::string bytes = readBytes(kReference / "optiland/zemax/lens2.zmx");
  bytes.pop_back();
  const LensFileResult result = parseZemaxBytes(bytes, "cut.zmx");
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.diagnostics.formatAll().find("odd number of bytes"), std::string::npos)
      << result.diagnostics.formatAll();
}

// --- Refusals, each at its line and naming what it is ---

void expectRefusal(const std::string& name, const std::string& needle, const std::string& message) {
  SCOPED_TRACE(name);
  const LensFileResult result = readReference(name);
  EXPECT_FALSE(result.ok());
  const int line = lineContaining(referenceText(name), needle);
  ASSERT_GT(line, 0) << needle;
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, line, message))
      << "expected '" << message << "' at line " << line << ":\n"
      << result.diagnostics.formatAll();
}

TEST(ZemaxFile, RefusesWhatLenslabCannotModelAtItsLine) {
  expectRefusal("optiland/zemax/one_mirror_up_45deg.zmx", "GLAS MIRROR", "is a mirror");
  expectRefusal("optiland/zemax/simple_fold_mirror_up.zmx", "TYPE COORDBRK",
                "TYPE COORDBRK: a coordinate break");
  expectRefusal("optiland/zemax/thorlabs_lj1598l1.zmx", "TYPE TOROIDAL",
                "TYPE TOROIDAL: a toroidal or cylindrical surface");
  expectRefusal("ray-optics/zemax/ASL5040-UV-Zemax(ZMX).zmx", "TYPE QED_TYPE",
                "TYPE QED_TYPE: a Forbes Q-type asphere");
  expectRefusal("optiland/zemax/flat_transmission_grating.zmx", "TYPE DGRATING",
                "TYPE DGRATING: a diffraction grating");
  expectRefusal("ray-optics/zemax/zmax_37992.zmx", "SCBD", "a tilt or decentre (SCBD)");
  expectRefusal("optiland/zemax/thorlabs_lj1598l1.zmx", "SQAP", "a rectangular aperture");
}

TEST(ZemaxFile, GlassInNoCatalogueIsNamedInTheError) {
  // D-ZK3M (LightPath): lenslab's LIGHTPATH catalogue does not have it; never a default index.
  const std::string name = "ray-optics/zemax/354710-C-Zemax(ZMX).zmx";
  const LensFileResult result = readReference(name);
  EXPECT_FALSE(result.ok());
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error,
                            lineContaining(referenceText(name), "GLAS D-ZK3M"), "\"D-ZK3M\""))
      << result.diagnostics.formatAll();
}

TEST(ZemaxFile, OtherSurfaceTypesAndFileDamage) {
  const std::string head = "SURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 5\n";
  LensFileResult result =
      parseZemaxText(head + "SURF 2\n  TYPE BINARY_2\n  DIAM 5\nSURF 3\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 7, "TYPE BINARY_2: a binary optic"));
  result = parseZemaxText(head + "SURF 2\n  TYPE FANCY\nSURF 3\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 7, "a surface type lenslab cannot model"));
  result = parseZemaxText(head + "SURF 2\n  DISZ 1e400\nSURF 3\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 7, "not a finite number"));
  result = parseZemaxText(head +
                              "SURF 2\n  TYPE EVENASPH\n  PARM 0 0\n  PARM 9 1e-20\n  DIAM 5\n"
                              "SURF 3\n",
                          "t.zmx");
  EXPECT_FALSE(hasDiagnostic(result, Severity::Error, 8, "PARM"));  // PARM 0 0: unused
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 9, "EVENASPH has PARM 1 to 8"));
  result = parseZemaxText("SURF 0\nSURF 1\nSURF 258\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 3, "too many surfaces"));
  result = parseZemaxText("YFLN 0 95\nFTYP 0 0 2 0\n" + head + "SURF 2\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 1, "field 2 (95 degrees)"));
  result = parseZemaxText("UNIT METER\nENPD 500\n" + head + "SURF 2\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 2, "entrance pupil diameter 500000"));
  result = parseZemaxText("", "empty.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 1, "empty file"));
  result = parseZemaxText("MODE NSC\n" + head + "SURF 2\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 1, "sequential"));
  result = parseZemaxText(head + "SURF 2\n  STOP\n  DIAM 5\nSURF 3\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 7,
                            "a second STOP, on SURF 2 (the first is SURF 1, line 4)"));
  result =
      parseZemaxText(head + "SURF 2\n  GLAS NOSUCHGLASS 0 0 1.5 40\n  DIAM 5\nSURF 3\n", "t.zmx");
  EXPECT_TRUE(hasDiagnostic(result, Severity::Error, 7, "\"NOSUCHGLASS\""));
}

TEST(ZemaxFile, FieldsOffTheYAxisAreTheirDistanceFromIt) {
  const std::string lens =
      "SURF 0\n  DISZ INFINITY\nSURF 1\n  STOP\n  DIAM 5\n  DISZ 2\nSURF 2\n  CURV 0.02\n"
      "  GLAS ___BLANK 1 0 1.5 60\n  DISZ 3\n  DIAM 6\nSURF 3\n  CURV -0.02\n  DISZ 50\n"
      "  DIAM 6\nSURF 4\n  CURV -0.01\nMNUM 3 1\n";
  // Object heights (FTYP 1) in inches: (3, 4) is 5 in from the axis, 127 mm.
  LensFileResult result =
      parseZemaxText("UNIT IN\nFTYP 1 0 2 0\nXFLN 0 3\nYFLN 0 4\n" + lens, "xy.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->design.fields.kind, FieldKind::ObjectHeightMm);
  ASSERT_EQ(result.lens->design.fields.values.size(), 2u);
  EXPECT_NEAR(result.lens->design.fields.values[1], 127.0, 1e-12);
  EXPECT_TRUE(hasDiagnostic(result, Severity::Note, 3, "read as their distance from the axis"));
  // Angles: the angle whose tangent is the tangents' length.
  result = parseZemaxText("FTYP 0 0 2 0\nXFLN 0 3\nYFLN 0 4\n" + lens, "xy.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const double degree = std::acos(-1.0) / 180.0;
  EXPECT_NEAR(result.lens->design.fields.values[1],
              std::atan(std::hypot(std::tan(3 * degree), std::tan(4 * degree))) / degree, 1e-12);
  // The image surface's curvature (lenslab's film is flat) and the configurations are warnings.
  EXPECT_TRUE(hasDiagnostic(result, Severity::Warning, 19,
                            "the image surface is curved (radius "
                            "-100 mm)"));
  EXPECT_TRUE(hasDiagnostic(result, Severity::Warning, 21, "the file has 3 configurations"));
}

TEST(ZemaxFile, FiniteObjectIsANote) {
  const std::string text =
      "FLOA\nSURF 0\n  DISZ 250\nSURF 1\n  STOP\n  DIAM 5\n  DISZ 2\nSURF 2\n  CURV 0.02\n"
      "  GLAS ___BLANK 1 0 1.5 60\n  DISZ 3\n  DIAM 6\nSURF 3\n  CURV -0.02\n  DISZ 50\n"
      "  DIAM 6\nSURF 4\n";
  const LensFileResult result = parseZemaxText(text, "near.zmx");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_TRUE(hasDiagnostic(result, Severity::Note, 3, "finite distance, 250 mm"));
  ASSERT_TRUE(result.lens->design.aperture);  // FLOA: the stop's own size
  EXPECT_EQ(result.lens->design.aperture->kind, ApertureKind::StopDiameter);
  // The stop is a flat surface in air: lenslab's stop row itself.
  EXPECT_TRUE(result.lens->prescription.surfaces[0].isStop());
  EXPECT_EQ(result.lens->prescription.surfaces.size(), 3u);
  EXPECT_EQ(result.lens->prescription.surfaces.back().thicknessMm, 50.0);  // the film distance
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

// Every .zmx of the reference folder opens, or is refused with an error at a line of the file
// (not at line 0 or 1 by default): the list in docs/file-formats.md.
TEST(ZemaxFile, EveryReferenceFileOpensOrIsRefusedAtALine) {
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kReference)) {
    if (!hasZemaxExtension(entry.path())) continue;
    ++files;
    const LensFileResult result = readLensFile(entry.path());
    const std::string name = entry.path().lexically_relative(kReference).string();
    if (result.ok()) {
      const FirstOrderData first = firstOrderAtPrimary(*result.lens);
      std::printf("opens    %-62s EFL %.4f BFL %.4f\n", name.c_str(), first.eflMm, first.bflMm);
      continue;
    }
    const Diagnostic* firstError = nullptr;
    for (const Diagnostic& d : result.diagnostics.all())
      if (d.severity == Severity::Error && !firstError) firstError = &d;
    ASSERT_TRUE(firstError) << name;
    EXPECT_GT(firstError->location.line, 1) << firstError->format();
    std::printf("refused  %-62s %d: %s\n", name.c_str(), firstError->location.line,
                firstError->message.c_str());
  }
  EXPECT_EQ(files, 28);
}

}  // namespace
}  // namespace lenslab::optics
