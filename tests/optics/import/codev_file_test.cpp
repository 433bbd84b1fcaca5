#include "optics/import/codev_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "optics/glass/glass_catalog.h"
#include "optics/glass/glass_catalog_loader.h"
#include "optics/glass/glass_names.h"
#include "optics/lens_system.h"
#include "support/bundled_glass.h"

namespace lenslab::optics {
namespace {

const std::filesystem::path kSeqReference = LENSLAB_IMPORT_REFERENCE_DIR;

LensFileResult readSeqReference(const std::string& relative) {
  return readLensFile(kSeqReference / relative);
}

std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The lens as the file gives it, before the clear apertures are derived (readCodeVLens).
struct ReadOnly {
  std::optional<LensFile> lens;
  Diagnostics diagnostics;
};
ReadOnly readOnly(const std::string& relative) {
  ReadOnly read;
  const std::filesystem::path path = kSeqReference / relative;
  read.lens = readCodeVLens(fileText(path), path.string(), read.diagnostics);
  return read;
}

// Paraxial data do not depend on the clear apertures: every surface the file leaves without one
// gets a small one, so that the lens builds.
Prescription withNominalApertures(Prescription prescription) {
  for (Surface& s : prescription.surfaces)
    if (!(s.apertureDiameterMm > 0.0)) s.apertureDiameterMm = 1.0;
  return prescription;
}

// The first error's line, or 0.
int firstErrorLine(const Diagnostics& diagnostics) {
  for (const Diagnostic& d : diagnostics.all())
    if (d.severity == Severity::Error) return d.location.line;
  return 0;
}
std::vector<const Diagnostic*> errorsOf(const Diagnostics& diagnostics) {
  std::vector<const Diagnostic*> errors;
  for (const Diagnostic& d : diagnostics.all())
    if (d.severity == Severity::Error) errors.push_back(&d);
  return errors;
}
bool hasNoteContaining(const Diagnostics& diagnostics, const std::string& text, int line = 0) {
  return std::any_of(diagnostics.all().begin(), diagnostics.all().end(), [&](const Diagnostic& d) {
    return d.severity != Severity::Error && d.message.find(text) != std::string::npos &&
           (line == 0 || d.location.line == line);
  });
}

FirstOrderData firstOrderAt(const Prescription& prescription, double wavelengthNm) {
  const BuildResult built = LensSystem::build(prescription, wavelengthNm);
  EXPECT_TRUE(built.ok());
  return built.ok() ? built.system->firstOrder() : FirstOrderData{};
}

// An independent paraxial y-nu trace of the rows as a file gives them (radius, thickness, index
// after), the object at infinity: the EFL and the BFL.
struct YnuRow {
  double radiusMm, thicknessMm, indexAfter;
};
std::pair<double, double> ynuEflBfl(const std::vector<YnuRow>& rows) {
  double y = 1.0, nu = 0.0, n = 1.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double c = std::isinf(rows[i].radiusMm) ? 0.0 : 1.0 / rows[i].radiusMm;
    nu -= y * c * (rows[i].indexAfter - n);
    n = rows[i].indexAfter;
    if (i + 1 < rows.size()) y += rows[i].thicknessMm * nu / n;
  }
  return {-1.0 / nu, -y / nu};
}

double catalogIndex(const std::string& name, const std::string& maker, double wavelengthNm) {
  const GlassLookup found = defaultGlassCatalog().catalog->lookup(name, maker);
  EXPECT_TRUE(found) << name;
  return found ? refractiveIndexAt(*found.glass, wavelengthNm).index.value_or(0.0) : 0.0;
}

// A prescription's refracting rows (the stop row left out, its gap given to the row before), for
// comparing with a file's S lines.
std::vector<Surface> refractingRows(const Prescription& prescription) {
  std::vector<Surface> rows;
  for (const Surface& s : prescription.surfaces) {
    if (!s.isStop())
      rows.push_back(s);
    else if (!rows.empty())
      rows.back().thicknessMm += s.thicknessMm;
  }
  return rows;
}

// --- CODE V's own files, against CODE V's own numbers ---------------------------------------

TEST(CodeVFile, DoubleGaussMatchesCodeVsListing) {
  const LensFileResult result = readSeqReference("ray-optics/codev/ag_dblgauss.seq");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  EXPECT_EQ(lens.title, "Double Gauss F/2 -  Available Glasses");
  // 11 S lines; the sixth, flat in air with STO, is the stop row itself.
  const std::vector<Surface>& rows = lens.prescription.surfaces;
  ASSERT_EQ(rows.size(), 11u);
  ASSERT_EQ(lens.prescription.stopIndex(), std::optional<std::size_t>(5));
  EXPECT_EQ(lens.rowLines[5], 24);
  // RDM N: curvatures (the listing's RDY column).
  EXPECT_NEAR(rows[0].radiusMm, 56.20238, 5e-6);
  EXPECT_NEAR(rows[1].radiusMm, 152.28580, 5e-6);
  EXPECT_NEAR(rows[6].radiusMm, -28.37731, 5e-6);
  EXPECT_TRUE(rows[3].isFlat());
  // The image surface's -0.400269 is a defocus: the film is at IMG DIS 61.0873.
  EXPECT_NEAR(rows.back().thicknessMm, 61.0873, 5e-5);

  const DesignConditions& design = lens.design;
  EXPECT_EQ(design.wavelengths.nanometres, (std::vector<double>{656.3, 587.6, 486.1}));
  EXPECT_EQ(design.wavelengths.primaryIndex, 1);
  EXPECT_EQ(design.fields.kind, FieldKind::ObjectAngleDeg);
  ASSERT_EQ(design.fields.values.size(), 3u);
  EXPECT_NEAR(design.fields.values[2], 14.0, 1e-8);
  ASSERT_TRUE(design.aperture);
  EXPECT_EQ(design.aperture->kind, ApertureKind::EntrancePupilDiameterMm);
  EXPECT_EQ(design.aperture->value, 50.0);

  // INFINITE CONJUGATES at 587.6 nm, as the listing prints them (4 decimals).
  const FirstOrderData first = firstOrderAt(lens.prescription, 587.6);
  EXPECT_NEAR(first.eflMm, 100.0038, 1e-4);
  EXPECT_NEAR(first.bflMm, 61.4875, 1e-4);
  EXPECT_NEAR(first.fflMm, 29.3208, 1e-4);  // CODE V counts it from surface 1, toward the film
  EXPECT_NEAR(first.entrancePupil.diameterMm, 50.0, 1e-4);
  EXPECT_NEAR(first.entrancePupil.positionMm, 57.9120, 1e-4);
  EXPECT_NEAR(first.exitPupil.diameterMm, 57.3201, 1e-4);
  EXPECT_NEAR(first.exitPupil.positionMm, -53.1569, 1e-4);  // from the last surface

  // REFRACTIVE INDICES: the four glasses, from Schott's formulas.
  const double wavelengths[] = {656.3, 587.6, 486.1};
  const struct {
    std::size_t row;
    const char* name;
    double n[3];
  } glasses[] = {{0, "N-SSK2", {1.618769, 1.622292, 1.630455}},
                 {2, "N-SK2", {1.604134, 1.607379, 1.614860}},
                 {3, "F5", {1.598744, 1.603417, 1.614617}},
                 {7, "N-SK16", {1.617271, 1.620408, 1.627559}}};
  for (const auto& glass : glasses) {
    const Surface& row = rows[glass.row];
    ASSERT_TRUE(row.glass) << glass.name;
    EXPECT_EQ(row.glass->name, glass.name);
    EXPECT_EQ(row.glass->maker, "SCHOTT");
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(refractiveIndexAt(*row.glass, wavelengths[k]).index.value_or(0.0), glass.n[k],
                  1e-6)
          << glass.name << " at " << wavelengths[k];
  }
}

TEST(CodeVFile, EdmundAchromatsHaveCodeVsSolvedBackFocus) {
  // The PIM solve put the image at the paraxial focus (587.6 nm); the last thickness is it.
  const struct {
    const char* file;
    double bflMm;
    double stopDiameterMm;
  } cases[] = {{"ray-optics/codev/CODV_32327.seq", 95.951944, 24.0},
               {"ray-optics/codev/CODV_65564.seq", 0.917675, 0.5}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const ReadOnly result = readOnly(c.file);
    ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
    const Prescription& prescription = result.lens->prescription;
    // STO on the first, curved surface: a stop row at its vertex, with the surface's CIR.
    ASSERT_EQ(prescription.surfaces.size(), 4u);
    ASSERT_EQ(prescription.stopIndex(), std::optional<std::size_t>(0));
    EXPECT_EQ(prescription.surfaces[0].apertureDiameterMm, c.stopDiameterMm);
    EXPECT_EQ(prescription.surfaces[1].apertureDiameterMm, c.stopDiameterMm);
    const FirstOrderData first = firstOrderAt(withNominalApertures(prescription), 587.6);
    EXPECT_NEAR(first.bflMm, c.bflMm, 2e-6);
  }
}

TEST(CodeVFile, AspherizedAchromatWithOharaGlassesAndAFictitiousLayer) {
  const ReadOnly result = readOnly("ray-optics/codev/CODV_49664.seq");
  ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
  const std::vector<Surface> rows = refractingRows(result.lens->prescription);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].glass->name, "S-LAL8");
  EXPECT_EQ(rows[0].glass->maker, "OHARA");
  EXPECT_EQ(rows[1].glass->name, "S-TIH53");
  // 517000.520000: n_d 1.517, V_d 52.0, a model glass.
  EXPECT_FALSE(rows[2].glass);
  EXPECT_NEAR(rows[2].indexD, 1.517, 1e-12);
  EXPECT_NEAR(rows[2].abbeD.value_or(0.0), 52.0, 1e-12);
  EXPECT_EQ(rows[3].profile.conic(), 0.0);
  EXPECT_EQ(rows[3].profile.coefficient(4), 0.138925111836e-4);
  EXPECT_EQ(rows[3].profile.coefficient(6), -0.208175206307e-7);
  EXPECT_EQ(rows[3].profile.highestPower(), 6);
  // Edmund's 35 mm; the paraxial EFL from these glasses is 35.011 (SOURCES.md).
  const FirstOrderData first = firstOrderAt(withNominalApertures(result.lens->prescription), 587.6);
  EXPECT_NEAR(first.eflMm, 35.011, 1e-3);
  // By hand at lenslab's d line, where the model glass has its n_d exactly.
  const double d = LensSystem::kDefaultWavelengthNm;
  const FirstOrderData atD = firstOrderAt(withNominalApertures(result.lens->prescription), d);
  const double n1 = catalogIndex("S-LAL8", "OHARA", d);
  const double n2 = catalogIndex("S-TIH53", "OHARA", d);
  const auto [efl, bfl] = ynuEflBfl({{23.49999999999983, 9.0, n1},
                                     {-36.69999999999967, 2.5, n2},
                                     {kFlatRadius, 0.08, 1.517},
                                     {-323.006393602994, 28.077783387, 1.0}});
  EXPECT_NEAR(atD.eflMm, efl, 1e-9);
  EXPECT_NEAR(atD.bflMm, bfl, 1e-9);
}

TEST(CodeVFile, PolynomialAsphereInCurvatureMode) {
  // Both surfaces are flat: paraxially afocal (its power is all in A r^4).
  const ReadOnly result = readOnly("ray-optics/codev/asp46.seq");
  ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
  const Prescription& prescription = result.lens->prescription;
  // STO on the flat aspheric front: a stop row in front of it.
  ASSERT_EQ(prescription.surfaces.size(), 3u);
  EXPECT_TRUE(prescription.surfaces[0].isStop());
  const Surface& front = prescription.surfaces[1];
  EXPECT_TRUE(front.isFlat());
  EXPECT_EQ(front.profile.coefficient(4), -0.1);
  EXPECT_EQ(front.profile.coefficient(6), 0.1);
  EXPECT_EQ(front.profile.highestPower(), 6);
  EXPECT_NEAR(front.indexD, 1.5, 1e-12);  // glass 500.700
  EXPECT_NEAR(front.abbeD.value_or(0.0), 70.0, 1e-12);
  // CIR EDG is the mechanical edge, not a clear aperture.
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "CIR EDG", 11));
}

// --- Hand-written sequences (ray-optics' tests): comments, continuation, no RDM --------------

TEST(CodeVFile, HandWrittenSingletIsInCurvatureMode) {
  const ReadOnly result = readOnly("ray-optics/codev/singlet.seq");
  ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  EXPECT_EQ(lens.title, "singlet");
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "read as curvatures", 4));
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "no STO", 4));
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "100 mm in front", 3));
  const std::vector<Surface> rows = refractingRows(lens.prescription);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows[0].radiusMm, 10.0);  // s 0.1: c = 0.1
  EXPECT_DOUBLE_EQ(rows[1].radiusMm, -20.0);
  EXPECT_EQ(rows[0].glass->name, "N-BK7");
  EXPECT_EQ(rows[1].thicknessMm, 15.0);  // si 0 0: no defocus
  EXPECT_EQ(lens.design.fields.kind, FieldKind::ParaxialImageHeightMm);
  EXPECT_EQ(lens.design.fields.values, (std::vector<double>{0.0, 1.0}));
  ASSERT_TRUE(lens.design.aperture);
  EXPECT_EQ(lens.design.aperture->kind, ApertureKind::ImageFNumber);
  EXPECT_EQ(lens.design.wavelengths.primaryIndex, 0);  // no REF
  const double n = catalogIndex("N-BK7", "SCHOTT", 587.6);
  const auto [efl, bfl] = ynuEflBfl({{10.0, 1.0, n}, {-20.0, 15.0, 1.0}});
  EXPECT_NEAR(firstOrderAt(withNominalApertures(lens.prescription), 587.6).eflMm, efl, 1e-9);
}

TEST(CodeVFile, LandscapeLensStopIsItsFlatFirstSurface) {
  const LensFileResult result = readSeqReference("ray-optics/codev/landscape_lens.seq");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const Prescription& prescription = result.lens->prescription;
  ASSERT_EQ(prescription.surfaces.size(), 3u);
  EXPECT_TRUE(prescription.surfaces[0].isStop());
  EXPECT_EQ(prescription.surfaces[0].thicknessMm, 1.664);
  EXPECT_DOUBLE_EQ(prescription.surfaces[1].radiusMm, -5.0);
  EXPECT_DOUBLE_EQ(prescription.surfaces[2].radiusMm, 1.0 / -0.387040626);
  EXPECT_EQ(result.lens->design.wavelengths.primaryIndex, 1);  // ref 2
  const double n = catalogIndex("N-BK7", "SCHOTT", 587.6);
  const auto [efl, bfl] = ynuEflBfl({{-5.0, 0.22, n}, {1.0 / -0.387040626, 10.150245, 1.0}});
  const FirstOrderData first = firstOrderAt(prescription, 587.6);
  EXPECT_NEAR(first.eflMm, efl, 1e-9);
  EXPECT_NEAR(first.bflMm, bfl, 1e-9);
}

TEST(CodeVFile, TestSeqReadsThroughItsContinuationsAndRefusesOnlyItsBk7) {
  // Comments, '&' continuations and ';' on one line; "bk7" (Schott's old BK7, not N-BK7) is in
  // no catalogue lenslab has, and f2 is in three.
  const LensFileResult result = readSeqReference("ray-optics/codev/test.seq");
  ASSERT_FALSE(result.ok());
  const std::vector<const Diagnostic*> errors = errorsOf(result.diagnostics);
  ASSERT_EQ(errors.size(), 1u) << result.diagnostics.formatAll();
  EXPECT_EQ(errors[0]->location.line, 5);
  EXPECT_EQ(errors[0]->location.column, 9);
  EXPECT_NE(errors[0]->message.find("\"bk7\""), std::string::npos) << errors[0]->message;
  EXPECT_NE(errors[0]->message.find("N-BK7 (SCHOTT) is in the catalogue"), std::string::npos)
      << errors[0]->message;
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "using SCHOTT's", 8));
}

// --- Optiland's hand-written files -------------------------------------------------------------

TEST(CodeVFile, OptilandCookeTriplet) {
  const ReadOnly result = readOnly("optiland/codev/cooke_triplet.seq");
  ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  EXPECT_EQ(lens.title, "Cooke Triplet");
  ASSERT_EQ(lens.headerComments.size(), 1u);
  EXPECT_EQ(lens.headerComments[0], "Cooke Triplet lens \xE2\x80\x94 CODE V test file");
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "read as radii", 10));
  const std::vector<Surface> rows = refractingRows(lens.prescription);
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0].glass->name, "N-SK16");  // N-SK16_SCHOTT, the hyphen kept
  EXPECT_EQ(rows[2].glass->name, "F2");
  EXPECT_EQ(rows[2].glass->maker, "SCHOTT");
  const double sk16 = catalogIndex("N-SK16", "SCHOTT", 587.6);
  const double f2 = catalogIndex("F2", "SCHOTT", 587.6);
  const auto [efl, bfl] = ynuEflBfl({{22.01359, 3.795568, sk16},
                                     {-435.7602, 6.0, 1.0},
                                     {-22.21328, 2.0, f2},
                                     {20.29192, 4.750246, 1.0},
                                     {79.68360, 2.720573, sk16},
                                     {-18.39533, 42.20170, 1.0}});
  const FirstOrderData first = firstOrderAt(withNominalApertures(lens.prescription), 587.6);
  EXPECT_NEAR(first.eflMm, efl, 1e-9);
  EXPECT_NEAR(first.bflMm, bfl, 1e-9);
}

TEST(CodeVFile, OptilandAsphereWithModelGlassAndTermsWithoutAsp) {
  const ReadOnly result = readOnly("optiland/codev/asphere.seq");
  ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
  const std::vector<Surface> rows = refractingRows(result.lens->prescription);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].indexD, 1.5168);  // 1.5168:64.17
  EXPECT_EQ(rows[0].abbeD, 64.17);
  EXPECT_FALSE(rows[0].glass);
  EXPECT_EQ(rows[0].profile.conic(), -0.5);
  EXPECT_EQ(rows[0].profile.coefficient(4), 1.5e-6);
  EXPECT_EQ(rows[0].profile.coefficient(6), -2.3e-9);
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "not declared CON or ASP", 10));
  EXPECT_EQ(result.lens->design.fields.values, (std::vector<double>{0.0, 3.0}));
}

TEST(CodeVFile, OptilandFNumberAndFields) {
  const ReadOnly result = readOnly("optiland/codev/fno_fields.seq");
  ASSERT_TRUE(result.lens) << result.diagnostics.formatAll();
  const LensFile& lens = *result.lens;
  ASSERT_TRUE(lens.design.aperture);
  EXPECT_EQ(lens.design.aperture->kind, ApertureKind::ImageFNumber);
  EXPECT_EQ(lens.design.aperture->value, 4.0);
  EXPECT_EQ(lens.design.fields.values, (std::vector<double>{0.0, 5.0}));
  EXPECT_EQ(lens.design.wavelengths.nanometres, (std::vector<double>{550.0}));
  EXPECT_EQ(lens.design.fields.kind, FieldKind::ObjectAngleDeg);
}

TEST(CodeVFile, OptilandTelescopeObjectiveWithBareNames) {
  const LensFileResult result = readSeqReference("optiland/codev/telescope_objective.seq");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const Prescription& prescription = result.lens->prescription;
  ASSERT_EQ(prescription.surfaces.size(), 9u);  // nine S lines, the third the stop
  ASSERT_EQ(prescription.stopIndex(), std::optional<std::size_t>(2));  // S 0 0.015 / STO
  EXPECT_EQ(prescription.surfaces[0].glass->name, "N-PSK3");
  EXPECT_EQ(prescription.surfaces[5].glass->name, "S-LAL18");
  EXPECT_EQ(prescription.surfaces[7].glass->name, "N-SK16");
  // CAF2_DAIMON-20: Optiland names the data set (Daimon, 20 C) where CODE V has a maker.
  ASSERT_TRUE(prescription.surfaces[3].glass);
  EXPECT_EQ(glassNameKey(prescription.surfaces[3].glass->name), "CAF2");
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "DAIMON-20", 13));
  const double wavelength = 587.5618;
  std::vector<YnuRow> rows;
  for (const Surface& s : refractingRows(prescription))
    rows.push_back({s.radiusMm, s.thicknessMm,
                    s.glass ? refractiveIndexAt(*s.glass, wavelength).index.value_or(0.0) : 1.0});
  const auto [efl, bfl] = ynuEflBfl(rows);
  EXPECT_NEAR(firstOrderAt(prescription, wavelength).eflMm, efl, 1e-9);
}

TEST(CodeVFile, TheLensesLenslabCanModelOpenWithDerivedClearApertures) {
  // Surfaces without CIR are sized by finishImportedLens from the design aperture and fields; the
  // stated f-number and entrance pupil then hold.
  const struct {
    const char* file;
    ApertureKind kind;
    double value;
  } cases[] = {{"ray-optics/codev/ag_dblgauss.seq", ApertureKind::EntrancePupilDiameterMm, 50.0},
               {"ray-optics/codev/CODV_32327.seq", ApertureKind::EntrancePupilDiameterMm, 24.0},
               {"ray-optics/codev/CODV_65564.seq", ApertureKind::EntrancePupilDiameterMm, 0.5},
               {"ray-optics/codev/CODV_49664.seq", ApertureKind::EntrancePupilDiameterMm, 25.0},
               {"ray-optics/codev/singlet.seq", ApertureKind::ImageFNumber, 5.0},
               {"ray-optics/codev/landscape_lens.seq", ApertureKind::EntrancePupilDiameterMm, 1.0},
               {"optiland/codev/cooke_triplet.seq", ApertureKind::EntrancePupilDiameterMm, 10.0},
               {"optiland/codev/asphere.seq", ApertureKind::EntrancePupilDiameterMm, 5.0},
               {"optiland/codev/fno_fields.seq", ApertureKind::ImageFNumber, 4.0},
               {"optiland/codev/telescope_objective.seq", ApertureKind::ImageFNumber, 6.0}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const LensFileResult result = readSeqReference(c.file);
    EXPECT_TRUE(result.ok()) << result.diagnostics.formatAll();
    if (!result.ok()) continue;
    const double wavelength =
        result.lens->design.wavelengths.empty()
            ? 587.56
            : result.lens->design.wavelengths.nanometres[static_cast<std::size_t>(
                  result.lens->design.wavelengths.primaryIndex)];
    const FirstOrderData first = firstOrderAt(result.lens->prescription, wavelength);
    // The Edmund achromats' stop is their CIR (24 and 0.5 mm), under the EPD the files state (25
    // and 1 mm): the lens's rim limits the beam.
    if (c.kind == ApertureKind::ImageFNumber)
      EXPECT_NEAR(first.fNumber, c.value, 1e-6);
    else
      EXPECT_NEAR(first.entrancePupil.diameterMm, c.value, 1e-6 * c.value);
  }
}

// --- What lenslab refuses, at its line -------------------------------------------------------

TEST(CodeVFile, RefusesMirrorsDecentresPrivateGlassesAndDiffractiveSurfaces) {
  const struct {
    const char* file;
    int line;
    const char* what;
  } cases[] = {
      {"optiland/codev/mirror.seq", 8, "REFL: a mirror"},
      {"ray-optics/codev/paraboloid.seq", 6, "REFL: a mirror"},
      {"ray-optics/codev/dec_test.seq", 8, "YDE: a decentre"},
      {"ray-optics/codev/dec_tilt_test.seq", 7, "REFL: a mirror"},
      {"ray-optics/codev/tilt_test.seq", 8, "ADE: a tilt"},
      {"ray-optics/codev/dar_test.seq", 8, "ADE: a tilt"},
      {"ray-optics/codev/CODV_65988_noDOE.seq", 15, "PRV: a private glass catalogue"},
      {"ray-optics/codev/CODV_65988.seq", 15, "PRV: a private glass catalogue"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const LensFileResult result = readSeqReference(c.file);
    ASSERT_FALSE(result.ok());
    const std::vector<const Diagnostic*> errors = errorsOf(result.diagnostics);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0]->location.line, c.line) << result.diagnostics.formatAll();
    EXPECT_NE(errors[0]->message.find(c.what), std::string::npos) << errors[0]->message;
  }
  // The tilt test's second tilt, the DAR after it, and the diffractive surface of 65988.
  const LensFileResult dar = readSeqReference("ray-optics/codev/dar_test.seq");
  EXPECT_TRUE(std::any_of(
      dar.diagnostics.all().begin(), dar.diagnostics.all().end(),
      [](const Diagnostic& d) { return d.location.line == 9 && d.message.find("DAR:") == 0; }));
  const LensFileResult doe = readSeqReference("ray-optics/codev/CODV_65988.seq");
  EXPECT_TRUE(std::any_of(
      doe.diagnostics.all().begin(), doe.diagnostics.all().end(), [](const Diagnostic& d) {
        return d.location.line == 32 && d.message.find("DIF: a diffractive surface") == 0;
      }));
}

TEST(CodeVFile, EverySequenceInTheReferenceFolderOpensOrIsRefusedAtALine) {
  int opened = 0, refused = 0;
  for (const char* folder : {"ray-optics/codev", "optiland/codev"}) {
    for (const auto& entry : std::filesystem::directory_iterator(kSeqReference / folder)) {
      if (entry.path().extension() != ".seq") continue;
      SCOPED_TRACE(entry.path().filename().string());
      const LensFileResult result = readLensFile(entry.path());
      if (result.ok()) {
        ++opened;
        EXPECT_TRUE(LensSystem::build(result.lens->prescription).ok());
      } else {
        ++refused;
        EXPECT_GT(firstErrorLine(result.diagnostics), 0) << result.diagnostics.formatAll();
      }
      std::printf("%-28s %s\n", entry.path().filename().string().c_str(),
                  result.ok() ? "opens" : errorsOf(result.diagnostics).front()->format().c_str());
    }
  }
  EXPECT_EQ(opened + refused, 34);
}

// --- Syntax, in small texts ----------------------------------------------------------------

// A singlet with every aperture given, so that nothing needs deriving.
constexpr const char* kSinglet =
    "RDM;LEN\n"
    "TITLE 'A singlet; with ! and ;'\n"
    "EPD 10\n"
    "DIM M\n"
    "WL 587.6\n"
    "SO 0 1e10\n"
    "S 0 2\n"
    "  STO\n"
    "  CIR 5\n"
    "S 50 5 N-BK7\n"
    "  CIR 8\n"
    "S -50 45\n"
    "  CIR 8\n"
    "SI 0 0\n"
    "GO\n";

LensFileResult parse(const std::string& text) { return parseCodeVText(text, "inline.seq"); }

TEST(CodeVSyntax, ReadsASmallLens) {
  const LensFileResult result = parse(kSinglet);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->title, "A singlet; with ! and ;");
  const std::vector<Surface>& rows = result.lens->prescription.surfaces;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_TRUE(rows[0].isStop());
  EXPECT_EQ(rows[0].apertureDiameterMm, 10.0);
  EXPECT_EQ(rows[1].radiusMm, 50.0);
  EXPECT_EQ(rows[1].apertureDiameterMm, 16.0);
  EXPECT_EQ(result.lens->rowLines, (std::vector<int>{7, 10, 12}));
  EXPECT_TRUE(result.diagnostics.empty()) << result.diagnostics.formatAll();
}

TEST(CodeVSyntax, AnyCase) {
  std::string lower = kSinglet;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const LensFileResult result = parse(lower);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->prescription.surfaces[1].glass->name, "N-BK7");
  EXPECT_EQ(result.lens->title, "a singlet; with ! and ;");
}

TEST(CodeVSyntax, CommandsOnOneLineAndContinuedAcrossLines) {
  const LensFileResult result = parse(
      "RDM; EPD 10; WL 587.6 ! a comment; S 1 1 F2\n"
      "SO 0 1e10; S 0 2; STO; CIR 5\n"
      "S 50 &   ! the thickness and glass follow\n"
      "  5 N-BK7&\n"
      "; CIR 8\n"
      "S -50 45; CIR 8; SI 0 0; GO\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const std::vector<Surface>& rows = result.lens->prescription.surfaces;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].thicknessMm, 5.0);
  EXPECT_EQ(rows[1].glass->name, "N-BK7");
  EXPECT_EQ(rows[1].apertureDiameterMm, 16.0);
  EXPECT_EQ(result.lens->rowLines[1], 3);  // the line the S command starts on
}

TEST(CodeVSyntax, MissingGoIsANote) {
  std::string text = kSinglet;
  text.erase(text.find("GO\n"));
  const LensFileResult result = parse(text);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "no closing GO", 14));
}

TEST(CodeVSyntax, CommandsAfterGoAreNotRead) {
  const LensFileResult result = parse(std::string(kSinglet) + "XDE 5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_TRUE(hasNoteContaining(result.diagnostics, "after GO", 16));
}

TEST(CodeVSyntax, UnknownCommandIsRefusedAtItsLine) {
  std::string text = kSinglet;
  text.insert(text.find("S -50"), "  FOO 3\n");
  const LensFileResult result = parse(text);
  ASSERT_FALSE(result.ok());
  const std::vector<const Diagnostic*> errors = errorsOf(result.diagnostics);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]->location.line, 12);
  EXPECT_EQ(errors[0]->location.column, 3);
  EXPECT_NE(errors[0]->message.find("'FOO' is not a CODE V command"), std::string::npos);
}

TEST(CodeVSyntax, TextAfterAContinuationAndNonAsciiBytesAreErrors) {
  std::string text = kSinglet;
  text.replace(text.find("S 50 5 N-BK7"), 12, "S 50 & 5 N-BK7");
  LensFileResult result = parse(text);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(errorsOf(result.diagnostics)[0]->location.line, 10);
  EXPECT_EQ(errorsOf(result.diagnostics)[0]->location.column, 8);

  text = kSinglet;
  text.replace(text.find("N-BK7"), 5, "N-BK7\xC3\x98");
  result = parse(text);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(errorsOf(result.diagnostics)[0]->location.column, 13);
  EXPECT_NE(errorsOf(result.diagnostics)[0]->message.find("0xC3"), std::string::npos);

  // In a comment or a title, such bytes are text.
  text = kSinglet;
  text.replace(text.find("A singlet"), 9, "Objectif \xC3\xA0 50 mm");
  text.insert(0, "! Ein sch\xC3\xB6nes Objektiv\n");
  result = parse(text);
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  EXPECT_EQ(result.lens->headerComments, (std::vector<std::string>{"Ein sch\xC3\xB6nes Objektiv"}));
}

TEST(CodeVSyntax, DimensionsScaleLengthsAndAsphericTerms) {
  // The same singlet in centimetres, with an asphere: every length times 10, and A r^4 and
  // B r^6 in cm^-3 and cm^-5 times 10^-3 and 10^-5.
  const LensFileResult result = parse(
      "RDM\nDIM C\nEPD 1\nSO 0 1e10\nS 0 0.2; STO; CIR 0.5\n"
      "S 5 0.5 N-BK7; CIR 0.8; ASP; K -1; A 2e-3; B -4e-5\nS -5 4.5; CIR 0.8\nSI 0 0\nGO\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const std::vector<Surface>& rows = result.lens->prescription.surfaces;
  EXPECT_DOUBLE_EQ(rows[0].thicknessMm, 2.0);
  EXPECT_DOUBLE_EQ(rows[0].apertureDiameterMm, 10.0);
  EXPECT_DOUBLE_EQ(rows[1].radiusMm, 50.0);
  EXPECT_DOUBLE_EQ(rows[1].profile.conic(), -1.0);
  EXPECT_DOUBLE_EQ(rows[1].profile.coefficient(4), 2e-6);
  EXPECT_DOUBLE_EQ(rows[1].profile.coefficient(6), -4e-10);
  EXPECT_DOUBLE_EQ(rows[2].thicknessMm, 45.0);
  EXPECT_DOUBLE_EQ(result.lens->design.aperture->value, 10.0);

  // Inches, in curvature mode: c in 1/inch.
  const LensFileResult inches = parse(
      "RDM N\nDIM I\nSO 0 1e10\nS 0 0; STO; CIR 0.2\nS 0.5 0.2 N-BK7; CIR 0.3\n"
      "S -0.5 1.8; CIR 0.3\nGO\n");
  ASSERT_TRUE(inches.ok()) << inches.diagnostics.formatAll();
  EXPECT_DOUBLE_EQ(inches.lens->prescription.surfaces[1].radiusMm, 2.0 * 25.4);
  EXPECT_DOUBLE_EQ(inches.lens->prescription.surfaces[1].thicknessMm, 0.2 * 25.4);
}

TEST(CodeVSyntax, GlassCodesAndNames) {
  const struct {
    const char* glass;
    double nd, vd;
  } models[] = {{"517642", 1.517, 64.2},
                {"569.631", 1.569, 63.1},
                {"517000.520000", 1.517, 52.0},
                {"1.5168:64.17", 1.5168, 64.17}};
  for (const auto& m : models) {
    std::string text = kSinglet;
    text.replace(text.find("N-BK7"), 5, m.glass);
    const LensFileResult result = parse(text);
    ASSERT_TRUE(result.ok()) << m.glass << "\n" << result.diagnostics.formatAll();
    const Surface& row = result.lens->prescription.surfaces[1];
    EXPECT_FALSE(row.glass);
    EXPECT_NEAR(row.indexD, m.nd, 1e-12) << m.glass;
    EXPECT_NEAR(row.abbeD.value_or(0.0), m.vd, 1e-12) << m.glass;
  }
  const struct {
    const char* glass;
    const char* name;
    const char* maker;
  } names[] = {{"NSK16_SCHOTT", "N-SK16", "SCHOTT"},    {"nsk16_schott", "N-SK16", "SCHOTT"},
               {"'N-SK16_SCHOTT'", "N-SK16", "SCHOTT"}, {"SLAH66_OHARA", "S-LAH66", "OHARA"},
               {"F2_HIKARI", "F2", "HIKARI"},           {"n-psk3", "N-PSK3", "SCHOTT"}};
  for (const auto& n : names) {
    std::string text = kSinglet;
    text.replace(text.find("N-BK7"), 5, n.glass);
    const LensFileResult result = parse(text);
    ASSERT_TRUE(result.ok()) << n.glass << "\n" << result.diagnostics.formatAll();
    const Surface& row = result.lens->prescription.surfaces[1];
    ASSERT_TRUE(row.glass) << n.glass;
    EXPECT_EQ(row.glass->name, n.name);
    EXPECT_EQ(row.glass->maker, n.maker);
  }
  // A glass in no catalogue, a maker without it, a code with the wrong digits: errors at the
  // glass, never a default index.
  for (const char* bad : {"NBK8_SCHOTT", "SLAH66_SCHOTT", "51764", "1.52", "1.5:0"}) {
    std::string text = kSinglet;
    text.replace(text.find("N-BK7"), 5, bad);
    const LensFileResult result = parse(text);
    ASSERT_FALSE(result.ok()) << bad;
    const std::vector<const Diagnostic*> errors = errorsOf(result.diagnostics);
    ASSERT_EQ(errors.size(), 1u) << bad << "\n" << result.diagnostics.formatAll();
    EXPECT_EQ(errors[0]->location.line, 10) << bad;
    EXPECT_EQ(errors[0]->location.column, 8) << bad;
  }
}

TEST(CodeVSyntax, RefusalsAndChecksAtTheirLines) {
  const struct {
    const char* insert;  // before "S -50"
    const char* what;
  } cases[] = {{"  XDE 0.1\n", "XDE: a decentre"},
               {"  CDE 2\n", "CDE: a tilt"},
               {"  BEN\n", "BEN: a decentre"},
               {"  REV\n", "REV: a decentre"},
               {"  DIF DOE\n", "DIF: a diffractive"},
               {"  CIR OBS 2\n", "a central obscuration"},
               {"  STO\n", "a second STO"},
               {"  RDX 40\n", "a toroidal surface"},
               {"  REX 4\n", "rectangular"},
               {"  K 'x'\n", "is not a number"},
               {"ZOO 2\n", "'ZOO' is not a CODE V command"}};
  for (const auto& c : cases) {
    std::string text = kSinglet;
    text.insert(text.find("S -50"), c.insert);
    const LensFileResult result = parse(text);
    ASSERT_FALSE(result.ok()) << c.insert;
    const std::vector<const Diagnostic*> errors = errorsOf(result.diagnostics);
    ASSERT_EQ(errors.size(), 1u) << c.insert << result.diagnostics.formatAll();
    EXPECT_EQ(errors[0]->location.line, 12) << c.insert;
    EXPECT_NE(errors[0]->message.find(c.what), std::string::npos) << errors[0]->message;
  }
  // A zero decentre is none; variables, solves, labels and derivatives change nothing.
  std::string text = kSinglet;
  text.insert(
      text.find("S -50"),
      "  XDE 0; ADE 0.0\n  CCY 0; THC 100\n  THI HMY 0\n  SLB \"x\"\n  PIM\nDER VAL I1 2\n");
  const LensFileResult ignored = parse(text);
  EXPECT_TRUE(ignored.ok()) << ignored.diagnostics.formatAll();

  // An S thickness of 1e10 or more is infinity, which only the object may have.
  text = kSinglet;
  text.replace(text.find("S -50 45"), 8, "S -50 1e10");
  EXPECT_EQ(firstErrorLine(parse(text).diagnostics), 12);
  // A REF beyond the wavelengths.
  text = kSinglet;
  text.insert(text.find("SO"), "REF 2\n");
  EXPECT_EQ(firstErrorLine(parse(text).diagnostics), 6);
  // A curved image.
  text = kSinglet;
  text.replace(text.find("SI 0 0"), 6, "SI -80 0");
  EXPECT_EQ(firstErrorLine(parse(text).diagnostics), 14);
}

TEST(CodeVSyntax, EmptyAndSurfacelessTextsAreErrors) {
  for (const char* text : {"", "! only a comment\n", "RDM\nEPD 5\nGO\n"}) {
    const LensFileResult result = parse(text);
    ASSERT_FALSE(result.ok()) << text;
    EXPECT_GT(firstErrorLine(result.diagnostics), 0);
  }
}

TEST(CodeVFile, TheOptilandLac9SingletGivesOpticStudiosFocalLength) {
  // SOURCES.md: Optiland's validation singlet (optiland/optiland#710), with OpticStudio 2025 R2's
  // figures at 587.5618 nm: EFL 101.501826, back focal point 2.255622 beyond the image surface
  // (BFL 94.993968). The stop is on the curved rear surface; no CIR, so the apertures are derived
  // from the EPD.
  const LensFileResult result = parseCodeVText(
      "TIT 'LAC9 singlet'\nRDM\nDIM M\nEPD 25\nWL 587.5618\nREF 1\nYAN 0\n"
      "SO 0 1e13\nS 63.73364157 10 LAC9_HOYA\nS 653.2939232 92.7383463\nSTO\nSI 0 0\nGO\n",
      "lac9.seq");
  ASSERT_TRUE(result.ok()) << result.diagnostics.formatAll();
  const FirstOrderData first = firstOrderAt(result.lens->prescription, 587.5618);
  EXPECT_NEAR(first.eflMm, 101.501826, 2e-6);
  EXPECT_NEAR(first.bflMm, 94.993968, 2e-6);
  EXPECT_NEAR(first.entrancePupil.diameterMm, 25.0, 1e-9);
}

}  // namespace
}  // namespace lenslab::optics
