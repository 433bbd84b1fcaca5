#include "app/analysis/distortion_analysis.h"

#include "optics/field_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/drawing/cross_section_drawing.h"
#include "common/distance_text.h"

namespace lenslab::app {

namespace {

constexpr double kBreak = std::numeric_limits<double>::quiet_NaN();  // breaks a plotted line

// Field i's mark: a guide line in the colour of field i's fan in the cross-section.
PlotSeries fieldMark(const DistortionResult::FieldMark& mark, std::size_t index,
                     std::vector<double> x, std::vector<double> y) {
  const Colour c = palette::kFieldColours[index % std::size(palette::kFieldColours)];
  char name[32];
  std::snprintf(name, sizeof name, "field %g", mark.fraction);
  PlotSeries series{
      name, std::move(x), std::move(y),
      (std::uint32_t{c.r} << 24) | (std::uint32_t{c.g} << 16) | (std::uint32_t{c.b} << 8) | 0xffu,
      false};
  series.guide = true;
  return series;
}

std::string objectText(const DistortionResult& result) {
  return result.objectDistanceFromFilmMm
             ? "object " + distanceText(*result.objectDistanceFromFilmMm) + " from the film"
             : "object at infinity";
}

}  // namespace

void requestDistortion(DistortionView& view, const AnalysisRequest& request) {
  if (!request.lens) return;
  if (view.job && request == view.requested) return;
  if (!view.job) view.job = std::make_unique<LatestJob<DistortionResult>>();
  view.requested = request;
  view.job->request(++view.requests, [request] { return computeDistortion(request); });
}

DistortionResult computeDistortion(const AnalysisRequest& request) {
  DistortionResult result;
  result.request = request;
  const optics::AnalysisSetup setup = analysisSetupFor(request);
  result.setup = setup;
  result.objectDistanceFromFilmMm = setup.objectDistanceFromFilmMm;
  const optics::LensSystem& lens = *request.lens;
  result.distortion = optics::distortionCurve(lens, setup, kDistortionPoints, &result.whyNot);
  const optics::FieldScale scale = optics::fieldScaleFor(lens, setup);
  for (double fraction : setup.fieldFractions) {
    const double h = scale.imageHeightMm(fraction);
    const auto field = optics::FieldPoint::resolve(lens, h, setup.objectDistanceFromFilmMm);
    result.fieldMarks.push_back(
        {fraction, h, field ? std::optional(field->fieldAngleDeg()) : std::nullopt});
  }
  if (result.distortion) {
    result.grid = optics::distortionGrid(lens, setup, kGridFilmAspect, 8, kDistortionPoints);
    result.fieldCurves = optics::fieldCurvature(lens, setup, kDistortionPoints);
  }
  return result;
}

std::shared_ptr<const DistortionResult> currentDistortion(const DistortionView& view,
                                                          const AnalysisRequest& request) {
  if (!view.job) return nullptr;
  auto result = view.job->latest();
  return result && result->request == request ? result : nullptr;
}

PlotSpec distortionPlot(const DistortionResult& result, bool againstFieldAngle) {
  PlotSpec spec;
  spec.title = "Distortion";
  spec.x.label = againstFieldAngle ? "field angle (deg)" : "image height (mm)";
  spec.x.min = 0.0;
  spec.y.label = "distortion (%)";
  if (!result.distortion) {
    spec.note = result.whyNot;
    return spec;
  }
  const optics::DistortionCurve& curve = *result.distortion;
  spec.note = std::string(curve.objectAtInfinity ? "real chief ray vs f tan(theta)"
                                                 : "real chief ray vs paraxial m Y") +
              ", on the film; " + objectText(result);
  PlotSeries series{"distortion", {}, {}, 0xf0f0f0ffu, false};
  for (const optics::DistortionPoint& p : curve.points) {
    if (!p.percent) {
      series.x.push_back(kBreak);
      series.y.push_back(kBreak);
      continue;
    }
    series.x.push_back(againstFieldAngle ? *p.fieldAngleDeg : p.imageHeightMm);
    series.y.push_back(*p.percent);
  }
  // The axis ends at the corner (or its field angle), not at the next round tick.
  for (std::size_t i = series.x.size(); i-- > 0;) {
    if (std::isfinite(series.x[i])) {
      if (series.x[i] > 0.0) spec.x.max = series.x[i];
      break;
    }
  }
  spec.series = {series};
  // The fields, across the curve's range.
  double low = 0.0, high = 0.0;
  for (double y : series.y)
    if (std::isfinite(y)) low = std::min(low, y), high = std::max(high, y);
  if (high - low < 1e-9) low -= 0.5, high += 0.5;
  for (std::size_t i = 0; i < result.fieldMarks.size(); ++i) {
    const auto& mark = result.fieldMarks[i];
    if (againstFieldAngle && !mark.fieldAngleDeg) continue;
    const double x = againstFieldAngle ? *mark.fieldAngleDeg : mark.imageHeightMm;
    spec.series.push_back(fieldMark(mark, i, {x, x}, {low, high}));
  }
  return spec;
}

PlotSpec distortionGridPlot(const DistortionResult& result) {
  PlotSpec spec;
  spec.title = "Grid distortion";
  spec.x.label = "across the film (mm)";
  spec.y.label = "up the film (mm)";
  spec.equalAspect = true;
  if (!result.grid) {
    spec.note = result.whyNot;
    return spec;
  }
  spec.note = "a square grid whose paraxial image fills a 3:2 film; " + objectText(result);
  PlotSeries ideal{"paraxial", {}, {}, 0x6e7480ffu, false};
  PlotSeries real{"real chief rays", {}, {}, 0x5ec8ffffu, false};
  auto add = [](PlotSeries& series, const std::vector<std::vector<glm::dvec2>>& lines) {
    for (const auto& line : lines) {
      for (const glm::dvec2& p : line) {
        series.x.push_back(p.x);
        series.y.push_back(p.y);
      }
      series.x.push_back(kBreak);
      series.y.push_back(kBreak);
    }
  };
  add(ideal, result.grid->ideal);
  add(real, result.grid->real);
  spec.series = {ideal, real};
  return spec;
}

PlotSpec fieldCurvesPlot(const DistortionResult& result) {
  PlotSpec spec;
  spec.title = "Field curves";
  spec.x.label = "focus from the film (mm, + behind it)";
  spec.y.label = "field angle (deg)";
  spec.y.min = 0.0;
  spec.seriesAlongY = true;
  if (!result.fieldCurves) {
    spec.note = result.whyNot;
    return spec;
  }
  spec.note = "real-ray pairs about each chief ray; " + objectText(result);
  // White dashed and solid, as the books draw them; colours are the fields'.
  PlotSeries tangential{"tangential", {}, {}, 0xf0f0f0ffu, true};
  PlotSeries sagittal{"sagittal", {}, {}, 0xf0f0f0ffu, false};
  PlotSeries petzval{"Petzval (3rd order)", {}, {}, 0x8a8f99ffu, true};
  PlotSeries film{"film", {}, {}, 0x6e7480ffu, false};
  double top = 0.0;
  for (const optics::FieldCurvaturePoint& p : result.fieldCurves->points) {
    if (!p.fieldAngleDeg || !p.tangentialMm || !p.sagittalMm) {
      for (PlotSeries* s : {&tangential, &sagittal, &petzval}) {
        s->x.push_back(kBreak);
        s->y.push_back(kBreak);
      }
      continue;
    }
    const double angle = *p.fieldAngleDeg;
    top = std::max(top, angle);
    tangential.x.push_back(*p.tangentialMm);
    tangential.y.push_back(angle);
    sagittal.x.push_back(*p.sagittalMm);
    sagittal.y.push_back(angle);
    petzval.x.push_back(p.petzvalMm);
    petzval.y.push_back(angle);
  }
  film.x = {0.0, 0.0};
  film.y = {0.0, top};
  if (top > 0.0) spec.y.max = top;
  spec.series = {tangential, sagittal, petzval, film};
  double left = 0.0, right = 0.0;
  for (const PlotSeries& s : spec.series)
    for (double x : s.x)
      if (std::isfinite(x)) left = std::min(left, x), right = std::max(right, x);
  for (std::size_t i = 0; i < result.fieldMarks.size(); ++i) {
    const auto& mark = result.fieldMarks[i];
    if (!mark.fieldAngleDeg) continue;
    spec.series.push_back(
        fieldMark(mark, i, {left, right}, {*mark.fieldAngleDeg, *mark.fieldAngleDeg}));
  }
  return spec;
}

}  // namespace lenslab::app
