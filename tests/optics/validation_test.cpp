// Validation names the surface and the problem, and build() refuses invalid prescriptions.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string>

#include "test_lenses.h"

namespace lenslab::optics {
namespace {

Prescription goodLens() { return testing::singlet(40.0, -60.0, 6.0, 1.5, 50.0); }

// The first error's surface and whether its message contains `fragment`.
void expectValidationError(const Prescription& p, int surface, const std::string& fragment) {
  const auto built = LensSystem::build(p);
  EXPECT_FALSE(built.ok());
  ASSERT_FALSE(built.errors.empty());
  bool found = false;
  for (const auto& e : built.errors)
    if (e.surface == surface && e.message.find(fragment) != std::string::npos) found = true;
  EXPECT_TRUE(found) << "expected surface " << surface << ": " << fragment << "; got surface "
                     << built.errors.front().surface << ": " << built.errors.front().message;
}

TEST(Validation, AGoodLensBuilds) {
  EXPECT_TRUE(validate(goodLens()).empty());
  EXPECT_TRUE(LensSystem::build(goodLens()).ok());
}

TEST(Validation, CrossingSurfacesHaveNegativeEdgeThickness) {
  Prescription p = goodLens();
  // A strongly biconvex lens 1 mm thick: the rims cross inside the 20 mm aperture.
  p.surfaces[0].radiusMm = 12.0;
  p.surfaces[1].radiusMm = -12.0;
  p.surfaces[0].thicknessMm = 1.0;
  expectValidationError(p, 1, "edge thickness");
}

TEST(Validation, SemiApertureLargerThanRadius) {
  Prescription p = goodLens();
  p.surfaces[0].radiusMm = 9.0;
  expectValidationError(p, 0, "exceeds |radius|");
}

// An aspheric bump that crosses its neighbour at mid-height while the rims stay apart: a flat
// front with S(h) = A4 h^4 + A6 h^6, A4 = -54 A6, peaks where S' = 0, h^2 = -2 A4 / (3 A6) = 36,
// at S(6) = -23328 A6 = 2 mm for A6 = -2 / 23328. Behind 1 mm of glass and a flat rear the gap is
// 1 - 2 = -1 mm at 6 mm, but 1 - S(10) = 1 + 39.4 mm at the 10 mm rim, where the old check looked.
TEST(Validation, AnAsphericBumpCrossingInsideTheApertureIsFound) {
  Prescription p = goodLens();
  const double a6 = -2.0 / 23328.0;
  p.surfaces[0].radiusMm = kFlatRadius;
  p.surfaces[0].thicknessMm = 1.0;
  p.surfaces[0].profile.setCoefficient(4, -54.0 * a6);
  p.surfaces[0].profile.setCoefficient(6, a6);
  p.surfaces[1].radiusMm = kFlatRadius;
  expectValidationError(p, 1, "crosses the previous surface");
  const auto errors = validate(p);
  ASSERT_EQ(errors.size(), 1u);
  // The samples are 10/128 mm apart: the deepest lies within one of 6 mm, at most 0.01 mm less
  // deep.
  double gap = 0.0, height = 0.0;
  const std::string& m = errors[0].message;
  ASSERT_EQ(std::sscanf(m.c_str() + m.find("gap "), "gap %lf mm at height %lf", &gap, &height), 2)
      << m;
  EXPECT_NEAR(height, 6.0, 10.0 / 128.0);
  EXPECT_NEAR(gap, -1.0, 0.01);
  // Half as high a bump (1 mm) only touches: no error.
  p.surfaces[0].profile.setCoefficient(4, -27.0 * a6);
  p.surfaces[0].profile.setCoefficient(6, 0.5 * a6);
  EXPECT_TRUE(validate(p).empty()) << validate(p).front().message;
}

TEST(Validation, AConicMustHaveARealSagAcrossTheAperture) {
  Prescription p = goodLens();  // semi-aperture 10 mm, front R = 40 mm: c^2 = 1/1600
  // k = 24: (1 + k) c^2 = 25/1600, so the sag is real only out to 1/sqrt(25/1600) = 8 mm.
  p.surfaces[0].profile.setConic(24.0);
  expectValidationError(p, 0, "no real sag beyond height 8 mm");
  // k = 15 reaches exactly 10 mm: the rim is still on the surface.
  p.surfaces[0].profile.setConic(15.0);
  EXPECT_TRUE(validate(p).empty());
  // A paraboloid has a real sag at every height, even beyond |R|, where a sphere has none: R = 9
  // mm against the 10 mm semi-aperture. Its sag there, h^2 / (2 R) = 5.56 mm, needs a thicker lens.
  p.surfaces[0].radiusMm = 9.0;
  p.surfaces[0].thicknessMm = 8.0;
  p.surfaces[0].profile.setConic(0.0);
  expectValidationError(p, 0, "exceeds |radius|");
  p.surfaces[0].profile.setConic(-1.0);
  EXPECT_TRUE(validate(p).empty()) << validate(p).front().message;
}

TEST(Validation, AsphericTermsMustBeNumbersAndNotOnTheStop) {
  Prescription p = goodLens();
  p.surfaces[0].profile.setCoefficient(4, std::nan(""));
  expectValidationError(p, 0, "A4");
  p = goodLens();
  p.surfaces[0].profile.setConic(std::numeric_limits<double>::infinity());
  expectValidationError(p, 0, "conic constant");
  p = goodLens();
  p.surfaces[2].profile.setCoefficient(4, 1e-6);  // row 3 is the stop
  expectValidationError(p, 2, "aperture stop is a plane");
}

TEST(Validation, IndexBelowOne) {
  Prescription p = goodLens();
  p.surfaces[0].indexD = 0.8;
  expectValidationError(p, 0, "below 1");
}

TEST(Validation, NonPositiveAperture) {
  Prescription p = goodLens();
  p.surfaces[1].apertureDiameterMm = 0.0;
  expectValidationError(p, 1, "must be positive");
  p.surfaces[1].apertureDiameterMm = -2.0;
  expectValidationError(p, 1, "must be positive");
}

TEST(Validation, MissingStopAndTwoStops) {
  Prescription p = goodLens();
  p.surfaces.pop_back();
  expectValidationError(p, -1, "no aperture stop");
  p = goodLens();
  p.surfaces.push_back({0.0, 5.0, 1.0, std::nullopt, 10.0});
  expectValidationError(p, 3, "second aperture stop");
}

TEST(Validation, NonFiniteNumbersAreRejectedNotTraced) {
  Prescription p = goodLens();
  p.surfaces[0].thicknessMm = std::nan("");
  expectValidationError(p, 0, "thickness");
  p = goodLens();
  p.surfaces[2].apertureDiameterMm = std::numeric_limits<double>::infinity();
  expectValidationError(p, 2, "aperture");
  p = goodLens();
  p.surfaces[0].radiusMm = std::nan("");
  expectValidationError(p, 0, "radius");
}

// A table edit of V_d goes through validate() too: zero, negative, NaN and absurd values name the
// row; 150 itself is allowed.
TEST(Validation, AbbeNumbersMustBeAGlass) {
  for (const double bad : {0.0, -20.0, std::nan(""), 151.0, 1e300}) {
    Prescription p = goodLens();
    p.surfaces[0].abbeD = bad;
    expectValidationError(p, 0, "Abbe number");
  }
  Prescription p = goodLens();
  p.surfaces[0].abbeD = 151.0;
  expectValidationError(p, 0, "beyond any glass");
  p.surfaces[0].abbeD = kMaxAbbeNumber;
  EXPECT_TRUE(LensSystem::build(p).ok());
}

TEST(Validation, NoSurfaces) { expectValidationError(Prescription{}, -1, "no surfaces"); }

TEST(Validation, AbsurdMagnitudesAreFlagged) {
  // Table edits in the viewer go through validate(): a slip such as 1e300 must not build.
  Prescription p = goodLens();
  p.surfaces[0].radiusMm = 2e6;
  expectValidationError(p, 0, "radius 2e+06 mm is beyond");
  p = goodLens();
  p.surfaces[1].radiusMm = -1e300;
  expectValidationError(p, 1, "radius");
  p = goodLens();
  p.surfaces[2].thicknessMm = 1e300;
  expectValidationError(p, 2, "thickness 1e+300 mm is beyond");
  p = goodLens();
  p.surfaces[0].apertureDiameterMm = 2e5;
  p.surfaces[0].radiusMm = kFlatRadius;  // so that only the magnitude is wrong
  expectValidationError(p, 0, "aperture diameter 200000 mm is beyond");
  p = goodLens();
  p.surfaces[0].indexD = 1e300;
  expectValidationError(p, 0, "refractive index 1e+300 is beyond");
  // The largest allowed values still build (a flat surface stays inf).
  p = goodLens();
  p.surfaces[2].thicknessMm = kMaxLengthMm;
  EXPECT_TRUE(LensSystem::build(p).ok());
}

TEST(Validation, MessagesCountSurfacesFromOne) {
  // ValidationError::surface is an index; what users read counts from 1, as the viewer's table
  // and the script commands ("set surface 3 radius 40") do.
  Prescription p = goodLens();
  p.surfaces[0].radiusMm = 12.0;
  p.surfaces[1].radiusMm = -12.0;
  p.surfaces[0].thicknessMm = 1.0;
  const auto errors = validate(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].surface, 1);
  EXPECT_EQ(errors[0].toString().rfind("surface 2: crosses the previous surface (surface 1)", 0),
            0u)
      << errors[0].toString();
  Prescription noStop = goodLens();
  noStop.surfaces.pop_back();
  const auto lensWide = validate(noStop);
  ASSERT_FALSE(lensWide.empty());
  EXPECT_EQ(lensWide.back().toString(), lensWide.back().message);  // no surface to name
}

TEST(Validation, CheapVariantsRefuseNonsense) {
  const auto lens = LensSystem::build(goodLens()).system;
  EXPECT_FALSE(lens->withFilmDistance(-1.0));
  EXPECT_FALSE(lens->withStopDiameter(0.0));
  EXPECT_FALSE(lens->withWavelength(std::nan("")));
  EXPECT_FALSE(lens->withFilmDistance(1e300));
  EXPECT_FALSE(lens->withStopDiameter(1e300));
  const auto moved = lens->withFilmDistance(42.0);
  ASSERT_TRUE(moved);
  EXPECT_EQ(moved->filmDistanceMm(), 42.0);
  EXPECT_EQ(moved->rearVertexZ(), 42.0);
  EXPECT_EQ(lens->filmDistanceMm(), 50.0);  // the original is untouched
}

}  // namespace
}  // namespace lenslab::optics

namespace lenslab::optics {
namespace {

// DESIGN.md: src/optics and src/render build and test without a display: no GL, GLFW or ImGui
// header in them, nor in src/common, which both use. Each library also stays below the ones
// that use it (optics knows no renderer, common knows neither).
// Fails on every #include in src/DIRECTORY that names a banned word; returns the files scanned.
int scanIncludesFor(const std::string& directory, std::initializer_list<const char*> banned) {
  const std::filesystem::path dir =
      std::filesystem::path(LENSLAB_BUNDLED_LENS_DIR) / ".." / "src" / directory;
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path());
    std::string line;
    ++files;
    while (std::getline(in, line)) {
      const auto first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line.compare(first, 1, "#") != 0) continue;
      if (line.find("include", first) == std::string::npos) continue;
      for (const char* word : banned)
        EXPECT_EQ(line.find(word), std::string::npos) << entry.path() << ": " << line;
    }
  }
  return files;
}

TEST(Layering, OpticsIncludesNoGuiHeaders) {
  EXPECT_GT(scanIncludesFor(
                "optics", {"GL/", "GLFW", "glad", "imgui", "backends/", "app/", "render/", "cli/"}),
            10);
}

TEST(Layering, RenderIncludesNoGuiHeaders) {
  EXPECT_GT(
      scanIncludesFor("render", {"GL/", "GLFW", "glad", "imgui", "backends/", "app/", "cli/"}), 10);
}

TEST(Layering, CommonIncludesNoGuiOrHigherLevelHeaders) {
  EXPECT_GE(scanIncludesFor("common", {"GL/", "GLFW", "glad", "imgui", "backends/", "app/", "cli/",
                                       "render/", "optics/"}),
            2);
}

}  // namespace
}  // namespace lenslab::optics
