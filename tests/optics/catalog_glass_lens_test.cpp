// Catalogue glasses in a lens: read from a .lens file by name, their index at every wavelength
// from the maker's formula, refused outside its range, and kept out of the spectral batch trace,
// which follows model glasses only.

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "optics/glass/glass_catalog_loader.h"
#include "optics/native_lens_file.h"
#include "support/bundled_glass.h"
#include "test_lenses.h"

namespace lenslab::optics {
namespace {

// N-BK7 from SCHOTT's Sellmeier coefficients (B1..B3 = 1.03961212, 0.231792344, 1.01046945;
// C1..C3 = 0.00600069867, 0.0200179144, 103.560653 um^2), evaluated by hand (Python, double):
// n(486.1327) = 1.52237629, n(587.5618) = 1.51680003, n(656.2725) = 1.51432235,
// n(300) = 1.55277026.
constexpr double kBk7F = 1.52237629, kBk7D = 1.51680003, kBk7C = 1.51432235, kBk7At300 = 1.55277026;

const std::string kBk7Singlet =
    "lenslab-lens 1\n"
    "surface radius 50 thickness 5 glass nbk7 diameter 20\n"
    "surface radius -50 thickness 1 diameter 20\n"
    "stop thickness 45 diameter 10\n";

LensFileResult parseGlassLens(const std::string& text) {
  return parseNativeLensText(text, "g.lens");
}

std::string firstMessage(const LensFileResult& r) {
  return r.diagnostics.empty() ? std::string("(none)") : r.diagnostics.all().front().format();
}

TEST(CatalogGlassLens, ANamedGlassGivesTheMakersIndexAtEveryWavelength) {
  ASSERT_TRUE(defaultGlassCatalog().catalog) << defaultGlassCatalog().errors.front();
  const LensFileResult r = parseGlassLens(kBk7Singlet);
  ASSERT_TRUE(r.ok()) << firstMessage(r);
  const Surface& front = r.lens->prescription.surfaces[0];
  ASSERT_TRUE(front.glass);
  EXPECT_EQ(front.glass->name, "N-BK7");  // "nbk7" matched without case or hyphen
  EXPECT_EQ(front.glass->maker, "SCHOTT");
  EXPECT_NEAR(front.indexD, kBk7D, 1e-8);  // n_d from the formula, kept in the row
  const auto lens = LensSystem::build(r.lens->prescription);
  ASSERT_TRUE(lens.ok()) << lens.errors.front().toString();
  EXPECT_TRUE(lens.system->disperses());
  for (const auto& [wavelengthNm, n] :
       {std::pair{486.1327, kBk7F}, {587.5618, kBk7D}, {656.2725, kBk7C}, {300.0, kBk7At300}}) {
    const auto at = lens.system->withWavelength(wavelengthNm);
    ASSERT_TRUE(at) << wavelengthNm;
    EXPECT_NEAR(at->surfaces()[0].indexRear, n, 1e-8) << wavelengthNm;
    // The lensmaker's formula with that index: 1/f = (n - 1)(2/50 + (n - 1) 5 / (n 2500)).
    const double power = (n - 1.0) * (2.0 / 50.0 - (n - 1.0) * 5.0 / (n * 2500.0));
    EXPECT_NEAR(at->firstOrder().eflMm, 1.0 / power, 1e-6) << wavelengthNm;
  }
  // N-BK7's formula holds from 300 to 2500 nm: at 250 nm there is no index, and no lens.
  EXPECT_FALSE(lens.system->withWavelength(250.0));
  EXPECT_FALSE(lens.system->firstOrderAt(250.0));
  const BuildResult at250 = LensSystem::build(r.lens->prescription, 250.0);
  ASSERT_FALSE(at250.ok());
  EXPECT_EQ(at250.errors.front().surface, 0);
  EXPECT_NE(at250.errors.front().message.find("250 nm is outside"), std::string::npos)
      << at250.errors.front().message;
}

TEST(CatalogGlassLens, NamesMakersAndMistakesAreReportedWhereTheyAre) {
  ASSERT_TRUE(defaultGlassCatalog().catalog);
  // "surface radius 50 thickness 5 glass " is 36 characters: the name starts at column 37.
  LensFileResult r =
      parseGlassLens("lenslab-lens 1\nsurface radius 50 thickness 5 glass NBK8 diameter 20\n");
  ASSERT_FALSE(r.ok());
  const Diagnostic& unknown = r.diagnostics.all().front();
  EXPECT_EQ(unknown.location.line, 2);
  EXPECT_EQ(unknown.location.column, 37);
  EXPECT_NE(unknown.message.find("NBK8"), std::string::npos) << unknown.message;
  EXPECT_NE(unknown.message.find("N-BK7"), std::string::npos) << unknown.message;  // nearest
  // F5 is in several catalogues: SCHOTT's is taken, and a note says so at the name; with a
  // maker there is no note.
  r = parseGlassLens(
      "lenslab-lens 1\n"
      "surface radius 50 thickness 5 glass F5 diameter 20\n"
      "surface radius -50 thickness 1 diameter 20\n"
      "stop thickness 45 diameter 10\n");
  ASSERT_TRUE(r.ok()) << firstMessage(r);
  EXPECT_EQ(r.lens->prescription.surfaces[0].glass->maker, "SCHOTT");
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.all().front().severity, Severity::Note);
  EXPECT_NE(r.diagnostics.all().front().message.find("using SCHOTT's"), std::string::npos);
  r = parseGlassLens(
      "lenslab-lens 1\n"
      "surface radius 50 thickness 5 glass F5 maker cdgm diameter 20\n"
      "surface radius -50 thickness 1 diameter 20\n"
      "stop thickness 45 diameter 10\n");
  ASSERT_TRUE(r.ok()) << firstMessage(r);
  EXPECT_EQ(r.lens->prescription.surfaces[0].glass->maker, "CDGM");
  EXPECT_TRUE(r.diagnostics.empty());
  // A glass and numbers together, a maker alone, and an infrared material.
  r = parseGlassLens("lenslab-lens 1\nsurface radius 50 thickness 5 glass F5 nd 1.6 diameter 20\n");
  EXPECT_NE(firstMessage(r).find("not both"), std::string::npos) << firstMessage(r);
  r = parseGlassLens("lenslab-lens 1\nsurface radius 50 thickness 5 maker SCHOTT diameter 20\n");
  EXPECT_NE(firstMessage(r).find("'maker' without 'glass'"), std::string::npos);
  r = parseGlassLens(
      "lenslab-lens 1\nsurface radius 50 thickness 5 glass Ge maker MISC diameter 20\n");
  EXPECT_NE(firstMessage(r).find("no index in the visible"), std::string::npos) << firstMessage(r);
}

TEST(CatalogGlassLens, TheFileKeepsTheGlassByNameAndDatRefusesIt) {
  const LensFileResult r = parseGlassLens(kBk7Singlet);
  ASSERT_TRUE(r.ok()) << firstMessage(r);
  const std::string text = formatNativeLensText(*r.lens);
  EXPECT_NE(text.find("glass N-BK7 maker SCHOTT"), std::string::npos) << text;
  EXPECT_EQ(text.find(" nd "), std::string::npos) << text;  // the name, not its numbers
  const LensFileResult again = parseGlassLens(text);
  ASSERT_TRUE(again.ok()) << firstMessage(again);
  EXPECT_EQ(again.lens->prescription.surfaces[0].glass, r.lens->prescription.surfaces[0].glass);
  EXPECT_NE(whyNotDat(r.lens->prescription).find("surface 1's glass N-BK7 is a catalogue glass"),
            std::string::npos);
}

TEST(CatalogGlassLens, ARowsNumbersMustBeItsGlasss) {
  Prescription p = parseGlassLens(kBk7Singlet).lens->prescription;
  p.surfaces[0].indexD = 1.6;  // the number edited, the name left: a contradiction
  const auto errors = validate(p);
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors.front().surface, 0);
  EXPECT_NE(errors.front().message.find("are not those of glass N-BK7"), std::string::npos)
      << errors.front().message;
}

// A doublet of two catalogue glasses from different makers' formulas (Sellmeier for SCHOTT's
// N-BK7, OHARA's S-TIH6), then the stop.
const std::string kCatalogueDoublet =
    "lenslab-lens 1\n"
    "surface radius 40 thickness 6 glass N-BK7 maker SCHOTT diameter 20\n"
    "surface radius -30 thickness 2 glass S-TIH6 maker OHARA diameter 20\n"
    "surface radius -120 thickness 1 diameter 20\n"
    "stop thickness 45 diameter 10\n";

TEST(CatalogGlassLens, TheSpectralBatchTraceFollowsEachGlasssOwnFormula) {
  const LensFileResult file = parseGlassLens(kCatalogueDoublet);
  ASSERT_TRUE(file.ok()) << firstMessage(file);
  const auto lens = LensSystem::build(file.lens->prescription);
  ASSERT_TRUE(lens.ok());
  EXPECT_EQ(lens.system->spectralTraceProblem(), "");
  // Each ray against the scalar trace of the lens built at its wavelength, whose indices come
  // from the formulas themselves (glass.h's mediumIndexAt). The model glass of the same n_d and
  // V_d misses the glasses by up to 2e-3 at 380 nm, and the exit directions below by up to 1e-3.
  for (LensSystem::BatchKernel kernel :
       {LensSystem::BatchKernel::Portable, LensSystem::BatchKernel::Avx2,
        LensSystem::BatchKernel::Avx512}) {
    if (!LensSystem::batchKernelAvailable(kernel)) continue;
    for (float wavelengthNm : {380.0f, 430.0f, 486.1f, 587.6f, 656.3f, 720.0f, 780.0f}) {
      const auto atWavelength = lens.system->withWavelength(wavelengthNm);
      ASSERT_TRUE(atWavelength);
      for (double filmXMm : {0.0, 3.0, 8.0}) {
        // From a film point toward the rear surface, 3 mm off its centre.
        const glm::dvec3 origin{filmXMm, 0.0, 0.0};
        const glm::dvec3 direction =
            glm::normalize(glm::dvec3{3.0, 1.0, lens.system->rearVertexZ()} - origin);
        const std::optional<LensRay> exact = atWavelength->traceFromFilm({origin, direction});
        ASSERT_TRUE(exact);
        LensRayBatch rays;
        rays.resize(1);
        rays.ox[0] = static_cast<float>(origin.x);
        rays.oy[0] = rays.oz[0] = 0.0f;
        rays.dx[0] = static_cast<float>(direction.x);
        rays.dy[0] = static_cast<float>(direction.y);
        rays.dz[0] = static_cast<float>(direction.z);
        lens.system->traceFromFilmBatch(rays, &wavelengthNm, kernel);
        ASSERT_EQ(rays.alive[0], 1);
        EXPECT_NEAR(rays.dx[0], exact->direction.x, 1e-5) << wavelengthNm << " nm";
        EXPECT_NEAR(rays.dy[0], exact->direction.y, 1e-5) << wavelengthNm << " nm";
        EXPECT_NEAR(rays.ox[0], exact->origin.x, 1e-4) << wavelengthNm << " nm";
      }
    }
  }
}

TEST(CatalogGlassLens, AGlassTheSpectralTraceCannotFollowIsNamedAndRefused) {
  // CDGM's formulas stop at 706.5 nm, short of the spectral render's 780; LZOS's glasses are
  // measured tables that no series follows to 1e-6.
  for (const auto& [glass, fragment] :
       {std::pair<std::string, std::string>{"H-LAK67 maker CDGM",
                                            "H-LAK67 (CDGM): its formula covers 365-706.5 nm"},
        std::pair<std::string, std::string>{"K8 maker LZOS", "K8 (LZOS) is a measured table"}}) {
    const LensFileResult file =
        parseGlassLens("lenslab-lens 1\nsurface radius 50 thickness 5 glass " + glass +
                       " diameter 20\n"
                       "surface radius -50 thickness 1 diameter 20\n"
                       "stop thickness 45 diameter 10\n");
    ASSERT_TRUE(file.ok()) << firstMessage(file);
    const auto lens = LensSystem::build(file.lens->prescription);
    ASSERT_TRUE(lens.ok());
    const std::string problem = lens.system->spectralTraceProblem();
    EXPECT_NE(problem.find("surface 1's glass " + fragment), std::string::npos) << problem;
    LensRayBatch rays;
    rays.resize(1);
    rays.ox[0] = rays.oy[0] = rays.oz[0] = 0.0f;
    rays.dx[0] = rays.dy[0] = 0.0f;
    rays.dz[0] = 1.0f;
    const float wavelengthNm = 500.0f;
    EXPECT_THROW(lens.system->traceFromFilmBatch(rays, &wavelengthNm), std::logic_error);
  }
}

}  // namespace
}  // namespace lenslab::optics
