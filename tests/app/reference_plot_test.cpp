// A pinned reference's curves added to a plot (analysis/reference_lens.h): named, dashed, in the
// tinted colour, out of the legend, which names the reference once; the axes' fixed ends grow to
// hold both; a reference with nothing to draw says why; the CSV carries both.

#include <gtest/gtest.h>

#include "app/analysis/reference_lens.h"
#include "app/plot/plot_csv.h"
#include "app/plot/plot_layout.h"

namespace lenslab::app {
namespace {

PlotSpec twoCurves(double scale) {
  PlotSpec spec;
  spec.title = "t";
  spec.x.label = "x";
  spec.y.label = "y";
  spec.x.min = 0.0;
  spec.x.max = 10.0 * scale;
  spec.series.push_back({"a", {0.0, 10.0 * scale}, {1.0, 2.0}, 0x50dc78ffu, false});
  spec.series.push_back({"b", {0.0, 10.0 * scale}, {3.0, 4.0}, 0xf0f0f0ffu, true});
  PlotSeries mark{"field 1", {5.0, 5.0}, {0.0, 4.0}, 0xff0000ffu, false};
  mark.guide = true;
  spec.series.push_back(mark);
  return spec;
}

TEST(ReferencePlot, AddsTheReferenceSeriesDashedTintedAndNamedOnce) {
  PlotSpec spec = twoCurves(1.0);
  addReference(spec, twoCurves(2.0), "Triplet · f/4");
  // The lens's three, the reference's two curves (not its guide), one legend entry.
  ASSERT_EQ(spec.series.size(), 6u);
  const PlotSeries& a = spec.series[3];
  EXPECT_EQ(a.name, "reference: a");
  EXPECT_TRUE(a.dashed);
  EXPECT_FALSE(a.inLegend);
  // 45% of (80, 220, 120) and 55% of (150, 130, 255), rounded: (119, 171, 194).
  EXPECT_EQ(a.rgba, 0x77abc2ffu);
  EXPECT_EQ(spec.series[4].name, "reference: b");
  // White: (191, 180, 248), below the exports' ink threshold in green.
  EXPECT_EQ(spec.series[4].rgba, 0xbfb4f8ffu);
  const PlotSeries& entry = spec.series[5];
  EXPECT_EQ(entry.name, "reference: Triplet · f/4");
  EXPECT_TRUE(entry.inLegend && entry.guide && entry.dashed);
  EXPECT_TRUE(entry.x.empty());
  // The x axis's fixed end grows to the reference's.
  EXPECT_EQ(*spec.x.max, 20.0);
  EXPECT_EQ(legendEntries(spec.series), 4u);  // a, b, field 1, the reference
  // The CSV: the reference's columns by name, no column for the legend entry.
  const std::string csv = plotCsv(spec);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "x,a,b,reference: a,reference: b");
}

TEST(ReferencePlot, AReferenceWithNothingToDrawSaysWhy) {
  PlotSpec spec = twoCurves(1.0);
  PlotSpec empty;
  empty.series.push_back({"a", {0.0, 1.0}, {NAN, NAN}, 0x50dc78ffu, false});
  addReference(spec, empty, "Singlet", "forms no image (diverging)");
  ASSERT_EQ(spec.series.size(), 4u);
  EXPECT_EQ(spec.series.back().name, "reference: Singlet: forms no image (diverging)");
  EXPECT_EQ(*spec.x.max, 10.0);
  PlotSpec computing = twoCurves(1.0);
  addReferenceNote(computing, "Singlet", "computing...");
  EXPECT_EQ(computing.series.back().name, "reference: Singlet: computing...");
}

TEST(ReferencePlot, TheLegendListsOnlyItsEntries) {
  PlotSpec spec = twoCurves(1.0);
  addReference(spec, twoCurves(1.0), "R");
  const auto width = [](const std::string& text) { return 7.0f * text.size(); };
  const PlotFrame frame = layoutPlot(spec, {0, 0, 900, 600}, 14.0f, width);
  ASSERT_GT(frame.legend.width, 0.0f);
  // Four rows (a, b, field 1, reference: R), not six.
  EXPECT_NEAR(frame.legend.height, 4 * frame.lineHeightPx + 0.5f * 14.0f, 1e-3);
  // A figure's legend under the plots: the same four names.
  PlotFigure figure = singlePlotFigure(spec);
  const FigureFrame laid = layoutFigure(figure, {0, 0, 900, 600}, 14.0f, width);
  EXPECT_EQ(laid.legendItems.size(), 4u);
}

}  // namespace
}  // namespace lenslab::app
