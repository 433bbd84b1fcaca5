#include "app/analysis/ray_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "app/drawing/cross_section_drawing.h"
#include "common/units.h"
#include "optics/glass.h"

namespace lenslab::app {

namespace {

std::uint32_t opaqueRgba(Colour c) {
  return (std::uint32_t{c.r} << 24) | (std::uint32_t{c.g} << 16) | (std::uint32_t{c.b} << 8) |
         0xffu;
}

// Field i's colour, shaded toward blue for F and toward red for C.
std::uint32_t fanColour(std::size_t field, double wavelengthNm) {
  Colour c = palette::kFieldColours[field % std::size(palette::kFieldColours)];
  auto mix = [](std::uint8_t from, int to) {
    return static_cast<std::uint8_t>(0.55 * from + 0.45 * to);
  };
  if (std::abs(wavelengthNm - optics::kWavelengthFNm) < 0.01) {
    c = {mix(c.r, 60), mix(c.g, 110), mix(c.b, 255), 255};
  } else if (std::abs(wavelengthNm - optics::kWavelengthCNm) < 0.01) {
    c = {mix(c.r, 255), mix(c.g, 60), mix(c.b, 50), 255};
  }
  return opaqueRgba(c);
}

std::string lineName(double wavelengthNm) {
  if (std::abs(wavelengthNm - optics::kWavelengthDNm) < 0.01) return "d";
  if (std::abs(wavelengthNm - optics::kWavelengthFNm) < 0.01) return "F";
  if (std::abs(wavelengthNm - optics::kWavelengthCNm) < 0.01) return "C";
  char text[32];
  std::snprintf(text, sizeof text, "%.0f nm", wavelengthNm);
  return text;
}

std::string fieldName(const optics::TransverseFanField& field) {
  char text[64];
  std::snprintf(text, sizeof text, "%.2g field", field.fieldFraction);
  return text;
}

const optics::Spot* spotAt(const optics::SpotField& field, int focusIndex) {
  if (field.throughFocus.empty()) return field.atFilm ? &*field.atFilm : nullptr;
  const int index = std::clamp(focusIndex, 0, static_cast<int>(field.throughFocus.size()) - 1);
  return &field.throughFocus[static_cast<std::size_t>(index)];
}

}  // namespace

RayAnalysisResult computeRayAnalysis(const AnalysisRequest& request) {
  const optics::AnalysisSetup setup = analysisSetupFor(request);
  RayAnalysisResult result;
  result.request = request;
  result.setup = setup;
  result.fans = optics::computeTransverseRayFans(*request.lens, setup);
  result.spots = optics::computeSpotDiagrams(*request.lens, setup);
  return result;
}

void requestRayAnalysis(RayAnalysisView& view, const AnalysisRequest& request) {
  if (!request.lens) return;
  if (view.job && request == view.requested) return;
  if (!view.job) view.job = std::make_unique<LatestJob<RayAnalysisResult>>();
  view.requested = request;
  view.job->request(++view.requests, [request] { return computeRayAnalysis(request); });
}

std::shared_ptr<const RayAnalysisResult> latestRayAnalysis(const RayAnalysisView& view,
                                                           const AnalysisRequest& request,
                                                           bool* current) {
  auto result = view.job ? view.job->latest() : nullptr;
  if (current) *current = result && result->request == request;
  return result;
}

PlotSpec rayFanPlot(const RayAnalysisResult& result, FanPlane plane) {
  PlotSpec spec;
  spec.title = plane == FanPlane::Tangential ? "Tangential fan"
               : plane == FanPlane::Sagittal ? "Sagittal fan"
                                             : "Transverse ray fans";
  spec.x.label = plane == FanPlane::Tangential ? "pupil py"
                 : plane == FanPlane::Sagittal ? "pupil px"
                                               : "pupil coordinate";
  spec.y.label = plane == FanPlane::Tangential ? "ey (um)"
                 : plane == FanPlane::Sagittal ? "ex (um)"
                                               : "error (um)";
  spec.x.min = -1.0;
  spec.x.max = 1.0;
  spec.note = "from the " + lineName(result.fans.wavelengthsNm.front()) + " chief ray";
  if (result.fans.wavelengthsNm.size() > 1) spec.note += "; F bluer, C redder";
  if (plane == FanPlane::Both) spec.note += "; tangential solid, sagittal dashed";
  for (std::size_t f = 0; f < result.fans.fields.size(); ++f) {
    const optics::TransverseFanField& field = result.fans.fields[f];
    for (const optics::TransverseFansAtWavelength& at : field.wavelengths) {
      for (const bool tangential : {true, false}) {
        if (plane == FanPlane::Tangential && !tangential) continue;
        if (plane == FanPlane::Sagittal && tangential) continue;
        PlotSeries series;
        series.name = fieldName(field) + " " + lineName(at.wavelengthNm);
        if (plane == FanPlane::Both) series.name = (tangential ? "T " : "S ") + series.name;
        series.rgba = fanColour(f, at.wavelengthNm);
        series.dashed = plane == FanPlane::Both && !tangential;
        for (const optics::TransverseFanSample& s : tangential ? at.tangential : at.sagittal) {
          series.x.push_back(s.pupil);
          // A blocked ray is a gap in the line, not a zero.
          series.y.push_back(s.errorMm ? *s.errorMm * kMicronsPerMm : NAN);
        }
        spec.series.push_back(std::move(series));
      }
    }
  }
  return spec;
}

PlotSpec spotPlot(const RayAnalysisResult& result, int fieldIndex, int focusIndex) {
  const optics::SpotDiagrams& spots = result.spots;
  PlotSpec spec;
  spec.title = "Spot diagram";
  spec.x.label = "x (um)";
  spec.y.label = "y (um)";
  // One half width for every field and plane: the largest spot's reach, or the Airy disk's.
  double halfWidthUm = spots.airyRadiusMm.value_or(0.0) * kMicronsPerMm;
  for (const optics::SpotField& field : spots.fields)
    for (int i = 0; i < std::max<int>(1, static_cast<int>(field.throughFocus.size())); ++i)
      if (const optics::Spot* spot = spotAt(field, i)) {
        auto reach = [&](const std::vector<glm::dvec2>& points) {
          for (const glm::dvec2& p : points)
            halfWidthUm =
                std::max(halfWidthUm, kMicronsPerMm * std::max(std::abs(p.x), std::abs(p.y)));
        };
        reach(spot->raysMm);
        reach(spot->edgeRaysMm);
      }
  halfWidthUm = halfWidthUm > 0.0 && std::isfinite(halfWidthUm) ? 1.05 * halfWidthUm : 1.0;
  spec.x.min = spec.y.min = -halfWidthUm;
  spec.x.max = spec.y.max = halfWidthUm;

  char note[160];
  const optics::SpotField* any = spots.fields.empty() ? nullptr : &spots.fields.front();
  const optics::Spot* plane = any ? spotAt(*any, focusIndex) : nullptr;
  // "working": the real-ray f-number of the Airy disk, not the lens's f-number of the title.
  std::snprintf(note, sizeof note, "%s; film shift %+.3f mm; Airy radius %.2f um (working f/%.2f)",
                lineName(spots.wavelengthNm).c_str(), plane ? plane->filmShiftMm : 0.0,
                spots.airyRadiusMm.value_or(NAN) * kMicronsPerMm,
                spots.workingFNumber.value_or(NAN));
  spec.note = note;
  for (std::size_t f = 0; f < spots.fields.size(); ++f) {
    if (fieldIndex >= 0 && static_cast<int>(f) != fieldIndex) continue;
    const optics::SpotField& field = spots.fields[f];
    const optics::Spot* spot = spotAt(field, focusIndex);
    if (!spot) continue;
    PlotSeries rays;
    char name[64];
    std::snprintf(name, sizeof name, "%.2g field", field.fieldFraction);
    rays.name = name;
    rays.points = true;
    rays.rgba = opaqueRgba(palette::kFieldColours[f % std::size(palette::kFieldColours)]);
    for (const auto* points : {&spot->raysMm, &spot->edgeRaysMm})
      for (const glm::dvec2& p : *points) {
        rays.x.push_back(p.x * kMicronsPerMm);
        rays.y.push_back(p.y * kMicronsPerMm);
      }
    spec.series.push_back(std::move(rays));
  }
  // The Airy disk about the chief ray: a closed line (its x go round, which a line may when the
  // plot is a scatter: the CSV is then one point a row, and the hover readout is off).
  if (spots.airyRadiusMm && std::isfinite(*spots.airyRadiusMm)) {
    const double r = *spots.airyRadiusMm * kMicronsPerMm;
    PlotSeries airy{"Airy disk", {}, {}, 0xf0f0f0ffu, false, PlotSeriesKind::Line, false};
    for (int i = 0; i <= 96; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / 96.0;
      airy.x.push_back(r * std::cos(angle));
      airy.y.push_back(r * std::sin(angle));
    }
    spec.series.push_back(std::move(airy));
  }
  return spec;
}

PlotFigure rayFanFigure(const RayAnalysisResult& result) {
  PlotFigure figure;
  figure.plots = {rayFanPlot(result, FanPlane::Tangential), rayFanPlot(result, FanPlane::Sagittal)};
  figure.title = "Transverse ray fans";
  figure.note = figure.plots.front().note;
  // Each plot keeps its legend for the panel; a saved figure draws one under both instead.
  for (PlotSpec& plot : figure.plots) plot.note.clear();
  return figure;
}

PlotFigure spotFigure(const RayAnalysisResult& result, int focusIndex) {
  PlotFigure figure;
  const PlotSpec overview = spotPlot(result, -1, focusIndex);
  figure.title = overview.title;
  figure.note = overview.note;
  figure.squareBoxes = true;
  for (std::size_t f = 0; f < result.spots.fields.size(); ++f) {
    const optics::SpotField& field = result.spots.fields[f];
    PlotSpec spec = spotPlot(result, static_cast<int>(f), focusIndex);
    char title[96];
    std::snprintf(title, sizeof title, "%.2g field, %.1f deg", field.fieldFraction,
                  field.fieldAngleDeg.value_or(0.0));
    spec.title = field.fieldAngleDeg ? title : "no ray reaches this field";
    spec.note.clear();
    spec.legend = false;
    figure.plots.push_back(std::move(spec));
    figure.captions.push_back(spotFigures(result, static_cast<int>(f), focusIndex));
  }
  return figure;
}

std::string spotFigures(const RayAnalysisResult& result, int fieldIndex, int focusIndex) {
  if (fieldIndex < 0 || fieldIndex >= static_cast<int>(result.spots.fields.size())) return "";
  const optics::SpotField& field = result.spots.fields[static_cast<std::size_t>(fieldIndex)];
  const optics::Spot* spot = spotAt(field, focusIndex);
  if (!spot) return field.whyNot.empty() ? "no ray passes" : field.whyNot;
  char text[96];
  std::snprintf(text, sizeof text, "RMS %.1f um  GEO %.1f um", spot->rmsRadiusMm * kMicronsPerMm,
                spot->geoRadiusMm * kMicronsPerMm);
  return text;
}

}  // namespace lenslab::app
