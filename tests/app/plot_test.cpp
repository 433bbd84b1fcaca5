// The plot component's arithmetic and its exports: tick choice by hand cases, interpolation,
// the CSV read back, and the SVG's text and coordinates read back with a small parser written
// here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

#include "app/plot/plot_csv.h"
#include "app/plot/plot_layout.h"
#include "app/plot/plot_scale.h"
#include "app/plot/plot_svg.h"

namespace lenslab::app {
namespace {

TEST(PlotScale, TicksAreRoundAndCoverTheData) {
  // 0..21.6 in at most 6 intervals: a step of 5 (2 would give 11), ends widened to 0 and 25.
  const AxisTicks a = niceTicks(0.0, 21.6, 6);
  EXPECT_DOUBLE_EQ(a.min, 0.0);
  EXPECT_DOUBLE_EQ(a.max, 25.0);
  EXPECT_EQ(a.values, (std::vector<double>{0, 5, 10, 15, 20, 25}));
  EXPECT_EQ(a.decimals, 0);
  // Fixed ends stay; ticks are the round values within them.
  const AxisTicks b = niceTicks(0.1, 0.9, 5, 0.0, 1.05);
  EXPECT_DOUBLE_EQ(b.min, 0.0);
  EXPECT_DOUBLE_EQ(b.max, 1.05);
  // Step 0.5: 0.2 would give 5.25 intervals, more than 5.
  EXPECT_EQ(b.values, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(b.decimals, 1);
  // Negative and small ranges.
  const AxisTicks c = niceTicks(-0.0032, 0.0041, 4);
  EXPECT_NEAR(c.values.front(), -0.004, 1e-12);
  EXPECT_NEAR(c.values.back(), 0.006, 1e-12);  // step 0.002; 0.0041 rounds up to 0.006
  EXPECT_EQ(c.decimals, 3);
  // One value gets a unit range; no ticks from NaN.
  EXPECT_EQ(niceTicks(3.0, 3.0, 4).values.front(), 2.5);
  EXPECT_FALSE(niceTicks(NAN, 1.0, 4).values.empty());
}

// A spot diagram's axis is fixed at +-1.05 x its largest ray's reach. Tiny spots on a small plot
// ask for two intervals, whose step (0.5 for +-0.42 um) is wider than either end: the axis showed
// "0" alone, with no scale. Smaller round steps until two ticks fit, labelled apart.
TEST(PlotScale, FixedEndsNarrowerThanAStepStillGetTwoTicks) {
  const AxisTicks tiny = niceTicks(-0.4, 0.4, 2, -0.42, 0.42);  // step 0.5, then 0.2
  ASSERT_EQ(tiny.values.size(), 5u);
  EXPECT_NEAR(tiny.values.front(), -0.4, 1e-12);
  EXPECT_EQ(tiny.values[2], 0.0);
  EXPECT_EQ(tickLabel(tiny.values.front(), tiny.decimals), "-0.4");
  const AxisTicks small = niceTicks(-3.0, 3.0, 2, -3.1, 3.1);  // step 5, then 2
  EXPECT_EQ(small.values, (std::vector<double>{-2.0, 0.0, 2.0}));
  // One fixed end only: the same.
  EXPECT_GE(niceTicks(0.0, 0.3, 2, 0.0, 0.3).values.size(), 2u);
}

TEST(PlotScale, TickLabels) {
  EXPECT_EQ(tickLabel(0.25, 2), "0.25");
  EXPECT_EQ(tickLabel(-1e-17, 1), "0.0");
  EXPECT_EQ(tickLabel(-0.0, 0), "0");
  EXPECT_EQ(tickLabel(20, 0), "20");
}

TEST(PlotScale, ValuesAtInterpolateEachSeries) {
  PlotSpec spec;
  spec.series = {{"a", {0, 10}, {1, 0}}, {"b", {5, 6}, {2, 4}}};
  const auto values = valuesAt(spec, 5.5);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_DOUBLE_EQ(*values[0], 0.45);
  EXPECT_DOUBLE_EQ(*values[1], 3.0);
  EXPECT_FALSE(valuesAt(spec, 8.0)[1].has_value());  // outside b's range
}

PlotSpec sampleSpec() {
  PlotSpec spec;
  spec.title = "Relative illumination";
  spec.note = "film diagonal 43.3 mm";
  spec.x.label = "image height (mm)";
  spec.y.label = "relative to the axis";
  spec.y.min = 0.0;
  spec.y.max = 1.05;
  spec.series = {{"total", {0, 10, 20}, {1, 0.6, 0.2}, 0xf0f0f0ffu},
                 {"cos4, \"chief\"", {0, 10, 20}, {1, 0.8, 0.45}, 0xffb347ffu, true}};
  return spec;
}

TEST(PlotCsv, HeaderAndRowsReadBack) {
  const std::string csv = plotCsv(sampleSpec());
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  // The comma and quotes in a name are quoted (RFC 4180).
  EXPECT_EQ(line, "image height (mm),total,\"cos4, \"\"chief\"\"\"");
  std::getline(lines, line);
  EXPECT_EQ(line, "0,1,1");
  std::getline(lines, line);
  EXPECT_EQ(line, "10,0.6,0.8");
  std::getline(lines, line);
  EXPECT_EQ(line, "20,0.2,0.45");
  EXPECT_FALSE(std::getline(lines, line));
}

TEST(PlotCsv, SeriesWithOtherXValuesLeaveCellsEmpty) {
  PlotSpec spec;
  spec.x.label = "x";
  spec.series = {{"a", {0, 1}, {5, 6}}, {"b", {1, 2}, {7, NAN}}};
  EXPECT_EQ(plotCsv(spec), "x,a,b\n0,5,\n1,6,7\n2,,\n");
}

// The numbers in `attribute="..."` of every element named `element`.
std::vector<std::string> attributes(const std::string& svg, const std::string& element,
                                    const std::string& attribute) {
  std::vector<std::string> found;
  const std::regex tag("<" + element + "[^>]*\\s" + attribute + "=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator();
       ++it)
    found.push_back((*it)[1]);
  return found;
}

std::vector<std::string> texts(const std::string& svg) {
  std::vector<std::string> found;
  const std::regex text("<text[^>]*>([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator();
       ++it)
    found.push_back((*it)[1]);
  return found;
}

TEST(PlotSvg, LabelsTicksLegendAndCurvesWhereTheAxesSay) {
  const std::string svg = plotSvg(sampleSpec(), 1200, 750, 16.0f);
  const auto words = texts(svg);
  auto has = [&](const std::string& w) {
    return std::find(words.begin(), words.end(), w) != words.end();
  };
  EXPECT_TRUE(has("Relative illumination"));
  EXPECT_TRUE(has("film diagonal 43.3 mm"));
  EXPECT_TRUE(has("image height (mm)"));
  EXPECT_TRUE(has("relative to the axis"));
  EXPECT_TRUE(has("total"));
  EXPECT_TRUE(has("cos4, &quot;chief&quot;"));
  // (0.2 apart on y: the legend under the box leaves it some 550 px tall.)
  for (const char* tick : {"0", "10", "20", "0.0", "0.4", "1.0"}) EXPECT_TRUE(has(tick)) << tick;
  // The curves: the point (10, 0.6) of "total" lies where the x tick "10" and the y ticks say.
  // x ticks: where the label "10" is centred.
  const std::regex xTick("<text class=\"x-tick\" x=\"([0-9.]+)\"[^>]*>10</text>");
  std::smatch tenTick;
  ASSERT_TRUE(std::regex_search(svg, tenTick, xTick));
  const auto polylines = attributes(svg, "polyline", "points");
  ASSERT_EQ(polylines.size(), 2u);
  std::istringstream points(polylines[0]);
  std::vector<std::pair<double, double>> xy;
  for (std::string pair; points >> pair;) {
    const auto comma = pair.find(',');
    xy.push_back({std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1))});
  }
  ASSERT_EQ(xy.size(), 3u);
  EXPECT_NEAR(xy[1].first, std::stod(tenTick[1]), 0.01);
  // y: 0 at the box's bottom, 1.05 at its top; the box is the rect with a stroke and no fill.
  const std::regex box(
      "<rect x=\"([0-9.]+)\" y=\"([0-9.]+)\" width=\"([0-9.]+)\" height=\"([0-9.]+)\" "
      "fill=\"none\"");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, box));
  const double top = std::stod(m[2]), height = std::stod(m[4]);
  EXPECT_NEAR(xy[1].second, top + height * (1.0 - 0.6 / 1.05), 0.02);
  EXPECT_NEAR(xy[0].second, top + height * (1.0 - 1.0 / 1.05), 0.02);
  // The dashed series is dashed, and white "total" is drawn dark on the white page.
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("data-name=\"total\" stroke=\"#202020\""), std::string::npos);
}

TEST(PlotLayout, LegendAvoidsTheCurves) {
  // A curve along the top: the legend goes to a bottom corner.
  PlotSpec spec = sampleSpec();
  spec.series[0].y = {1.0, 1.0, 1.0};
  spec.series[1].y = {1.0, 1.0, 0.95};
  const PlotFrame frame = layoutPlot(spec, {0, 0, 800, 500}, 14.0f,
                                     [](const std::string& s) { return 7.0f * s.size(); });
  ASSERT_GT(frame.legend.width, 0.0f);
  EXPECT_GT(frame.legend.y, frame.area.y + 0.5f * frame.area.height);
  // A curve along the bottom: the legend stays at the top.
  spec.series[0].y = {0.0, 0.05, 0.0};
  spec.series[1].y = {0.1, 0.05, 0.0};
  const PlotFrame low = layoutPlot(spec, {0, 0, 800, 500}, 14.0f,
                                   [](const std::string& s) { return 7.0f * s.size(); });
  EXPECT_LT(low.legend.y, low.area.y + 0.5f * low.area.height);
}

// The axes' boxes of an SVG plot: the rects with a black stroke and no fill.
std::vector<Rect> svgBoxes(const std::string& svg) {
  std::vector<Rect> boxes;
  const std::regex box(
      "<rect x=\"([0-9.]+)\" y=\"([0-9.]+)\" width=\"([0-9.]+)\" height=\"([0-9.]+)\" "
      "fill=\"none\" stroke=\"#000000\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), box); it != std::sregex_iterator();
       ++it)
    boxes.push_back(
        {std::stof((*it)[1]), std::stof((*it)[2]), std::stof((*it)[3]), std::stof((*it)[4])});
  return boxes;
}

TEST(PlotSvg, TheLegendStandsUnderTheBoxWhereItCoversNoCurve) {
  // Issue 38: a saved plot drew its legend inside the axes, over the curves. Each legend text's
  // baseline is below the box (and its x label), inside the picture.
  const std::string svg = plotSvg(sampleSpec(), 1200, 750, 16.0f);
  const auto boxes = svgBoxes(svg);
  ASSERT_EQ(boxes.size(), 1u);
  const std::regex legend("<text class=\"legend\" x=\"([0-9.]+)\" y=\"([0-9.]+)\"[^>]*>([^<]*)<");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), legend); it != std::sregex_iterator();
       ++it) {
    names.push_back((*it)[3]);
    const float y = std::stof((*it)[2]);
    EXPECT_GT(y - 16.0f, boxes[0].bottom()) << (*it)[3];
    EXPECT_LT(y, 750.0f);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"total", "cos4, &quot;chief&quot;"}));
}

// Three spot diagrams' worth of square plots, as the Spot panel shows them.
PlotFigure threeSpots() {
  PlotFigure figure;
  figure.title = "Spot diagram · Double-Gauss 50 mm, 22 degree half field · f/2.07";
  figure.note = "d; film shift +0.000 mm";
  figure.squareBoxes = true;
  for (const char* field : {"0 field", "0.7 field", "1 field"}) {
    PlotSpec spec;
    spec.title = std::string(field) + ", 0.0 deg";
    spec.x.label = "x (um)";
    spec.y.label = "y (um)";
    spec.x.min = spec.y.min = -20.0;
    spec.x.max = spec.y.max = 20.0;
    spec.equalAspect = true;
    PlotSeries rays{field, {1.0, -3.0, 5.0}, {2.0, 4.0, -6.0}, 0x50dc78ffu};
    rays.points = true;
    PlotSeries airy{
        "Airy disk", {-3.0, 0.0, 3.0, 0.0, -3.0}, {0.0, 3.0, 0.0, -3.0, 0.0}, 0xf0f0f0ffu};
    spec.series = {rays, airy};
    figure.plots.push_back(spec);
    figure.captions.push_back("RMS 1.0 um  GEO 2.0 um");
  }
  return figure;
}

TEST(PlotLayout, AFiguresPlotsStandSideBySideWithSquareBoxesAndTheLegendUnderThem) {
  const TextWidthPx width = [](const std::string& s) { return 9.0f * s.size(); };
  const PlotFigure figure = threeSpots();
  const FigureFrame frame = layoutFigure(figure, {0, 0, 1200, 750}, 18.0f, width);
  ASSERT_EQ(frame.plots.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const Rect& area = frame.plots[i].area;
    EXPECT_NEAR(area.width, area.height, 1.0f) << i;
    EXPECT_GT(area.width, 200.0f) << i;
    EXPECT_GE(area.x, 0.0f);
    EXPECT_LE(area.right(), 1200.0f);
    if (i > 0) {
      EXPECT_GT(area.x, frame.plots[i - 1].outer.right() - 0.5f) << i;  // side by side
      EXPECT_FLOAT_EQ(area.y, frame.plots[0].area.y);
    }
    EXPECT_LT(frame.titleY + frame.titlePx, frame.plots[i].outer.y + 1.0f);
    // The caption under the plot's x label, the legend under the captions.
    EXPECT_GE(frame.captionY[i], frame.plots[i].xLabelY + frame.lineHeightPx - 0.5f);
    EXPECT_GE(frame.legend.y, frame.captionY[i] + frame.lineHeightPx);
  }
  EXPECT_LE(frame.legend.bottom(), 750.0f);
  // Each name once: the three fields and the Airy disk.
  ASSERT_EQ(frame.legendItems.size(), 4u);
  EXPECT_EQ(figure.plots[frame.legendItems[3].plot].series[frame.legendItems[3].series].name,
            "Airy disk");
}

TEST(PlotLayout, ASquarePlotsAxesHaveThreeLabelsAtTheLeast) {
  // A spot diagram of the fisheye: -44 to 44 um in a box some 300 px wide. The x axis was
  // labelled "0" alone (its round step of 50 put -50 and 50 outside the box).
  PlotSpec spec = threeSpots().plots[0];
  spec.x.min = spec.y.min = -44.0;
  spec.x.max = spec.y.max = 44.0;
  spec.equalAspect = false;  // as spotPlot: fixed equal ranges
  const float fontPx = 18.75f;
  const PlotFrame frame = layoutPlot(spec, {0, 0, 380, 380}, fontPx, [&](const std::string& s) {
    return 0.6f * fontPx * static_cast<float>(s.size());
  });
  ASSERT_LT(frame.area.width, 340.0f);
  EXPECT_GE(frame.xTicks.values.size(), 3u);
  EXPECT_GE(frame.yTicks.values.size(), 3u);
  for (double value : frame.xTicks.values) {
    EXPECT_GE(value, -44.0);
    EXPECT_LE(value, 44.0);
  }
}

TEST(PlotSvg, AFigureHasOneBoxPerPlotAndTheTitleOnce) {
  const std::string svg = figureSvg(threeSpots(), 1200, 750);
  const auto boxes = svgBoxes(svg);
  ASSERT_EQ(boxes.size(), 3u);
  for (std::size_t i = 1; i < boxes.size(); ++i) EXPECT_GT(boxes[i].x, boxes[i - 1].right());
  const auto words = texts(svg);
  EXPECT_EQ(std::count(words.begin(), words.end(), threeSpots().title), 1);
  EXPECT_EQ(std::count(words.begin(), words.end(), "RMS 1.0 um  GEO 2.0 um"), 3);
  EXPECT_EQ(std::count(words.begin(), words.end(), "0.7 field, 0.0 deg"), 1);
  // Each plot clips its dots to its own box.
  EXPECT_NE(svg.find("id=\"plot-area-2\""), std::string::npos);
}

// Grouped bars on a categorical axis: two series over three categories ("1", "2", "total").
PlotSpec barSpec() {
  PlotSpec spec;
  spec.title = "Seidel sums per surface";
  spec.x.label = "surface";
  spec.y.label = "sum (mm)";
  spec.categories = {"1", "2", "total"};
  spec.series = {{"S_I", {0, 1, 2}, {0.2, -0.1, 0.1}, 0xff6b6bffu, false, PlotSeriesKind::Bars},
                 {"S_II", {0, 1, 2}, {0.05, 0.3, 0.35}, 0x5ec8ffffu, false, PlotSeriesKind::Bars}};
  return spec;
}

TEST(PlotLayout, BarsStandOnZeroSideBySideInTheirCategory) {
  const PlotFrame frame = layoutPlot(barSpec(), {0, 0, 900, 500}, 14.0f,
                                     [](const std::string& s) { return 7.0f * s.size(); });
  // One tick per category, the axis from -0.5 to 2.5; the labels are the names.
  EXPECT_EQ(frame.xTicks.values, (std::vector<double>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(frame.xTicks.min, -0.5);
  EXPECT_DOUBLE_EQ(frame.xTicks.max, 2.5);
  EXPECT_EQ(xTickText(barSpec(), frame, 2.0), "total");
  // The y axis includes zero and the most negative bar.
  EXPECT_LE(frame.yTicks.min, -0.1);
  ASSERT_EQ(frame.bars.size(), 6u);
  // The slot of a category is one unit wide; its two bars take 0.4 each from -0.4 to +0.4.
  const double unitPx = frame.area.width / 3.0;
  const float zero = frame.toScreenY(0.0);
  for (const PlotBar& bar : frame.bars) {
    const double left = frame.area.x + unitPx * (bar.index + 0.5 - 0.4 + 0.4 * bar.series);
    EXPECT_NEAR(bar.rect.x, left, 0.01);
    EXPECT_NEAR(bar.rect.width, 0.4 * unitPx, 0.01);
    const double value = barSpec().series[bar.series].y[bar.index];
    const float top = frame.toScreenY(value);
    EXPECT_NEAR(bar.rect.y, std::min(top, zero), 0.01);
    EXPECT_NEAR(bar.rect.height, std::abs(top - zero), 0.01);
  }
  // The negative bar hangs below the zero line.
  const PlotBar& negative = frame.bars[1];
  EXPECT_EQ(negative.series, 0u);
  EXPECT_EQ(negative.index, 1u);
  EXPECT_NEAR(negative.rect.y, zero, 0.01);
  // The legend stands right of the box, where no bar is.
  ASSERT_GT(frame.legend.width, 0.0f);
  EXPECT_GE(frame.legend.x, frame.area.right());
}

TEST(PlotCsv, CategoriesNameTheRows) {
  EXPECT_EQ(plotCsv(barSpec()), "surface,S_I,S_II\n1,0.2,0.05\n2,-0.1,0.3\ntotal,0.1,0.35\n");
}

TEST(PlotSvg, BarsAreRectanglesWithTheirNamesAndTheCategoriesLabelTheAxis) {
  const std::string svg = plotSvg(barSpec(), 1200, 750, 16.0f);
  const auto names = attributes(svg, "rect class=\"bar\"", "data-name");
  EXPECT_EQ(names, (std::vector<std::string>{"S_I", "S_I", "S_I", "S_II", "S_II", "S_II"}));
  const auto words = texts(svg);
  for (const char* label : {"1", "2", "total", "S_I", "S_II", "surface"})
    EXPECT_NE(std::find(words.begin(), words.end(), label), words.end()) << label;
  EXPECT_NE(svg.find("class=\"zero\""), std::string::npos);
  EXPECT_EQ(attributes(svg, "polyline", "points").size(), 0u);  // no line series
}

TEST(PlotLayout, TickLabelsNeverRunIntoEachOther) {
  // Long x labels (a million, at 10 px a character) on a 420 px plot, and a plot only a few lines
  // high: before, five x labels of 70 px stood 66 px apart and three y labels in 10 px.
  PlotSpec spec;
  spec.x.label = "x";
  spec.y.label = "y";
  spec.series = {{"a", {1e6, 5e6}, {-0.012, 0.011}, 0xffffffffu, false}};
  const auto width = [](const std::string& s) { return 10.0f * s.size(); };
  for (const Rect outer : {Rect{0, 0, 420, 400}, Rect{0, 0, 900, 120}, Rect{0, 0, 300, 90}}) {
    const PlotFrame frame = layoutPlot(spec, outer, 14.0f, width);
    const auto& xs = frame.xTicks.values;
    ASSERT_GE(xs.size(), 1u);
    for (std::size_t i = 1; i < xs.size(); ++i) {
      const float left = width(tickLabel(xs[i - 1], frame.xTicks.decimals));
      const float right = width(tickLabel(xs[i], frame.xTicks.decimals));
      EXPECT_GE(frame.toScreenX(xs[i]) - frame.toScreenX(xs[i - 1]), 0.5f * (left + right))
          << outer.width << " x " << outer.height << ": " << xs[i - 1] << ", " << xs[i];
    }
    const auto& ys = frame.yTicks.values;
    ASSERT_GE(ys.size(), 1u);
    for (std::size_t i = 1; i < ys.size(); ++i) {
      EXPECT_GE(frame.toScreenY(ys[i - 1]) - frame.toScreenY(ys[i]), frame.lineHeightPx)
          << outer.width << " x " << outer.height << ": " << ys[i - 1] << ", " << ys[i];
    }
  }
}

}  // namespace
}  // namespace lenslab::app
