#include "app/analysis/mtf_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/drawing/cross_section_drawing.h"
#include "common/distance_text.h"
#include "common/formatted.h"

namespace lenslab::app {

namespace {

// The panel's curves: twice the JSON's frequency samples, for smooth lines at a plot's width.
constexpr int kPanelFrequencySamples = 129;

std::uint32_t rgba(const Colour& c) {
  return (std::uint32_t{c.r} << 24) | (std::uint32_t{c.g} << 16) | (std::uint32_t{c.b} << 8) |
         std::uint32_t{c.a};
}

double chosenRange(const MtfView& view) {
  constexpr int kChoices = static_cast<int>(std::size(kMtfRangesCyclesPerMm));
  return kMtfRangesCyclesPerMm[std::clamp(view.rangeChoice, 0, kChoices - 1)];
}

}  // namespace

void requestMtf(MtfView& view, const AnalysisRequest& request) {
  const double range = chosenRange(view);
  if (!request.lens || (request == view.requested && range == view.requestedRangeCyclesPerMm))
    return;
  if (!view.job) view.job = std::make_unique<LatestJob<MtfAnalysisResult>>();
  view.requested = request;
  view.requestedRangeCyclesPerMm = range;
  view.job->request(++view.requests, [request, range] { return computeMtf(request, range); });
}

double chosenMtfRange(const MtfView& view) { return chosenRange(view); }

MtfAnalysisResult computeMtf(const AnalysisRequest& request, double rangeCyclesPerMm) {
  MtfAnalysisResult result;
  result.request = request;
  result.rangeCyclesPerMm = rangeCyclesPerMm;
  result.setup = analysisSetupFor(request);
  optics::MtfOptions options;
  options.frequencySamples = kPanelFrequencySamples;
  options.commonFrequencyAxis = true;  // one CSV row per frequency
  if (rangeCyclesPerMm > 0.0) options.frequencyRangeCyclesPerMm = rangeCyclesPerMm;
  result.mtf = optics::diffractionMtf(*request.lens, result.setup, options);
  return result;
}

std::shared_ptr<const MtfAnalysisResult> latestMtf(const MtfView& view) {
  return view.job ? view.job->latest() : nullptr;
}

bool mtfIsCurrent(const MtfView& view, const MtfAnalysisResult* result,
                  const AnalysisRequest& request) {
  return result && result->request == request && result->rangeCyclesPerMm == chosenRange(view);
}

PlotSpec mtfPlot(const MtfAnalysisResult& result) {
  PlotSpec spec;
  spec.title = "MTF";
  spec.x.label = "spatial frequency (cycles/mm)";
  spec.x.min = 0.0;
  spec.y.label = "modulation";
  spec.y.min = 0.0;
  spec.y.max = 1.05;
  spec.note =
      formatted("diffraction MTF at %.1f nm, object ", result.mtf.wavelengthNm) +
      (result.setup.objectDistanceFromFilmMm
           ? "at " + millimetresText(*result.setup.objectDistanceFromFilmMm) + " from the film"
           : std::string("at infinity")) +
      "; T solid, S dashed";

  double largestCutoff = 0.0;
  std::string rms, missing;
  const optics::FieldMtf* limitField = nullptr;
  std::size_t limitIndex = 0;
  for (std::size_t i = 0; i < result.mtf.fields.size(); ++i) {
    const optics::FieldMtf& field = result.mtf.fields[i];
    const double fraction =
        i < result.setup.fieldFractions.size() ? result.setup.fieldFractions[i] : 0.0;
    if (field.whyNot) {
      missing += formatted("; field %g: ", fraction) + *field.whyNot;
      continue;
    }
    if (!limitField) {
      limitField = &field;
      limitIndex = i;
    }
    largestCutoff = std::max(largestCutoff, field.cutoffCyclesPerMm);
    rms += formatted("%s%.2f", rms.empty() ? "" : ", ", field.rmsWavefrontErrorWaves);
    const std::uint32_t colour =
        rgba(palette::kFieldColours[i % std::size(palette::kFieldColours)]);
    const std::string name = formatted("%g field (%.1f deg)", fraction, field.fieldAngleDeg);
    spec.series.push_back(
        {name + " T", field.frequenciesCyclesPerMm, field.tangential, colour, false});
    spec.series.push_back(
        {name + " S", field.frequenciesCyclesPerMm, field.sagittal, colour, true});
  }
  if (limitField) {
    // Light grey on the dark theme; the SVG and PNG darken it on white.
    const double fraction = limitIndex < result.setup.fieldFractions.size()
                                ? result.setup.fieldFractions[limitIndex]
                                : 0.0;
    spec.series.insert(spec.series.begin(),
                       PlotSeries{formatted("diffraction limit (%g field)", fraction),
                                  limitField->frequenciesCyclesPerMm,
                                  limitField->diffractionLimitTangential, 0xb4b4b4ffu, false});
    spec.x.max = result.rangeCyclesPerMm > 0.0 ? result.rangeCyclesPerMm : largestCutoff;
    spec.note += "; rms wavefront error " + rms + " waves";
  }
  spec.note += missing;
  return spec;
}

}  // namespace lenslab::app
