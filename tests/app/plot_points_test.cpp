// The plot component's scatter series (PlotSeries::points, for spot diagrams) and the gaps a
// non-finite y leaves in a line (rays the lens blocks), in the SVG, the PNG's picture and the
// CSV.

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "app/plot/plot_csv.h"
#include "app/plot/plot_picture.h"
#include "app/plot/plot_svg.h"

namespace lenslab::app {
namespace {

std::size_t count(const std::string& text, const std::regex& pattern) {
  return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), pattern), {}));
}

PlotSpec scatterSpec() {
  PlotSpec spec;
  spec.x.label = "x (um)";
  spec.y.label = "y (um)";
  spec.x.min = spec.y.min = -10.0;
  spec.x.max = spec.y.max = 10.0;
  // Two rays at the same x (a spot is symmetric): a scatter must keep both.
  PlotSeries rays{"0.7 field", {1.0, 1.0, -2.0, 50.0}, {2.0, -2.0, 3.0, 0.0}, 0x50dc78ffu};
  rays.points = true;
  PlotSeries airy{"Airy disk", {-1.0, 0.0, 1.0, 0.0, -1.0}, {0.0, 1.0, 0.0, -1.0, 0.0}};
  spec.series = {rays, airy};
  return spec;
}

TEST(PlotPoints, SvgDrawsADotPerPointInsideTheBox) {
  const std::string svg = plotSvg(scatterSpec(), 800, 800, 16.0f);
  // Four dots and the legend's sample; the one at x = 50 lies outside the axes but inside the
  // clip path, so it is written and clipped by the viewer.
  EXPECT_EQ(count(svg, std::regex("<circle cx=")), 5u);
  EXPECT_NE(svg.find("<g class=\"points\" data-name=\"0.7 field\""), std::string::npos);
  EXPECT_EQ(count(svg, std::regex("<polyline class=\"series\" data-name=\"Airy disk\"")), 1u);
}

TEST(PlotPoints, CsvListsEveryPointOnItsOwnRow) {
  EXPECT_EQ(plotCsv(scatterSpec()),
            "series,x (um),y (um)\n"
            "0.7 field,1,2\n0.7 field,1,-2\n0.7 field,-2,3\n0.7 field,50,0\n"
            "Airy disk,-1,0\nAiry disk,0,1\nAiry disk,1,0\nAiry disk,0,-1\nAiry disk,-1,0\n");
}

TEST(PlotPoints, PictureFillsADotPerPointWithinTheAxes) {
  SlideTextMetrics metrics;
  metrics.widthPx = [](const std::string& text, double sizePx) {
    return 0.6 * sizePx * text.size();
  };
  const SlidePicture picture = plotPicture(scatterSpec(), 800, 800, 16.0, metrics);
  std::size_t dots = 0;
  for (const SlideFill& fill : picture.fills) dots += fill.group == "series";
  EXPECT_EQ(dots, 3u);  // the ray at x = 50 is outside the axes
}

// A line with a non-finite y is two polylines, not one joined across the gap.
TEST(PlotPoints, ANonFiniteYBreaksALine) {
  PlotSpec spec;
  spec.x.label = "pupil";
  spec.y.label = "error (um)";
  spec.series = {{"fan", {-1.0, -0.5, 0.0, 0.5, 1.0}, {NAN, 1.0, 0.0, NAN, 2.0}, 0xffffffffu}};
  const std::string svg = plotSvg(spec, 800, 500, 16.0f);
  EXPECT_EQ(count(svg, std::regex("<polyline class=\"series\"")), 2u);
  // The CSV keeps the gap as an empty cell.
  EXPECT_EQ(plotCsv(spec), "pupil,fan\n-1,\n-0.5,1\n0,0\n0.5,\n1,2\n");
}

}  // namespace
}  // namespace lenslab::app
