// The first-order section's figures (app/analysis/lens_figures.h): the f-number by area that a
// shaped stop adds.

#include <gtest/gtest.h>

#include "app/analysis/lens_figures.h"
#include "app/lens_caption.h"

namespace lenslab::app {
namespace {

// A 10 mm stop 2 mm ahead of a biconvex singlet (R 50, -50, 4 mm of n 1.5), EFL 50.6757 mm by
// the thick-lens formula; the beam from infinity has the stop's shape.
std::shared_ptr<const optics::LensSystem> stopThenSinglet(const optics::ApertureShape& shape) {
  optics::Prescription p;
  p.surfaces = {{0.0, 2.0, 1.0, std::nullopt, 10.0},
                {50.0, 4.0, 1.5, std::nullopt, 20.0},
                {-50.0, 48.0, 1.0, std::nullopt, 20.0}};
  p.stopShape = shape;
  return optics::LensSystem::build(p).system;
}

TEST(LensFigures, AShapedStopGetsItsFNumberByAreaAndTheCircleNone) {
  optics::ApertureShape square;
  square.kind = optics::ApertureShape::Kind::Blades;
  square.bladeCount = 4;
  // 2 R^2 = 50 mm^2 passes: the circle of that area is 7.9788 mm across, 50.6757 / 7.9788 = 6.35.
  const LensFigures shaped = computeLensFigures(stopThenSinglet(square), true);
  EXPECT_EQ(shaped.areaFNumberText.rfind("f/6.35 (a 50.", 0), 0u) << shaped.areaFNumberText;
  EXPECT_EQ(shaped.fNumberText, "f/5.07");

  const LensFigures round = computeLensFigures(stopThenSinglet({}), true);
  EXPECT_TRUE(round.areaFNumberText.empty()) << round.areaFNumberText;
  // Beam figures not asked for (a drag): none.
  EXPECT_TRUE(computeLensFigures(stopThenSinglet(square), false).areaFNumberText.empty());
}

TEST(LensCaption, TheNameLosesItsNominalFNumberSoTheTitleCarriesOne) {
  // Issue 38: a slide said "f/2" in its title (the designer's name) and "f/2.4797" beside it.
  EXPECT_EQ(withoutNominalFNumber("Double-Gauss 50 mm f/2, 22 degree half field."),
            "Double-Gauss 50 mm, 22 degree half field");
  EXPECT_EQ(withoutNominalFNumber("Double-Gauss 100 mm f/1.35, 13 degree half field (Lowenthal)"),
            "Double-Gauss 100 mm, 13 degree half field (Lowenthal)");
  EXPECT_EQ(withoutNominalFNumber("a landscape lens of 50 mm, f/4, in one dense flint"),
            "a landscape lens of 50 mm, in one dense flint");
  EXPECT_EQ(withoutNominalFNumber("Telephoto 250 mm F/5.6"), "Telephoto 250 mm");
  EXPECT_EQ(withoutNominalFNumber("Wide-angle 22 mm"), "Wide-angle 22 mm");
  // The f-number as the first-order section writes it: EFL 50.6757 mm over the 10 mm stop.
  EXPECT_EQ(fNumberText(*stopThenSinglet(optics::ApertureShape{})), "f/5.07");
}

}  // namespace
}  // namespace lenslab::app
