// Validation names the surface and the problem, and build() refuses invalid prescriptions.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_lenses.h"

namespace lenslab::optics {
namespace {

Prescription goodLens() { return testing::singlet(40.0, -60.0, 6.0, 1.5, 50.0); }

// The first error's surface and whether its message contains `fragment`.
void expectError(const Prescription& p, int surface, const std::string& fragment) {
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
  expectError(p, 1, "edge thickness");
}

TEST(Validation, SemiApertureLargerThanRadius) {
  Prescription p = goodLens();
  p.surfaces[0].radiusMm = 9.0;
  expectError(p, 0, "exceeds |radius|");
}

TEST(Validation, IndexBelowOne) {
  Prescription p = goodLens();
  p.surfaces[0].indexD = 0.8;
  expectError(p, 0, "below 1");
}

TEST(Validation, NonPositiveAperture) {
  Prescription p = goodLens();
  p.surfaces[1].apertureDiameterMm = 0.0;
  expectError(p, 1, "must be positive");
  p.surfaces[1].apertureDiameterMm = -2.0;
  expectError(p, 1, "must be positive");
}

TEST(Validation, MissingStopAndTwoStops) {
  Prescription p = goodLens();
  p.surfaces.pop_back();
  expectError(p, -1, "no aperture stop");
  p = goodLens();
  p.surfaces.push_back({0.0, 5.0, 1.0, std::nullopt, 10.0});
  expectError(p, 3, "second aperture stop");
}

TEST(Validation, NonFiniteNumbersAreRejectedNotTraced) {
  Prescription p = goodLens();
  p.surfaces[0].thicknessMm = std::nan("");
  expectError(p, 0, "thickness");
  p = goodLens();
  p.surfaces[2].apertureDiameterMm = std::numeric_limits<double>::infinity();
  expectError(p, 2, "aperture");
  p = goodLens();
  p.surfaces[0].radiusMm = std::nan("");
  expectError(p, 0, "radius");
}

TEST(Validation, NoSurfaces) { expectError(Prescription{}, -1, "no surfaces"); }

TEST(Validation, CheapVariantsRefuseNonsense) {
  const auto lens = LensSystem::build(goodLens()).system;
  EXPECT_FALSE(lens->withFilmDistance(-1.0));
  EXPECT_FALSE(lens->withStopDiameter(0.0));
  EXPECT_FALSE(lens->withWavelength(std::nan("")));
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

// DESIGN.md: src/optics builds and tests without a display; no GL, GLFW or ImGui header in it.
TEST(Layering, OpticsIncludesNoGuiHeaders) {
  const std::filesystem::path dir =
      std::filesystem::path(LENSLAB_BUNDLED_LENS_DIR) / ".." / "src" / "optics";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path());
    std::string line;
    ++files;
    while (std::getline(in, line)) {
      if (line.rfind("#include", 0) != 0) continue;
      for (const char* banned : {"GL/", "GLFW", "glad", "imgui", "app/", "render/"})
        EXPECT_EQ(line.find(banned), std::string::npos) << entry.path() << ": " << line;
    }
  }
  EXPECT_GT(files, 10);
}

}  // namespace
}  // namespace lenslab::optics
