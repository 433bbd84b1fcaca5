#include "optics/import/patent_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "optics/lens_system.h"
#include "optics/limiting_aperture.h"
#include "support/hostile_patent_table.h"

namespace lenslab::optics {
namespace {

std::string readText(const std::string& name) {
  std::ifstream in(std::filesystem::path(LENSLAB_PATENT_TEXT_DIR) / name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// An independent paraxial EFL from the rows as understood (a y-nu trace of the table, object at
// infinity, d-line indices): not lenslab's paraxial code.
double yNuEfl(const std::vector<PatentTableRow>& rows) {
  double y = 1.0, nu = 0.0, n = 1.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PatentTableRow& r = rows[i];
    const double nAfter = r.indexD.value_or(1.0);
    const double c = std::isinf(r.radiusMm) || r.radiusMm == 0.0 ? 0.0 : 1.0 / r.radiusMm;
    nu = nu - y * c * (nAfter - n);
    n = nAfter;
    if (i + 1 < rows.size()) y += r.thicknessMm.value_or(0.0) * nu / n;
  }
  return -1.0 / nu;
}

const PatentTableRow& rowNumbered(const PatentTable& t, int number) {
  for (const PatentTableRow& r : t.rows)
    if (r.surfaceNumber == number) return r;
  static PatentTableRow none;
  ADD_FAILURE() << "no row " << number;
  return none;
}

const PatentAsphere* asphereOf(const PatentTable& t, int number) {
  for (const PatentAsphere& a : t.aspheres)
    if (a.surfaceNumber == number) return &a;
  return nullptr;
}

double term(const PatentAsphere& a, int power) {
  for (const auto& [p, v] : a.terms)
    if (p == power) return v;
  return 0.0;
}

std::string errors(const LensFileResult& r) { return r.diagnostics.formatAll(); }

// The reference folder's README gives the published focal lengths (in each file's header); the
// library's SOURCES.md says every table is within 0.1% of its published f, the tolerance here.
constexpr double kEflTolerance = 0.001;

struct Reference {
  const char* file;
  double publishedEflMm;  // the README's (each file's header), or SOURCES.md's for the Canon
  double publishedFNumber;
  std::size_t rows;
  int stopLine;
};

TEST(PatentTable, SonyJpStyleReadsAsPublished) {
  const PatentTableResult r = readPatentTable(readText("jp-style-sony-55.txt"), "sony.txt");
  const PatentTable& t = r.table;
  ASSERT_EQ(t.rows.size(), 15u) << errors(r.lens);
  EXPECT_EQ(t.headingLine, 6);
  // "7(Stop)  ∞  2.8100" on line 13.
  const PatentTableRow& stop = rowNumbered(t, 7);
  EXPECT_TRUE(stop.stop);
  EXPECT_EQ(stop.line, 13);
  EXPECT_TRUE(std::isinf(stop.radiusMm));
  int stops = 0;
  for (const PatentTableRow& row : t.rows) stops += row.stop;
  EXPECT_EQ(stops, 1);
  // Header ("Various data"): f 53.61, F-number 1.86, 2ω 44.30.
  ASSERT_TRUE(t.header.focalLengthMm);
  EXPECT_DOUBLE_EQ(t.header.focalLengthMm->value, 53.61);
  ASSERT_TRUE(t.header.fNumber);
  EXPECT_DOUBLE_EQ(t.header.fNumber->value, 1.86);
  ASSERT_TRUE(t.header.halfFieldDeg);
  EXPECT_DOUBLE_EQ(t.header.halfFieldDeg->value, 22.15);
  // The last d (row 15, 1.0000) is the film distance.
  ASSERT_TRUE(t.filmDistanceMm);
  EXPECT_DOUBLE_EQ(*t.filmDistanceMm, 1.0);
  // Surface 9, by hand from line 29:
  // K=0.00000E+00 A4=-1.66843E-05 A6=5.20407E-08 A8=3.77076E-12 A10=-6.66338E-13
  ASSERT_EQ(t.aspheres.size(), 5u);
  const PatentAsphere* a = asphereOf(t, 9);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->conic, 0.0);
  EXPECT_DOUBLE_EQ(term(*a, 4), -1.66843e-05);
  EXPECT_DOUBLE_EQ(term(*a, 6), 5.20407e-08);
  EXPECT_DOUBLE_EQ(term(*a, 8), 3.77076e-12);
  EXPECT_DOUBLE_EQ(term(*a, 10), -6.66338e-13);
  EXPECT_EQ(a->terms.size(), 4u);
  EXPECT_TRUE(rowNumbered(t, 9).aspheric);
  EXPECT_FALSE(rowNumbered(t, 7).aspheric);
  EXPECT_NEAR(yNuEfl(t.rows), 53.61, 53.61 * kEflTolerance);
}

TEST(PatentTable, SigmaEquationLinesReadAsPublished) {
  const PatentTableResult r = readPatentTable(readText("us-style-sigma-35.txt"), "sigma.txt");
  const PatentTable& t = r.table;
  ASSERT_TRUE(t.equationLayout);
  ASSERT_EQ(t.rows.size(), 27u) << errors(r.lens);
  const PatentTableRow& stop = rowNumbered(t, 15);
  EXPECT_TRUE(stop.stop);
  EXPECT_EQ(stop.line, 18);
  int stops = 0;
  for (const PatentTableRow& row : t.rows) stops += row.stop;
  EXPECT_EQ(stops, 1);
  // Glasses are numbered apart (N4 on R7's line): the row's own n and ν.
  EXPECT_DOUBLE_EQ(*rowNumbered(t, 7).indexD, 1.77250);
  EXPECT_DOUBLE_EQ(*rowNumbered(t, 7).abbeD, 49.5);
  EXPECT_FALSE(rowNumbered(t, 9).indexD);
  EXPECT_TRUE(rowNumbered(t, 7).aspheric);  // "R7 = 240.531 *"
  EXPECT_TRUE(rowNumbered(t, 25).aspheric);
  EXPECT_DOUBLE_EQ(t.header.focalLengthMm->value, 33.72);
  EXPECT_DOUBLE_EQ(t.header.fNumber->value, 1.46);
  EXPECT_DOUBLE_EQ(t.header.halfFieldDeg->value, 33.89);
  EXPECT_DOUBLE_EQ(*t.filmDistanceMm, 20.961);
  // R25, by hand from line 33; the formula (line 35) gives A h⁴ + B h⁶ + C h⁸ + D h¹⁰, and E, F
  // continue the series (h¹², h¹⁴):
  // k = 0.0000e+00, A = -4.0667e-06, B = 6.9253e-10, C = -6.1149e-11, D = 6.4287e-13,
  // E = -3.5297e-15, F = 8.5452e-18
  const PatentAsphere* a = asphereOf(t, 25);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->conic, 0.0);
  EXPECT_DOUBLE_EQ(term(*a, 4), -4.0667e-06);
  EXPECT_DOUBLE_EQ(term(*a, 6), 6.9253e-10);
  EXPECT_DOUBLE_EQ(term(*a, 8), -6.1149e-11);
  EXPECT_DOUBLE_EQ(term(*a, 10), 6.4287e-13);
  EXPECT_DOUBLE_EQ(term(*a, 12), -3.5297e-15);
  EXPECT_DOUBLE_EQ(term(*a, 14), 8.5452e-18);
  EXPECT_NEAR(yNuEfl(t.rows), 33.72, 33.72 * kEflTolerance);
}

TEST(PatentTable, NikonDExponentsReadAsPublished) {
  const PatentTableResult r = readPatentTable(readText("d-exponent-nikon-z50.txt"), "nikon.txt");
  const PatentTable& t = r.table;
  ASSERT_EQ(t.rows.size(), 26u) << errors(r.lens);
  // "STO  INFINITY  10.3200" on line 16 is surface 12; the flat 13 is not a stop.
  const PatentTableRow& stop = t.rows[11];
  EXPECT_TRUE(stop.stop);
  EXPECT_EQ(stop.line, 16);
  EXPECT_EQ(stop.surfaceNumber, 12);
  EXPECT_FALSE(rowNumbered(t, 13).stop);
  EXPECT_TRUE(std::isinf(rowNumbered(t, 13).radiusMm));
  EXPECT_DOUBLE_EQ(t.header.focalLengthMm->value, 51.6);
  EXPECT_DOUBLE_EQ(t.header.fNumber->value, 1.85);
  EXPECT_DOUBLE_EQ(t.header.halfFieldDeg->value, 22.94);
  // Surface 17, by hand from lines 35-36:
  // κ = 0.00000D+00;  A4 = 1.47643D-05  A6 = 2.08671D-08  A8 = 8.44852D-11  A10 = -6.93210D-13
  const PatentAsphere* a = asphereOf(t, 17);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->conic, 0.0);
  EXPECT_DOUBLE_EQ(term(*a, 4), 1.47643e-05);
  EXPECT_DOUBLE_EQ(term(*a, 6), 2.08671e-08);
  EXPECT_DOUBLE_EQ(term(*a, 8), 8.44852e-11);
  EXPECT_DOUBLE_EQ(term(*a, 10), -6.93210e-13);
  EXPECT_TRUE(rowNumbered(t, 6).aspheric);  // "*6": the mark before the number
  EXPECT_NEAR(yNuEfl(t.rows), 51.6, 51.6 * kEflTolerance);
}

TEST(PatentTable, CanonTabsReadAsPublished) {
  const PatentTableResult r = readPatentTable(readText("x10-tabs-canon-rf50.txt"), "canon.txt");
  const PatentTable& t = r.table;
  ASSERT_EQ(t.rows.size(), 12u) << errors(r.lens);
  // nd and νd come before r and d.
  ASSERT_EQ(t.columns.size(), 5u);
  EXPECT_EQ(t.columns[1].meaning, PatentColumn::IndexD);
  EXPECT_EQ(t.columns[2].meaning, PatentColumn::AbbeD);
  EXPECT_EQ(t.columns[3].meaning, PatentColumn::Radius);
  EXPECT_EQ(t.columns[4].meaning, PatentColumn::Thickness);
  const PatentTableRow& stop = rowNumbered(t, 6);
  EXPECT_TRUE(stop.stop);
  EXPECT_EQ(stop.line, 10);
  EXPECT_DOUBLE_EQ(rowNumbered(t, 7).radiusMm, -16.726);  // Unicode minus
  EXPECT_DOUBLE_EQ(*rowNumbered(t, 1).indexD, 1.83481);
  EXPECT_FALSE(rowNumbered(t, 2).indexD);
  // The header prints "f ?  Fno ?  2ω ?": nothing stated.
  EXPECT_FALSE(t.header.focalLengthMm);
  EXPECT_FALSE(t.header.fNumber);
  EXPECT_DOUBLE_EQ(*t.filmDistanceMm, 25.624);
  // Surface 10, by hand from line 21:
  // K 0  A4 −2.4162×10^−5  A6 −3.2915×10^−7  A8 1.9110×10^−10  A10 −9.2859×10^−13
  // A12 −2.2919×10^−13
  const PatentAsphere* a = asphereOf(t, 10);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->conic, 0.0);
  EXPECT_DOUBLE_EQ(term(*a, 4), -2.4162e-5);
  EXPECT_DOUBLE_EQ(term(*a, 6), -3.2915e-7);
  EXPECT_DOUBLE_EQ(term(*a, 8), 1.9110e-10);
  EXPECT_DOUBLE_EQ(term(*a, 10), -9.2859e-13);
  EXPECT_DOUBLE_EQ(term(*a, 12), -2.2919e-13);
  // SOURCES.md's published f for this example (the file's header gives none): 49.57.
  EXPECT_NEAR(yNuEfl(t.rows), 49.57, 49.57 * kEflTolerance);
}

// --- The four texts open as lenses (their clear apertures derived from the stated f-number) ---

struct OpenedLens {
  double eflMm = 0.0;
  double fNumber = 0.0;
  double limitedFNumber = 0.0;  // EFL over the limited entrance pupil: what the viewer shows
  bool stopLimits = false;
  std::size_t stopIndex = 0;
};

// Builds the lens the reader made and gives its paraxial EFL and f-number (lenslab's first-order
// data of the built lens at the d line).
std::optional<OpenedLens> openAsLens(const std::string& text, const std::string& name) {
  const PatentTableResult r = readPatentTable(text, name);
  EXPECT_TRUE(r.lens.ok()) << errors(r.lens);
  if (!r.lens.ok()) return std::nullopt;
  const BuildResult built = LensSystem::build(r.lens.lens->prescription);
  EXPECT_TRUE(built.ok()) << (built.errors.empty() ? "" : built.errors.front().message);
  if (!built.ok()) return std::nullopt;
  const FirstOrderData& first = built.system->firstOrder();
  const auto limit = findParaxialAxialLimit(*built.system, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(limit);
  if (!limit) return std::nullopt;
  return OpenedLens{first.eflMm, first.fNumber, limit->workingFNumber, limit->isStop,
                    *r.lens.lens->prescription.stopIndex()};
}

// The published focal lengths (the README's, in each file's header) and f-numbers, and the
// stop's row in lenslab's prescription (0-based).
TEST(PatentTableLenses, TheFourTextsOpenAtTheirPublishedFocalLengthAndFNumber) {
  struct Published {
    const char* file;
    double eflMm, fNumber;
    std::size_t stopRow;
  };
  const Published kPublished[] = {
      {"jp-style-sony-55.txt", 53.61, 1.86, 6},
      {"us-style-sigma-35.txt", 33.72, 1.46, 14},
      {"d-exponent-nikon-z50.txt", 51.6, 1.85, 11},
  };
  for (const Published& p : kPublished) {
    SCOPED_TRACE(p.file);
    const auto lens = openAsLens(readText(p.file), p.file);
    ASSERT_TRUE(lens);
    EXPECT_NEAR(lens->eflMm, p.eflMm, p.eflMm * kEflTolerance);
    EXPECT_NEAR(lens->fNumber, p.fNumber, 1e-6);
    // No other rim cuts the paraxial beam first: the f-number the viewer shows is the stated one.
    EXPECT_NEAR(lens->limitedFNumber, p.fNumber, 1e-6);
    EXPECT_TRUE(lens->stopLimits);
    EXPECT_EQ(lens->stopIndex, p.stopRow);
  }
}

TEST(PatentTableLenses, CanonTextStatesNoFNumberAndIsRefusedAtItsStop) {
  const PatentTableResult r = readPatentTable(readText("x10-tabs-canon-rf50.txt"), "canon.txt");
  ASSERT_FALSE(r.lens.ok());
  // The stop's row is line 10; the derivation names it.
  EXPECT_NE(errors(r.lens).find("canon.txt:10:1: error:"), std::string::npos) << errors(r.lens);
  EXPECT_NE(errors(r.lens).find("f-number"), std::string::npos) << errors(r.lens);
  // With SOURCES.md's published F/1.85 added to its header, it opens at 49.57 mm and f/1.85.
  const auto lens =
      openAsLens("Fno 1.85\n" + readText("x10-tabs-canon-rf50.txt"), "canon-with-fno.txt");
  ASSERT_TRUE(lens);
  EXPECT_NEAR(lens->eflMm, 49.57, 49.57 * kEflTolerance);
  EXPECT_NEAR(lens->fNumber, 1.85, 1e-6);
  EXPECT_NEAR(lens->limitedFNumber, 1.85, 1e-6);
  EXPECT_EQ(lens->stopIndex, 5u);
}

TEST(PatentTableLenses, ReadLensFileOpensTxtInAnyCase) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "lenslab-patent-txt";
  std::filesystem::create_directories(dir);
  for (const char* name : {"sony.txt", "sony.TXT", "sony.Txt"}) {
    std::ofstream(dir / name, std::ios::binary) << readText("jp-style-sony-55.txt");
    const LensFileResult r = readLensFile(dir / name);
    ASSERT_TRUE(r.ok()) << name << "\n" << errors(r);
    EXPECT_EQ(r.lens->prescription.surfaces.size(), 15u);
    ASSERT_TRUE(r.lens->publishedEflMm);
    EXPECT_DOUBLE_EQ(*r.lens->publishedEflMm, 53.61);
    ASSERT_TRUE(r.lens->design.aperture);
    EXPECT_EQ(r.lens->design.aperture->kind, ApertureKind::ImageFNumber);
    EXPECT_DOUBLE_EQ(r.lens->design.aperture->value, 1.86);
    EXPECT_EQ(r.lens->rowLines.front(), 7);
  }
  std::filesystem::remove_all(dir);
}

// --- Conventions, in small inline texts ---

// A two-element lens (a thin achromat-like pair and a stop), written in each convention; the
// readers must all give these rows.
void expectSmallLens(const PatentTableResult& r) {
  const PatentTable& t = r.table;
  ASSERT_EQ(t.rows.size(), 4u) << errors(r.lens);
  EXPECT_DOUBLE_EQ(t.rows[0].radiusMm, 50.0);
  EXPECT_DOUBLE_EQ(*t.rows[0].thicknessMm, 5.0);
  EXPECT_DOUBLE_EQ(*t.rows[0].indexD, 1.5168);
  EXPECT_DOUBLE_EQ(*t.rows[0].abbeD, 64.2);
  EXPECT_DOUBLE_EQ(t.rows[1].radiusMm, -200.0);
  EXPECT_DOUBLE_EQ(*t.rows[1].thicknessMm, 2.0);
  EXPECT_FALSE(t.rows[1].indexD);
  EXPECT_TRUE(std::isinf(t.rows[2].radiusMm));
  EXPECT_TRUE(t.rows[2].stop);
  EXPECT_DOUBLE_EQ(*t.rows[2].thicknessMm, 3.0);
  EXPECT_DOUBLE_EQ(t.rows[3].radiusMm, -80.0);
  EXPECT_DOUBLE_EQ(*t.rows[3].thicknessMm, 40.0);
}

TEST(PatentTableConventions, ColumnOrders) {
  expectSmallLens(
      readPatentTable("No r d nd vd\n"
                      "1 50 5 1.5168 64.2\n"
                      "2 -200 2\n"
                      "3(Stop) INF 3\n"
                      "4 -80 40\n",
                      "a.txt"));
  expectSmallLens(
      readPatentTable("Surface  Nd  Vd  r  d\n"
                      "1  1.5168  64.2  50  5\n"
                      "2                -200  2\n"
                      "3(Stop)          INF  3\n"
                      "4                -80  40\n",
                      "b.txt"));
  expectSmallLens(
      readPatentTable("i\tν\tn\td\tr\n"
                      "1\t64.2\t1.5168\t5\t50\n"
                      "2\t\t\t2\t-200\n"
                      "3 (stop)\t\t\t3\t∞\n"
                      "4\t\t\t40\t-80\n",
                      "c.txt"));
}

TEST(PatentTableConventions, InfinitySpellings) {
  for (const char* flat : {"\xE2\x88\x9E", "INF", "inf", "infinity", "INFINITY", "Infinity"}) {
    const std::string text =
        std::string("Surface r d nd vd\n1 50 5 1.5168 64.2\n2 -200 2\n3(Stop) ") + flat +
        " 3\n4 -80 40\n";
    SCOPED_TRACE(flat);
    expectSmallLens(readPatentTable(text, "inf.txt"));
  }
}

TEST(PatentTableConventions, StopMarkings) {
  for (const char* stopRow : {"3(Stop) INF 3", "3 (stop) INF 3", "STO INF 3", "S INF 3",
                              "3 INF (aperture stop) 3", "3 aperture stop INF 3"}) {
    const std::string text =
        std::string("Surface r d nd vd\n1 50 5 1.5168 64.2\n2 -200 2\n") + stopRow + "\n4 -80 40\n";
    SCOPED_TRACE(stopRow);
    expectSmallLens(readPatentTable(text, "stop.txt"));
  }
}

// The layout of ../shared/reference/library/tables: the heading is a comment line ("# surf ..."),
// air is n_d 1.0 with V_d "-", a semi-diameter column the reader does not use, and the stop is
// named in the last (note) column of a flat row.
TEST(PatentTableConventions, CommentedHeadingAndStopInANoteColumn) {
  const PatentTableResult r = readPatentTable(
      "# surf  radius   thickness  nd      vd     semi_diam  note\n"
      "  1     50       5          1.5168  64.2   20\n"
      "  2     -200     2          1.0     -      20\n"
      "  3     inf      3          1.0     -      15         STOP\n"
      "  4     -80      40         1.0     -      20\n",
      "library.txt");
  expectSmallLens(r);
  ASSERT_EQ(r.table.columns.size(), 7u);
  EXPECT_EQ(r.table.columns[0].meaning, PatentColumn::Surface);
  EXPECT_EQ(r.table.columns[5].meaning, PatentColumn::Ignored);
  EXPECT_FALSE(r.table.rows[0].stop);
  EXPECT_FALSE(r.table.rows[3].stop);
}
TEST(PatentTableConventions, StopOnARefractingSurfaceBecomesAStopRowAtItsVertex) {
  // A heading without a surface column: rows start with r.
  const PatentTableResult r = readPatentTable(
      "f=100 Fno=4\nr d nd vd\n"
      "50(Stop) 5 1.5168 64.2\n"
      "-200 45\n",
      "stop-on-surface.txt");
  ASSERT_EQ(r.table.rows.size(), 2u) << errors(r.lens);
  EXPECT_TRUE(r.table.rows[0].stop);
  EXPECT_DOUBLE_EQ(r.table.rows[0].radiusMm, 50.0);
  // The lens keeps the refracting surface and gains a stop row at its vertex (in front of it:
  // the surface bulges toward the object), with the row's line.
  ASSERT_TRUE(r.lens.ok()) << errors(r.lens);
  const std::vector<Surface>& s = r.lens.lens->prescription.surfaces;
  ASSERT_EQ(s.size(), 3u);
  EXPECT_TRUE(s[0].isStop());
  EXPECT_EQ(s[0].thicknessMm, 0.0);
  EXPECT_DOUBLE_EQ(s[1].radiusMm, 50.0);
  EXPECT_DOUBLE_EQ(s[1].thicknessMm, 5.0);
  EXPECT_EQ(r.lens.lens->rowLines, (std::vector<int>{3, 3, 4}));
  // A stop row labelled STO in such a table.
  const PatentTableResult sto =
      readPatentTable("Fno=4\nr d nd vd\n50 5 1.5168 64.2\n-200 2\nSTO INF 43\n", "sto.txt");
  ASSERT_EQ(sto.table.rows.size(), 3u) << errors(sto.lens);
  EXPECT_TRUE(sto.table.rows[2].stop);
  EXPECT_DOUBLE_EQ(*sto.table.rows[2].thicknessMm, 43.0);
  EXPECT_TRUE(sto.lens.ok()) << errors(sto.lens);
}

TEST(PatentTableConventions, ExponentNotations) {
  for (const char* a4 : {"-2.15E-06", "-2.15e-6", "-2.15D-06",
                         "-2.15\xC3\x97"
                         "10^-6",
                         "\xE2\x88\x92"
                         "2.15\xC3\x97"
                         "10^\xE2\x88\x92"
                         "6",
                         "-2.15x10-6",
                         "-2.15\xC3\x97"
                         "10\xE2\x81\xBB\xE2\x81\xB6"}) {
    const std::string text = std::string(
                                 "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n"
                                 "3(Stop) INF 3\n4 -80 40\n\nAspherical surface data\n"
                                 "1st surface\nK=-0.5 A4=") +
                             a4 + " A6=3.1E-9\n";
    SCOPED_TRACE(a4);
    const PatentTableResult r = readPatentTable(text, "exp.txt");
    ASSERT_EQ(r.table.aspheres.size(), 1u) << errors(r.lens);
    const PatentAsphere& a = r.table.aspheres[0];
    EXPECT_EQ(a.surfaceNumber, 1);
    EXPECT_DOUBLE_EQ(a.conic, -0.5);
    EXPECT_DOUBLE_EQ(term(a, 4), -2.15e-6);
    EXPECT_DOUBLE_EQ(term(a, 6), 3.1e-9);
  }
}

TEST(PatentTableConventions, AsphericMarkBeforeOrAfterTheNumber) {
  for (const char* row : {"*1 50 5 1.5168 64.2", "1* 50 5 1.5168 64.2"}) {
    const std::string text = std::string("Surface r d nd vd\n") + row +
                             "\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n\nAspheric coefficients\n"
                             "Surface 1: K = 0 A4 = 1.0E-05\n";
    SCOPED_TRACE(row);
    const PatentTableResult r = readPatentTable(text, "mark.txt");
    ASSERT_EQ(r.table.rows.size(), 4u) << errors(r.lens);
    EXPECT_TRUE(r.table.rows[0].aspheric);
    ASSERT_EQ(r.table.aspheres.size(), 1u);
    EXPECT_DOUBLE_EQ(term(r.table.aspheres[0], 4), 1.0e-5);
  }
}

TEST(PatentTableConventions, NikonKappaWithItsFormulaIsKPlusOne) {
  const std::string text =
      "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n\n"
      "Aspheric data\nS(y) = "
      "(y\xC2\xB2/r)/{1+(1\xE2\x88\x92\xCE\xBA\xC2\xB7y\xC2\xB2/r\xC2\xB2)^1/2} "
      "+ A4\xC2\xB7y\xE2\x81\xB4\nSurface 1: \xCE\xBA = 0.4 A4 = 1.0E-05\n";
  const PatentTableResult r = readPatentTable(text, "kappa.txt");
  ASSERT_EQ(r.table.aspheres.size(), 1u) << errors(r.lens);
  EXPECT_DOUBLE_EQ(r.table.aspheres[0].conic, 0.4 - 1.0);
}

TEST(PatentTableConventions, LetteredCoefficientsTakeTheFormulasPowers) {
  // Older Japanese examples start at B for h⁴ (A being the h² term they leave out); the formula
  // printed with the data says so, and the letters it does not show continue its series.
  const std::string text =
      "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n\n"
      "Aspherical coefficients\nX = (h\xC2\xB2/R)/[1+{1-(1+K)(h/R)\xC2\xB2}^1/2] + Bh\xE2\x81\xB4 "
      "+ "
      "Ch\xE2\x81\xB6\n1: K = -1 B = 1.5E-05 C = -2E-08 D = 3E-11 E = 4E-14\n";
  const PatentTableResult r = readPatentTable(text, "letters.txt");
  ASSERT_EQ(r.table.aspheres.size(), 1u) << errors(r.lens);
  const PatentAsphere& a = r.table.aspheres[0];
  EXPECT_DOUBLE_EQ(a.conic, -1.0);
  EXPECT_DOUBLE_EQ(term(a, 4), 1.5e-5);
  EXPECT_DOUBLE_EQ(term(a, 6), -2e-8);
  EXPECT_DOUBLE_EQ(term(a, 8), 3e-11);
  EXPECT_DOUBLE_EQ(term(a, 10), 4e-14);
  // Without a formula, CODE V's order: A is h⁴.
  const PatentTableResult plain = readPatentTable(
      "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n\n"
      "Aspherical coefficients\nR1: k = 0, A = 1.5E-05, B = -2E-08\n",
      "codev.txt");
  ASSERT_EQ(plain.table.aspheres.size(), 1u) << errors(plain.lens);
  EXPECT_DOUBLE_EQ(term(plain.table.aspheres[0], 4), 1.5e-5);
  EXPECT_DOUBLE_EQ(term(plain.table.aspheres[0], 6), -2e-8);
}

TEST(PatentTableConventions, HeaderValues) {
  const PatentTableResult r = readPatentTable(
      "f = 51.6  F-number = 2.8  \xCF\x89 = 20.5  Image height 21.6  BF = 38.2\n"
      "Surface r d nd vd\n1 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80\n",
      "header.txt");
  const PatentHeader& h = r.table.header;
  ASSERT_TRUE(h.focalLengthMm && h.fNumber && h.halfFieldDeg && h.imageHeightMm && h.backFocusMm)
      << errors(r.lens);
  EXPECT_DOUBLE_EQ(h.focalLengthMm->value, 51.6);
  EXPECT_DOUBLE_EQ(h.fNumber->value, 2.8);
  EXPECT_DOUBLE_EQ(h.halfFieldDeg->value, 20.5);
  EXPECT_DOUBLE_EQ(h.imageHeightMm->value, 21.6);
  EXPECT_DOUBLE_EQ(h.backFocusMm->value, 38.2);
  // The last row gives no d: the back focus is the film distance.
  ASSERT_TRUE(r.table.filmDistanceMm);
  EXPECT_DOUBLE_EQ(*r.table.filmDistanceMm, 38.2);
}

// The layout of ../shared/reference/library/tables (this project's transcriptions of 23 patent
// examples): a `# surf radius ...` heading, a semi-diameter and a remark column whose words mark
// the stop (`STOP`, not `flare stop`) and the aspheric surfaces (`ASPH`), and `ASPH <row>` naming
// a surface's coefficients. Largan's smartphone tables print `(ASP)` beside the radius.
TEST(PatentTableConventions, RemarkWordsMarkTheStopAndTheAsphericSurfaces) {
  const std::string text =
      "# published: FNO 4.0\n"
      "# surf  radius  thickness  nd      vd    semi_diam  note\n"
      "  1      50      5          1.5168  64.2  -          ASPH\n"
      "  2      -200    2          1.0     -     -          flare stop\n"
      "  3      0       3          1.0     -     -          STOP\n"
      "  4      -80     40         1.0     -     -          cover/filter plate\n"
      "#\n# aspheric surfaces (surf = row number above)\n"
      "ASPH 1 k=-0.5 A4=1.0e-05 A6=-2e-08 # from a transcription\n";
  const PatentTableResult r = readPatentTable(text, "remarks.txt");
  ASSERT_EQ(r.table.rows.size(), 4u) << errors(r.lens);
  EXPECT_TRUE(r.table.rows[0].aspheric);
  EXPECT_FALSE(r.table.rows[1].stop);  // a flare stop is a plane surface, not the iris
  EXPECT_TRUE(r.table.rows[2].stop);
  EXPECT_EQ(r.table.rows[2].radiusMm, 0.0);
  EXPECT_FALSE(r.table.rows[3].aspheric);
  EXPECT_DOUBLE_EQ(*r.table.rows[0].indexD, 1.5168);
  EXPECT_FALSE(r.table.rows[1].indexD);  // n_d 1.0: air
  ASSERT_EQ(r.table.aspheres.size(), 1u) << errors(r.lens);
  EXPECT_EQ(r.table.aspheres[0].surfaceNumber, 1);
  EXPECT_DOUBLE_EQ(r.table.aspheres[0].conic, -0.5);
  EXPECT_DOUBLE_EQ(term(r.table.aspheres[0], 4), 1.0e-5);
  EXPECT_DOUBLE_EQ(term(r.table.aspheres[0], 6), -2.0e-8);
  EXPECT_FALSE(r.lens.diagnostics.hasErrors()) << errors(r.lens);

  const PatentTableResult largan = readPatentTable(
      "Surface # r d nd vd\n1 50 (ASP) 5 1.5168 64.2\n2 -200 2\n3 Stop INF 3\n4 -80 40\n"
      "\nAspheric coefficients\nSurface 1: K = 0 A4 = 1.0E-05\n",
      "largan.txt");
  expectSmallLens(largan);
  EXPECT_TRUE(largan.table.rows[0].aspheric);
}

// The header of those tables: `2w` for 2ω, `half field`, and `F/4.00` as the f-number unless a
// word names one (a title's "f/3.5-5.6G" is not the example's FNO 3.56).
TEST(PatentTableConventions, HeaderValuesWithoutGreek) {
  const std::string table =
      "Surface r d nd vd\n1 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n";
  const PatentTableResult slash = readPatentTable(
      "# published: f = 14.420 mm, F/4.00, 2w = 115.36 deg (half field 57.68 deg)\n" + table,
      "slash.txt");
  const PatentHeader& h = slash.table.header;
  ASSERT_TRUE(h.fNumber && h.halfFieldDeg) << errors(slash.lens);
  EXPECT_DOUBLE_EQ(h.fNumber->value, 4.0);
  EXPECT_DOUBLE_EQ(h.halfFieldDeg->value, 57.68);
  const PatentTableResult worded = readPatentTable(
      "# title: Zoom 18-55mm f/3.5-5.6G\n# published: f = 18.5, FNO 3.56\n" + table, "worded.txt");
  ASSERT_TRUE(worded.table.header.fNumber) << errors(worded.lens);
  EXPECT_DOUBLE_EQ(worded.table.header.fNumber->value, 3.56);
  EXPECT_FALSE(worded.table.header.halfFieldDeg);
}

TEST(PatentTableConventions, OverridingAColumnRereads) {
  // Headings the reader does not know ("Gap", "Rad."): it takes the usual order (r before d),
  // which is wrong here, and says so; overriding the two columns reads the lens.
  const std::string text =
      "No Gap Rad. nd vd\n1 5 50 1.5168 64.2\n2 2 -200\n3(Stop) 3 INF\n4 40 -80\n";
  const PatentTableResult first = readPatentTable(text, "override.txt");
  ASSERT_EQ(first.table.columns.size(), 5u);
  EXPECT_EQ(first.table.columns[1].meaning, PatentColumn::Radius);
  EXPECT_NE(errors(first.lens).find("override.txt:2:1: note: no heading names the r and d columns"),
            std::string::npos)
      << errors(first.lens);
  std::vector<std::optional<PatentColumn>> overrides(5);
  overrides[1] = PatentColumn::Thickness;
  overrides[2] = PatentColumn::Radius;
  expectSmallLens(readPatentTable(text, "override.txt", overrides));
  // And a swapped pair: reading nd as νd and νd as nd is refused as a glass (ν_d 1.5168).
  std::vector<std::optional<PatentColumn>> swapped(5);
  swapped[3] = PatentColumn::AbbeD;
  swapped[4] = PatentColumn::IndexD;
  const PatentTableResult third = readPatentTable(
      "No r d nd vd\n1 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n", "swap.txt", swapped);
  ASSERT_EQ(third.table.rows.size(), 4u) << errors(third.lens);
  EXPECT_DOUBLE_EQ(*third.table.rows[0].indexD, 64.2);
  EXPECT_TRUE(third.table.columns[3].overridden);
}

// --- Bad input: errors at line:column ---

TEST(PatentTableErrors, RowWithoutItsThickness) {
  const PatentTableResult r = readPatentTable(
      "Fno 2\nSurface r d nd vd\n1 50 5 1.5168 64.2\n2 -200\n3(Stop) INF 3\n4 -80 40\n", "bad.txt");
  ASSERT_FALSE(r.lens.ok());
  // Line 4, after "2 -200" (column 7).
  EXPECT_NE(errors(r.lens).find("bad.txt:4:7: error: surface 2 has no d (thickness)"),
            std::string::npos)
      << errors(r.lens);
}

TEST(PatentTableErrors, TabRowWithAnEmptyThicknessCell) {
  const PatentTableResult r = readPatentTable(
      "No.\tnd\tvd\tr\td\n1\t1.5168\t64.2\t50\t5\n2\t\t\t-200\t\n3 (stop)\t\t\tINF\t3\n"
      "4\t\t\t-80\t40\n",
      "tab.txt");
  ASSERT_FALSE(r.lens.ok());
  EXPECT_NE(errors(r.lens).find("tab.txt:3:"), std::string::npos) << errors(r.lens);
  EXPECT_NE(errors(r.lens).find("surface 2 has no d"), std::string::npos) << errors(r.lens);
}

TEST(PatentTableErrors, AsphericBlockNamingAnUnmarkedSurface) {
  const PatentTableResult r = readPatentTable(
      "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n\n"
      "Aspheric coefficients\nSurface 1: K = 0 A4 = 1.0E-05\nSurface 2: K = 0 A4 = 2.0E-05\n",
      "unmarked.txt");
  ASSERT_FALSE(r.lens.ok());
  EXPECT_NE(errors(r.lens).find("unmarked.txt:9:1: error: aspheric data for surface 2, whose row "
                                "(line 3) is not marked aspheric (*)"),
            std::string::npos)
      << errors(r.lens);
}

TEST(PatentTableErrors, MarkedSurfaceWithoutData) {
  const PatentTableResult r = readPatentTable(
      "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n3(Stop) INF 3\n4 -80 40\n", "nodata.txt");
  EXPECT_NE(errors(r.lens).find("nodata.txt:2:1: error: surface 1 is marked aspheric (*) but no "
                                "aspheric data name it"),
            std::string::npos)
      << errors(r.lens);
}

TEST(PatentTableErrors, NotANumberAndOverflowAtTheirColumn) {
  const PatentTableResult r = readPatentTable(
      "Surface r d nd vd\n1 50 5 1.5168 64.2\n2 -2O0 2\n3(Stop) INF 3\n4 -80 1e999\n", "nan.txt");
  const std::string e = errors(r.lens);
  EXPECT_NE(e.find("nan.txt:3:3: error: '-2O0' is not a number (r of surface 2)"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("nan.txt:5:7: error: d of surface 4 is out of range"), std::string::npos) << e;
}

TEST(PatentTableErrors, UnknownCoefficientAndMissingStop) {
  const PatentTableResult r = readPatentTable(
      "Surface r d nd vd\n1* 50 5 1.5168 64.2\n2 -200 2\n3 -80 40\n\nAspheric data\n"
      "Surface 1: K = 0 A4 = 1.0E-05 Q9 = 3\n",
      "coef.txt");
  const std::string e = errors(r.lens);
  EXPECT_NE(e.find("coef.txt:7:31: error: 'q9' is not an aspheric coefficient"), std::string::npos)
      << e;
  EXPECT_NE(e.find("the table marks no aperture stop"), std::string::npos) << e;
}

TEST(PatentTableErrors, NoTableAtAll) {
  const PatentTableResult r = readPatentTable("just some words\nand more\n", "none.txt");
  EXPECT_NE(errors(r.lens).find("none.txt:1:1: error: no surface table found"), std::string::npos);
  EXPECT_FALSE(readPatentTable("", "empty.txt").lens.ok());
}

// --- Hostile tables: each a clear error at line:column, never a crash, a NaN or a lens ---------

// The first error's "file:line:column: error: message", or "" when there is none.
std::string firstError(const PatentTableResult& r) {
  for (const Diagnostic& d : r.lens.diagnostics.all())
    if (d.severity == Severity::Error) return d.format();
  return "";
}

TEST(PatentTableHostile, TheBaseTableOpens) {
  const PatentTableResult r = readPatentTable(testing::hostilePatentTable(), "base.txt");
  EXPECT_TRUE(r.lens.ok()) << errors(r.lens);
}

TEST(PatentTableHostile, EachCaseIsAnErrorAtItsPlace) {
  const struct {
    const char* what;
    std::string text;
    std::string expected;  // the start of the first error: "line:column: error: message"
  } cases[] = {
      {"a middle row without its d", testing::hostilePatentTable(4, "2 -200"),
       "4:7: error: surface 2 has no d (thickness)"},
      {"a header with no Fno", testing::hostilePatentTable(1, "f = 52.1  2ω 20"),
       "5:1: error: surface 3: the stop has no diameter, and the file states no f-number"},
      {"aspheric data for a surface the table does not have",
       testing::hostilePatentTable(0, "", "Surface 9: K = 0 A4 = 1.0E-05\n"),
       "10:1: error: aspheric data for surface 9, which the table does not have"},
      {"a huge exponent in a coefficient",
       testing::hostilePatentTable(9, "Surface 1: K = -0.5 A4 = 1.0E+400"),
       "9:21: error: aspheric coefficient 'a4' is out of range"},
      {"a huge exponent in D notation",
       testing::hostilePatentTable(9, "Surface 1: K = -0.5 A4 = 1.0D+999"),
       "9:21: error: aspheric coefficient 'a4' is out of range"},
      {"a huge exponent in x10^ notation",
       testing::hostilePatentTable(9, "Surface 1: K = -0.5 A4 = 1.0×10^999"),
       "9:21: error: aspheric coefficient 'a4' is out of range"},
      {"a huge exponent on a radius", testing::hostilePatentTable(4, "2 -2e999 2"),
       "4:3: error: r of surface 2 is out of range"},
      {"a huge thickness", testing::hostilePatentTable(4, "2 -200 1e300"),
       "4:8: error: d 1e+300 of surface 2 is beyond lenslab's 1e+06 mm"},
      {"a huge exponent on the f-number",
       testing::hostilePatentTable(1, "f = 52.1  Fno 2e400  2ω 20"),
       "1:15: error: Fno is out of range"},
      {"nan as a radius", testing::hostilePatentTable(4, "2 nan 2"),
       "4:3: error: 'nan' is not a number (r of surface 2)"},
      {"inf as a thickness", testing::hostilePatentTable(4, "2 -200 inf"),
       "4:8: error: d of surface 2 is infinite"},
      {"NaN as a thickness", testing::hostilePatentTable(4, "2 -200 NaN"),
       "4:8: error: 'NaN' is not a number (d of surface 2)"},
      {"inf as n_d", testing::hostilePatentTable(3, "1* 50 5 inf 64.2"),
       "3:9: error: n_d inf of surface 1 is not a refractive index (1 to 10)"},
      {"n_d below 1", testing::hostilePatentTable(3, "1* 50 5 0.5 64.2"),
       "3:9: error: n_d 0.5 of surface 1 is not a refractive index (1 to 10)"},
      {"nan as V_d", testing::hostilePatentTable(3, "1* 50 5 1.5168 nan"),
       "3:16: error: 'nan' is not a number (V_d of surface 1)"},
      {"-inf as V_d", testing::hostilePatentTable(3, "1* 50 5 1.5168 -inf"),
       "3:16: error: V_d -inf of surface 1 is not an Abbe number"},
      {"nan as a coefficient", testing::hostilePatentTable(9, "Surface 1: K = -0.5 A4 = nan"),
       "9:21: error:"},
      {"inf as the conic constant",
       testing::hostilePatentTable(9, "Surface 1: K = inf A4 = 1.0E-07"),
       "9:12: error: aspheric coefficient 'k' is infinite"},
      {"nan as the f-number", testing::hostilePatentTable(1, "f = 52.1  Fno nan  2ω 20"),
       "1:15: error: Fno is not a number ('nan')"},
      {"a negative f-number", testing::hostilePatentTable(1, "f = 52.1  Fno -4  2ω 20"),
       "1:15: error: Fno -4 is below 0.5"},
      {"inf as the focal length", testing::hostilePatentTable(1, "f = inf  Fno 4.0  2ω 20"),
       "1:5: error: f is out of range"},
  };
  for (const auto& c : cases) {
    const PatentTableResult r = readPatentTable(c.text, "hostile.txt");
    EXPECT_FALSE(r.lens.ok()) << c.what;
    EXPECT_EQ(firstError(r).rfind("hostile.txt:" + c.expected, 0), 0u) << c.what << "\n"
                                                                       << errors(r.lens);
  }
}

TEST(PatentTableHostile, AHugeRadiusIsFlatWithANote) {
  const PatentTableResult r =
      readPatentTable(testing::hostilePatentTable(4, "2 1e300 2"), "huge.txt");
  ASSERT_TRUE(r.lens.ok()) << errors(r.lens);
  EXPECT_TRUE(r.lens.lens->prescription.surfaces[1].isFlat());
  EXPECT_NE(errors(r.lens).find("huge.txt:4:3: note: r 1e+300 of surface 2 is taken as flat"),
            std::string::npos)
      << errors(r.lens);
}

TEST(PatentTableHostile, ATableOfOneRow) {
  // One surface, the stop on it, the film 40 mm behind it in glass: a table cut short, refused at
  // its n_d; and one row of air without a stop.
  const PatentTableResult glass =
      readPatentTable("Fno 2\nSurface r d nd vd\n1(Stop) 50 40 1.5168 64.2\n", "one.txt");
  EXPECT_FALSE(glass.lens.ok());
  EXPECT_EQ(firstError(glass).rfind(
                "one.txt:3:15: error: the last surface (1) has n_d 1.5168: the film would be "
                "inside glass",
                0),
            0u)
      << errors(glass.lens);
  const PatentTableResult air = readPatentTable("Fno 2\nSurface r d nd vd\n1 50 40\n", "one.txt");
  EXPECT_FALSE(air.lens.ok());
  EXPECT_EQ(firstError(air).rfind("one.txt:2:1: error: the table marks no aperture stop", 0), 0u)
      << errors(air.lens);
}

}  // namespace
}  // namespace lenslab::optics
