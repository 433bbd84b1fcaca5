// Flipping and scaling a lens with aspheric surfaces (issue 40), against hand-derived terms and
// against the sag itself (optics::sagMm), which the transformations must mirror and magnify.

#include <gtest/gtest.h>

#include <cmath>

#include "app/analysis/asphere_departure.h"
#include "app/document/lens_document.h"
#include "optics/aspheric_profile.h"
#include "optics/lens_system.h"

namespace lenslab::app {
namespace {

// A singlet whose front surface carries a conic, an A2 (which changes the vertex power), an odd
// A3 (as some patents write) and even A4, A6.
optics::Prescription asphericSinglet() {
  optics::Prescription lens;
  lens.surfaces = {{40.0, 5.0, 1.6, 58.0, 20.0}, {-120.0, 45.0, 1.0, std::nullopt, 20.0}};
  optics::AsphericProfile& front = lens.surfaces[0].profile;
  front.setConic(-0.5);
  front.setCoefficient(2, 1e-3);
  front.setCoefficient(3, 1e-5);
  front.setCoefficient(4, -2e-6);
  front.setCoefficient(6, 3e-9);
  return lens;
}

double sagAt(const optics::Surface& surface, double heightMm) {
  return *optics::sagMm(1.0 / surface.radiusMm, surface.profile, heightMm);
}

TEST(AsphericFlip, NegatesEveryTermAndKeepsTheConic) {
  const optics::Prescription flippedLens = flipped(asphericSinglet());
  // Old surface 1 is new surface 2, seen from behind.
  const optics::Surface& back = flippedLens.surfaces[1];
  EXPECT_DOUBLE_EQ(back.radiusMm, -40.0);
  EXPECT_DOUBLE_EQ(back.profile.conic(), -0.5);
  EXPECT_DOUBLE_EQ(back.profile.coefficient(2), -1e-3);
  EXPECT_DOUBLE_EQ(back.profile.coefficient(3), -1e-5);
  EXPECT_DOUBLE_EQ(back.profile.coefficient(4), 2e-6);
  EXPECT_DOUBLE_EQ(back.profile.coefficient(6), -3e-9);
  EXPECT_EQ(back.profile.highestPower(), 6);
  EXPECT_TRUE(flippedLens.surfaces[0].profile.isSphere());
}

TEST(AsphericFlip, MirrorsTheSag) {
  // z -> -z: the flipped surface's sag is the original's negated, at every height.
  const optics::Prescription lens = asphericSinglet();
  const optics::Prescription flippedLens = flipped(lens);
  for (double h = 0.0; h <= 10.0; h += 0.5) {
    EXPECT_NEAR(sagAt(flippedLens.surfaces[1], h), -sagAt(lens.surfaces[0], h), 1e-12) << h;
  }
}

TEST(AsphericFlip, TwiceGivesTheLensBack) {
  const optics::Prescription lens = asphericSinglet();
  const optics::Prescription twice = flipped(flipped(lens));
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    EXPECT_TRUE(twice.surfaces[i].profile == lens.surfaces[i].profile) << i;
  }
}

// The paraxial power follows the vertex curvature c + 2 A2 (the lead's paraxial data): a flip
// that left A2's sign alone would change the EFL; one that turns the surface keeps it, and a
// scale by s scales it by s.
TEST(AsphericFlip, KeepsTheFocalLengthOfALensWhoseA2AddsPower) {
  // A stop 2 mm before the singlet.
  optics::Prescription lens = asphericSinglet();
  lens.surfaces.insert(lens.surfaces.begin(), optics::Surface{0.0, 2.0, 1.0, std::nullopt, 10.0});
  optics::Prescription sphere = lens;
  sphere.surfaces[1].profile = {};
  const auto efl = [](const optics::Prescription& prescription) {
    const auto built = optics::LensSystem::build(prescription);
    EXPECT_TRUE(built.ok());
    return built.ok() ? built.system->firstOrder().eflMm : std::nan("");
  };
  const double original = efl(lens);
  // A2 = 1e-3 adds 2e-3 / mm of curvature to 1/40: the EFL must show it, or the test shows
  // nothing.
  ASSERT_GT(std::abs(original - efl(sphere)), 1.0);
  EXPECT_NEAR(efl(flipped(lens)), original, 1e-9 * original);
  EXPECT_NEAR(efl(scaled(lens, 2.0)), 2.0 * original, 1e-9 * original);
}

TEST(AsphericScale, ScalesEachTermByItsPowerOfTheFactor) {
  // A_i -> A_i s^(1 - i) for s = 2, by hand: A2 1e-3 / 2, A3 1e-5 / 4, A4 -2e-6 / 8,
  // A6 3e-9 / 32; k unchanged.
  const optics::Prescription doubled = scaled(asphericSinglet(), 2.0);
  const optics::Surface& front = doubled.surfaces[0];
  EXPECT_DOUBLE_EQ(front.radiusMm, 80.0);
  EXPECT_DOUBLE_EQ(front.profile.conic(), -0.5);
  EXPECT_DOUBLE_EQ(front.profile.coefficient(2), 5e-4);
  EXPECT_DOUBLE_EQ(front.profile.coefficient(3), 2.5e-6);
  EXPECT_DOUBLE_EQ(front.profile.coefficient(4), -2.5e-7);
  EXPECT_DOUBLE_EQ(front.profile.coefficient(6), 9.375e-11);
}

TEST(AsphericScale, MagnifiesTheSag) {
  // The scaled surface is the original magnified: its sag at s h is s times the original's at h.
  const optics::Prescription lens = asphericSinglet();
  for (const double s : {0.5, 2.0, 3.7}) {
    const optics::Prescription bigger = scaled(lens, s);
    for (double h = 0.0; h <= 10.0; h += 0.5) {
      EXPECT_NEAR(sagAt(bigger.surfaces[0], s * h), s * sagAt(lens.surfaces[0], h), 1e-12 * s)
          << "s " << s << " h " << h;
    }
  }
}

TEST(AsphericScale, ByTheFactorThenItsInverseGivesTheLensBack) {
  const optics::Prescription lens = asphericSinglet();
  const optics::Prescription back = scaled(scaled(lens, 3.7), 1.0 / 3.7);
  for (int power = 2; power <= 20; ++power) {
    const double original = lens.surfaces[0].profile.coefficient(power);
    EXPECT_NEAR(back.surfaces[0].profile.coefficient(power), original, 1e-14 * std::abs(original))
        << power;
  }
}

TEST(AsphericDocument, EachTermIsAnUndoStepAndMarksTheLensModified) {
  LensDocument document(asphericSinglet(), "singlet.dat");
  ASSERT_FALSE(document.apply(SetSurfaceField{1, SurfaceField::Conic, -1.0}));
  ASSERT_FALSE(document.apply(SetAsphericTerm{1, 8, 1e-12}));
  EXPECT_TRUE(document.modified());
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[1].profile.coefficient(8), 1e-12);
  ASSERT_TRUE(document.undo());
  EXPECT_EQ(document.prescription().surfaces[1].profile.coefficient(8), 0.0);
  EXPECT_DOUBLE_EQ(document.prescription().surfaces[1].profile.conic(), -1.0);
  ASSERT_TRUE(document.undo());
  EXPECT_TRUE(document.prescription().surfaces[1].profile.isSphere());
  EXPECT_FALSE(document.modified());
}

TEST(AsphericDocument, RefusesTermsThatAreNoShape) {
  LensDocument document(asphericSinglet(), "singlet.dat");
  const auto refused = [&](const EditCommand& command) {
    const auto why = document.apply(command);
    return why ? *why : std::string("accepted");
  };
  EXPECT_EQ(refused(SetAsphericTerm{0, 1, 1e-3}), "there is no term A1 (the powers are 2 to 20)");
  EXPECT_EQ(refused(SetAsphericTerm{0, 21, 1e-3}), "there is no term A21 (the powers are 2 to 20)");
  EXPECT_EQ(refused(SetAsphericTerm{0, 4, std::nan("")}),
            "surface 1: an aspheric term must be a finite number");
  EXPECT_EQ(refused(SetSurfaceField{0, SurfaceField::Conic, INFINITY}),
            "surface 1: an aspheric term must be a finite number");
  EXPECT_EQ(refused(SetAsphericTerm{5, 4, 1e-6}),
            "surface 6 does not exist (the lens has 2 surfaces)");
  EXPECT_FALSE(document.canUndo());
  // The stop has no shape; making a surface the stop takes its shape away.
  ASSERT_FALSE(document.apply(MakeStop{0}));
  EXPECT_TRUE(document.prescription().surfaces[0].profile.isSphere());
  EXPECT_NE(refused(SetAsphericTerm{0, 4, 1e-6}).find("surface 1 is the aperture stop"),
            std::string::npos);
  EXPECT_NE(refused(SetSurfaceField{0, SurfaceField::Conic, -1.0}).find("aperture stop"),
            std::string::npos);
}

// The departure plot's numbers, by hand: a paraboloid (k = -1) of R 50 mm departs from its sphere
// by r^2 / 2R - (R - sqrt(R^2 - r^2)): at r = 10 mm, 1 - (50 - sqrt(2400)) = -0.0102051443 mm.
TEST(AsphereDeparture, OfAParaboloidFromItsSphere) {
  optics::Surface surface{50.0, 5.0, 1.5, std::nullopt, 20.0};
  surface.profile.setConic(-1.0);
  EXPECT_NEAR(asphereDepartureMm(surface, 10.0), 1.0 - (50.0 - std::sqrt(2400.0)), 1e-13);
  EXPECT_EQ(asphereDepartureMm(surface, 0.0), 0.0);
  // Past its radius the sphere has no sag: no departure either (a gap, never a number).
  EXPECT_TRUE(std::isnan(asphereDepartureMm(surface, 60.0)));
}

TEST(AsphereDeparture, PlotIsInMicronsUnderATenthOfAMillimetre) {
  // A flat plate with A4 = -2e-6 mm^-3 (a Schmidt plate's kind): -2e-6 r^4, -20 um at r = 10 mm.
  optics::Surface plate{optics::kFlatRadius, 5.0, 1.5, std::nullopt, 20.0};
  plate.profile.setCoefficient(4, -2e-6);
  const PlotSpec spec = asphereDeparturePlot(plate, 3, 11);
  EXPECT_EQ(spec.y.label, "departure (um)");
  EXPECT_EQ(spec.x.label, "height from the axis (mm)");
  ASSERT_EQ(spec.series.size(), 1u);
  ASSERT_EQ(spec.series[0].x.size(), 11u);
  EXPECT_DOUBLE_EQ(spec.series[0].x.back(), 10.0);
  EXPECT_NEAR(spec.series[0].y.back(), -20.0, 1e-12);
  EXPECT_NEAR(spec.series[0].y[5], -2e-6 * 625.0 * 1000.0, 1e-12);  // r = 5 mm: -1.25 um
  // Ten times the term: -0.2 mm at the rim, in mm.
  plate.profile.setCoefficient(4, -2e-5);
  const PlotSpec deeper = asphereDeparturePlot(plate, 3, 11);
  EXPECT_EQ(deeper.y.label, "departure (mm)");
  EXPECT_NEAR(deeper.series[0].y.back(), -0.2, 1e-15);
}

}  // namespace
}  // namespace lenslab::app
