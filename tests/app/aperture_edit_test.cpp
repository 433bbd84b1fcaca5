// The stop's shape as a document edit and a script command (the GUI test runs them for real).

#include <gtest/gtest.h>

#include "app/automation/script.h"
#include "app/document/lens_document.h"

namespace lenslab::app {
namespace {

optics::Prescription apertureEditTriplet() {
  optics::Prescription lens;
  lens.surfaces = {{40.0, 5.0, 1.6, 58.0, 30.0},
                   {-200.0, 6.0, 1.0, std::nullopt, 30.0},
                   {0.0, 4.0, 1.0, std::nullopt, 20.0},
                   {-35.0, 2.0, 1.62, 36.0, 24.0},
                   {35.0, 45.0, 1.0, std::nullopt, 24.0}};
  return lens;
}

optics::ApertureShape sixBlades(double rotationDeg) {
  optics::ApertureShape shape;
  shape.kind = optics::ApertureShape::Kind::Blades;
  shape.bladeCount = 6;
  shape.rotationDeg = rotationDeg;
  return shape;
}

TEST(ApertureEdit, SetStopShapeIsOneUndoableStepThatMarksTheLensModified) {
  LensDocument document(apertureEditTriplet());
  EXPECT_FALSE(document.modified());
  ASSERT_FALSE(document.apply(SetStopShape{sixBlades(15.0)}));
  EXPECT_EQ(document.prescription().stopShape, sixBlades(15.0));
  EXPECT_TRUE(document.modified());
  EXPECT_EQ(describe(SetStopShape{sixBlades(15.0)}),
            "set aperture to blades 6 curvature 0 rotation 15");
  ASSERT_TRUE(document.undo());
  EXPECT_TRUE(document.prescription().stopShape.isCircle());
  EXPECT_FALSE(document.modified());
}

TEST(ApertureEdit, FlippingTheLensMirrorsTheIris) {
  optics::Prescription lens = apertureEditTriplet();
  lens.stopShape = sixBlades(15.0);
  const optics::Prescription turned = flipped(lens);
  // A corner at 15 degrees seen from the other side is at 180 - 15.
  EXPECT_EQ(turned.stopShape, sixBlades(165.0));
  const optics::ApertureShape& a = lens.stopShape;
  const optics::ApertureShape& b = turned.stopShape;
  for (double x = -0.9; x <= 0.9; x += 0.1)
    for (double y = -0.9; y <= 0.9; y += 0.1)
      EXPECT_EQ(a.containsUnit({x, y}), b.containsUnit({-x, y})) << x << ", " << y;
}

TEST(ApertureEdit, FlippingTheLensMirrorsAnImageIrisAndFlippingBackRestoresIt) {
  // A right triangle in the upper left: mirrored, it opens in the upper right.
  optics::Prescription lens = apertureEditTriplet();
  lens.stopShape.kind = optics::ApertureShape::Kind::Image;
  lens.stopShape.imageName = "corner.png";
  lens.stopShape.mask =
      optics::rasterizeApertureMask({{-1, 1}, {-1, -0.2}, {0.3, 1}}, 64, "corner.png");
  const optics::Prescription turned = flipped(lens);
  const optics::ApertureShape& a = lens.stopShape;
  const optics::ApertureShape& b = turned.stopShape;
  EXPECT_TRUE(b.mirrored);
  EXPECT_EQ(b.spec(), "image-mirrored corner.png");
  EXPECT_TRUE(a.containsUnit({-0.8, 0.8}));
  EXPECT_FALSE(b.containsUnit({-0.8, 0.8}));
  EXPECT_TRUE(b.containsUnit({0.8, 0.8}));
  // Points off the pixels' edges (multiples of 1/32), where which side a point falls on is
  // decided by rounding.
  for (double x = -0.937; x <= 0.95; x += 0.1)
    for (double y = -0.937; y <= 0.95; y += 0.1)
      EXPECT_EQ(a.containsUnit({x, y}), b.containsUnit({-x, y})) << x << ", " << y;
  // The traces' test sees the same mirror image.
  const optics::StopShapeTest before(a, 10.0), after(b, 10.0);
  for (double x = -9.37; x <= 9.5; x += 1.0)
    for (double y = -9.37; y <= 9.5; y += 1.0)
      EXPECT_EQ(before.contains(x, y), after.contains(-x, y)) << x << ", " << y;

  const optics::Prescription back = flipped(turned);
  EXPECT_EQ(back.stopShape, lens.stopShape);
  EXPECT_FALSE(back.stopShape.mirrored);
  EXPECT_EQ(back.stopShape.mask->open, lens.stopShape.mask->open);
}

TEST(ApertureEdit, ScriptChecksTheShapeAtItsArgument) {
  const ParsedScript good = parseScript(
      "set aperture blades 6 curvature 0.5 rotation 15\nset aperture circle\n"
      "set aperture image some file.png\nset aperture image-mirrored some file.png\n",
      "t");
  EXPECT_TRUE(good.diagnostics.empty()) << good.diagnostics.formatAll();
  const ParsedScript bad = parseScript(
      "set aperture blades 2\nset aperture blades 33\nset aperture blades 6 curvature 3\n"
      "set aperture disk\n",
      "t");
  ASSERT_EQ(bad.diagnostics.all().size(), 4u) << bad.diagnostics.formatAll();
  EXPECT_NE(bad.diagnostics.all()[0].format().find("t:1:21: error: blade count 2 is out of range"),
            std::string::npos)
      << bad.diagnostics.all()[0].format();
  EXPECT_NE(bad.diagnostics.all()[1].format().find("t:2:21: error: blade count 33"),
            std::string::npos)
      << bad.diagnostics.all()[1].format();
  EXPECT_NE(bad.diagnostics.all()[2].format().find("t:3:33: error: curvature 3 is out of range"),
            std::string::npos)
      << bad.diagnostics.all()[2].format();
  EXPECT_NE(bad.diagnostics.all()[3].format().find("t:4:14: error: unknown aperture 'disk'"),
            std::string::npos)
      << bad.diagnostics.all()[3].format();
}

}  // namespace
}  // namespace lenslab::app
