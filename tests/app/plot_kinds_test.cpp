// The plot component's kinds beyond a graph of y against x: a series broken by a non-finite
// point into several polylines (a grid's lines), series that are functions of y (field curves,
// field up the y axis), and equal scales on both axes (a picture of the film).

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "app/plot/plot_csv.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_scale.h"
#include "app/plot/plot_svg.h"

namespace lenslab::app {
namespace {

TEST(PlotKinds, ANonFinitePointBreaksTheLine) {
  PlotSeries grid{"lines", {0, 1, NAN, 0, 1, 2}, {0, 0, NAN, 1, 1, 1}};
  const auto runs = finiteRuns(grid);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0], (std::pair<std::size_t, std::size_t>{0, 2}));
  EXPECT_EQ(runs[1], (std::pair<std::size_t, std::size_t>{3, 6}));
  EXPECT_TRUE(finiteRuns(PlotSeries{"empty", {NAN}, {NAN}}).empty());
  PlotSpec spec;
  spec.series = {grid};
  const std::string svg = plotSvg(spec, 800, 600, 14.0f);
  // Two polylines for the one series, of 2 and 3 points.
  const std::regex polyline("<polyline[^>]*points=\"([^\"]*)\"");
  std::vector<int> sizes;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline);
       it != std::sregex_iterator(); ++it) {
    const std::string points = (*it)[1];
    sizes.push_back(static_cast<int>(std::count(points.begin(), points.end(), ',')));
  }
  EXPECT_EQ(sizes, (std::vector<int>{2, 3}));
}

TEST(PlotKinds, SeriesAlongYAreReadByY) {
  PlotSpec spec;
  spec.x.label = "focus shift (mm)";
  spec.y.label = "field angle (deg)";
  spec.seriesAlongY = true;
  spec.series = {{"T", {0.0, -0.1, -0.4}, {0, 10, 20}}, {"S", {0.0, -0.05}, {0, 10}}};
  EXPECT_EQ(plotCsv(spec), "field angle (deg),T,S\n0,0,0\n10,-0.1,-0.05\n20,-0.4,\n");
  const auto at15 = valuesAt(spec, 15.0);
  ASSERT_TRUE(at15[0]);
  EXPECT_NEAR(*at15[0], -0.25, 1e-12);
  EXPECT_FALSE(at15[1]);
}

// A 36 x 24 picture in a 1000 x 400 box: one millimetre is as many pixels across as up.
TEST(PlotKinds, EqualAspectGivesBothAxesOneScale) {
  PlotSpec spec;
  spec.equalAspect = true;
  spec.series = {{"film", {-18, 18, 18, -18, -18}, {-12, -12, 12, 12, -12}}};
  for (const auto& [width, height] : {std::pair{1000.0f, 400.0f}, std::pair{400.0f, 900.0f}}) {
    const PlotFrame frame = layoutPlot(spec, {0, 0, width, height}, 13.0f,
                                       [](const std::string& t) { return 7.0f * t.size(); });
    const double pxPerMmX = (frame.toScreenX(18) - frame.toScreenX(-18)) / 36.0;
    const double pxPerMmY = (frame.toScreenY(-12) - frame.toScreenY(12)) / 24.0;
    EXPECT_NEAR(pxPerMmX, pxPerMmY, 1e-3 * pxPerMmX) << width;
    // The film fits inside the box.
    EXPECT_GE(frame.toScreenX(-18), frame.area.x);
    EXPECT_LE(frame.toScreenX(18), frame.area.right());
    EXPECT_GE(frame.toScreenY(12), frame.area.y);
    EXPECT_LE(frame.toScreenY(-12), frame.area.bottom());
  }
}

}  // namespace
}  // namespace lenslab::app
