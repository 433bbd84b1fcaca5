#include <gtest/gtest.h>

#include "app/cross_section_drawing.h"
#include "app/cross_section_view.h"
#include "app/svg_export.h"
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
    if (line.colour.r == palette::kFilm.r && line.points.size() == 2 && line.points[0].zMm == 0) ++films;
  }
  EXPECT_EQ(stopBars, 2);
  EXPECT_EQ(films, 1);
  EXPECT_DOUBLE_EQ(drawing.bounds.maxY, 21.6);
}

TEST(SvgExport, WritesAnSvgWithTheLensInMillimetres) {
  const CrossSectionDrawing drawing = drawLens(optics::computeLensOutline(singletWithStop()), 21.6);
  const auto path = testing::makeTestDirectory("svg") / "lens.svg";
  ASSERT_EQ(writeCrossSectionSvg(path, drawing), "");
  const std::string svg = testing::readWholeFile(path);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find("mm\""), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_NE(writeCrossSectionSvg("/nonexistent-dir/x.svg", drawing), "");
}

}  // namespace
}  // namespace lenslab::app
