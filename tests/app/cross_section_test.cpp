#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "app/drawing/cross_section_drawing.h"
#include "app/drawing/cross_section_view.h"
#include "app/drawing/svg_export.h"
#include "optics/lens_system.h"
#include "optics/ray_fan.h"
#include "support/run_process.h"

namespace lenslab::app {
namespace {

optics::Prescription singletWithStop() {
  optics::Prescription lens;
  lens.surfaces = {{50.0, 5.0, 1.5, std::nullopt, 20.0},
                   {-50.0, 5.0, 1.0, std::nullopt, 20.0},
                   {0.0, 40.0, 1.0, std::nullopt, 8.0}};
  return lens;
}

TEST(CrossSectionView, MapsFrontToTheLeftAndUpToTheTop) {
  CrossSectionView view;
  view.centreZMm = 10;
  view.pixelsPerMm = 2;
  const PixelPoint centre{100, 100};
  const PixelPoint front = view.toPixels({20, 0}, centre);
  const PixelPoint up = view.toPixels({10, 5}, centre);
  EXPECT_FLOAT_EQ(front.x, 80);
  EXPECT_FLOAT_EQ(up.y, 90);
  const auto back = view.toLens(front, centre);
  EXPECT_NEAR(back.zMm, 20, 1e-9);
}

TEST(CrossSectionView, ZoomKeepsThePointUnderTheCursor) {
  CrossSectionView view;
  view.pixelsPerMm = 3;
  const PixelPoint centre{200, 150}, cursor{260, 90};
  const auto before = view.toLens(cursor, centre);
  view.zoomAbout(cursor, centre, 1.7);
  const auto after = view.toLens(cursor, centre);
  EXPECT_NEAR(before.zMm, after.zMm, 1e-9);
  EXPECT_NEAR(before.yMm, after.yMm, 1e-9);
  EXPECT_NEAR(view.pixelsPerMm, 5.1, 1e-9);
}

TEST(CrossSectionView, FitShowsTheWholeLensAndFilm) {
  const CrossSectionDrawing drawing = drawLens(optics::computeLensOutline(singletWithStop()), 21.6);
  CrossSectionView view;
  view.fit(drawing.bounds, 600, 400);
  const PixelPoint centre{300, 200};
  for (const auto& line : drawing.lines) {
    for (const auto& point : line.points) {
      if (point.yMm == 0) continue;  // the axis deliberately runs past the bounds
      const PixelPoint pixel = view.toPixels(point, centre);
      EXPECT_GE(pixel.x, 0);
      EXPECT_LE(pixel.x, 600);
      EXPECT_GE(pixel.y, 0);
      EXPECT_LE(pixel.y, 400);
    }
  }
}

TEST(CrossSectionDrawing, HasGlassStopAxisAndFilm) {
  const CrossSectionDrawing drawing = drawLens(optics::computeLensOutline(singletWithStop()), 21.6);
  EXPECT_EQ(drawing.fills.size(), 1u);
  int stopBars = 0, films = 0;
  for (const auto& line : drawing.lines) {
    if (line.colour.r == palette::kStop.r && line.colour.g == palette::kStop.g) ++stopBars;
    if (line.colour.r == palette::kFilm.r && line.points.size() == 2 && line.points[0].zMm == 0)
      ++films;
  }
  EXPECT_EQ(stopBars, 2);
  EXPECT_EQ(films, 1);
  EXPECT_DOUBLE_EQ(drawing.bounds.maxY, 21.6);
}

TEST(SvgExport, WritesAnSvgWithTheLensInMillimetres) {
  const CrossSectionDrawing drawing = drawLens(optics::computeLensOutline(singletWithStop()), 21.6);
  const auto path = testing::makeTestDirectory("svg") / "lens.svg";
  ASSERT_EQ(writeCrossSectionSvg(path, drawing, wholeDrawingFrame(drawing)), "");
  const std::string svg = testing::readWholeFile(path);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find("units: mm"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_NE(writeCrossSectionSvg("/nonexistent-dir/x.svg", drawing, wholeDrawingFrame(drawing)),
            "");
}

std::string rgbText(const Colour& colour) {
  return "rgb(" + std::to_string(colour.r) + "," + std::to_string(colour.g) + "," +
         std::to_string(colour.b) + ")";
}

TEST(SvgExport, HasTheRayFansInThePanelsColours) {
  const optics::Prescription lens = singletWithStop();
  const auto built = optics::LensSystem::build(lens);
  ASSERT_TRUE(built.ok());
  CrossSectionDrawing drawing = drawLens(optics::computeLensOutline(lens), 21.6);
  optics::FanSpec spec;
  spec.filmHalfDiagonalMm = 5.0;
  drawRayFans(drawing, optics::computeRayFans(*built.system, spec), true);
  const std::string svg = crossSectionSvg(drawing, wholeDrawingFrame(drawing));
  for (const Colour& colour : palette::kFieldColours) {
    if (&colour - palette::kFieldColours >= 3) break;  // three fans: 0, 0.7 and 1.0
    EXPECT_NE(svg.find("<polyline fill=\"none\" stroke=\"" + rgbText(colour)), std::string::npos)
        << rgbText(colour);
  }
  EXPECT_NE(svg.find("stroke=\"" + rgbText(palette::kMarginalRay)), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);  // chief rays and the axis
  EXPECT_NE(svg.find("stroke=\"" + rgbText(palette::kFilm)), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"" + rgbText(palette::kAxis)), std::string::npos);
}

TEST(SvgExport, ShowsOnlyTheFrameItIsGiven) {
  const CrossSectionDrawing drawing = drawLens(optics::computeLensOutline(singletWithStop()), 21.6);
  // Zoomed on the film's top end: the lens elements (z >= 40) are out of the frame.
  SvgFrame frame;
  frame.visibleMm.include({-2, 15});
  frame.visibleMm.include({2, 25});
  frame.mmPerPixel = 0.01;
  const std::string svg = crossSectionSvg(drawing, frame);
  EXPECT_NE(svg.find("viewBox=\"-2 -25 4 10\""), std::string::npos) << svg.substr(0, 400);
  EXPECT_EQ(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find("stroke=\"" + rgbText(palette::kFilm)), std::string::npos);
  // Every point lies within the frame (plus the small allowance for line caps).
  std::size_t at = 0;
  while ((at = svg.find("points=\"", at)) != std::string::npos) {
    at += 8;
    const std::string points = svg.substr(at, svg.find('"', at) - at);
    std::istringstream in(points);
    double x = 0, y = 0;
    char comma = 0;
    while (in >> x >> comma >> y) {
      EXPECT_GE(x, -2.1);
      EXPECT_LE(x, 2.1);
      EXPECT_GE(y, -25.1);
      EXPECT_LE(y, -14.9);
    }
  }
}

// A ray point that is not finite ends the drawn line there: the ray is drawn up to it and never
// joined across the canvas to the points after it.
TEST(CrossSectionDrawing, ARayEndsAtAPointThatIsNotFinite) {
  optics::RayFans fans;
  optics::FanRay ray;
  ray.path.points = {
      {0.0, 1.0, 30.0}, {0.0, 0.5, 20.0}, {0.0, std::nan(""), 10.0}, {0.0, 0.0, 5.0}};
  ray.filmPoint = glm::dvec3{0.0, -1.0, 0.0};
  fans.fans.push_back({});
  fans.fans.back().rays.push_back(ray);
  CrossSectionDrawing drawing;
  drawRayFans(drawing, fans, true);
  ASSERT_EQ(drawing.lines.size(), 1u);
  ASSERT_EQ(drawing.lines[0].points.size(), 2u);
  EXPECT_EQ(drawing.lines[0].points[1].yMm, 0.5);
}

}  // namespace
}  // namespace lenslab::app
