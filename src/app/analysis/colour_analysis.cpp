#include "app/analysis/colour_analysis.h"

#include <cmath>
#include <cstdio>

#include "common/distance_text.h"
#include "common/formatted.h"

namespace lenslab::app {

namespace {

// Colours for the dark theme (the exports darken them on white), one per aberration.
constexpr std::uint32_t kSeidelColours[] = {0xff6b6bffu, 0xffb347ffu, 0xf2e05cffu, 0x5ec8ffffu,
                                            0xc08cffffu};
constexpr std::uint32_t kAxialColour = 0x4f9dffffu, kLateralColour = 0xff6fb0ffu;

std::string objectText(const optics::AnalysisSetup& setup) {
  return setup.objectDistanceFromFilmMm
             ? "object " + distanceText(*setup.objectDistanceFromFilmMm) + " from the film"
             : "object at infinity";
}

}  // namespace

ColourResult computeColour(const std::shared_ptr<const optics::LensSystem>& lens,
                           const optics::AnalysisSetup& setup) {
  ColourResult result;
  result.lens = lens;
  result.setup = setup;
  if (!lens) return result;
  result.seidel =
      optics::computeSeidelSums(*lens, setup.objectDistanceFromFilmMm,
                                optics::seidelFieldHeightMm(*lens, setup), &result.seidelWhyNot);
  result.dispersive = optics::lensHasDispersion(lens->prescription());
  if (!result.dispersive) return result;
  result.focalShift = optics::chromaticFocalShift(*lens, setup.objectDistanceFromFilmMm, 31, 400.0,
                                                  700.0, &result.focalShiftWhyNot);
  result.fields = optics::lateralColour(*lens, setup);
  optics::AnalysisSetup along = setup;
  along.fieldFractions.clear();
  for (int i = 0; i < kLateralColourCurvePoints; ++i)
    along.fieldFractions.push_back(static_cast<double>(i) / (kLateralColourCurvePoints - 1));
  result.curve = optics::lateralColour(*lens, along);
  return result;
}

void requestColour(ColourView& view, const AnalysisRequest& request) {
  if (!request.lens) return;
  if (view.requested == request) return;
  if (!view.job) view.job = std::make_unique<LatestJob<ColourResult>>();
  view.requested = request;
  view.job->request(++view.requests, [request] {
    // The object plane takes real rays to find (where the film is focused): here, not on the UI.
    ColourResult result = computeColour(request.lens, analysisSetupFor(request));
    result.request = request;
    return result;
  });
}

std::shared_ptr<const ColourResult> latestColour(const ColourView& view) {
  return view.job ? view.job->latest() : nullptr;
}

bool colourIsCurrent(const ColourView& view, const AnalysisRequest& request) {
  const auto result = latestColour(view);
  return result && result->request == request;
}

PlotSpec seidelPlot(const ColourResult& result, bool chromaticSums) {
  PlotSpec spec;
  spec.title = chromaticSums ? "Chromatic Seidel sums per surface" : "Seidel sums per surface";
  spec.x.label = "surface";
  spec.y.label =
      chromaticSums ? "sum (mm): C_L axial, C_T lateral colour" : "sum (mm of wavefront, Welford)";
  if (!result.seidel) {
    spec.note = result.seidelWhyNot.empty() ? "no sums" : result.seidelWhyNot;
    return spec;
  }
  const optics::SeidelSums& sums = *result.seidel;
  spec.note = formatted("marginal ray to a %.2f mm pupil radius, chief ray to a %.1f mm image; ",
                        sums.entrancePupilRadiusMm, sums.fieldHeightMm) +
              objectText(result.setup);
  for (std::size_t i = 0; i < sums.surfaces.size(); ++i)
    spec.categories.push_back(std::to_string(i + 1));
  spec.categories.push_back("total");
  auto bars = [&](const char* name, std::uint32_t rgba, double optics::SeidelTerms::*term) {
    PlotSeries series{name, {}, {}, rgba, false, PlotSeriesKind::Bars};
    for (std::size_t i = 0; i <= sums.surfaces.size(); ++i) {
      series.x.push_back(static_cast<double>(i));
      series.y.push_back(i < sums.surfaces.size() ? sums.surfaces[i].*term : sums.total.*term);
    }
    return series;
  };
  if (chromaticSums) {
    if (!sums.chromatic) {
      spec.note = "no glass of this lens has an Abbe number (V_d): no colour sums";
      return spec;
    }
    spec.series = {bars("C_L axial colour", kAxialColour, &optics::SeidelTerms::cl),
                   bars("C_T lateral colour", kLateralColour, &optics::SeidelTerms::ct)};
  } else {
    spec.series = {bars("S_I spherical", kSeidelColours[0], &optics::SeidelTerms::s1),
                   bars("S_II coma", kSeidelColours[1], &optics::SeidelTerms::s2),
                   bars("S_III astigmatism", kSeidelColours[2], &optics::SeidelTerms::s3),
                   bars("S_IV Petzval", kSeidelColours[3], &optics::SeidelTerms::s4),
                   bars("S_V distortion", kSeidelColours[4], &optics::SeidelTerms::s5)};
  }
  return spec;
}

PlotSpec focalShiftPlot(const ColourResult& result) {
  PlotSpec spec;
  spec.title = "Chromatic focal shift";
  spec.x.label = "wavelength (nm)";
  spec.x.min = 400.0;
  spec.x.max = 700.0;
  spec.y.label = "paraxial focus minus the d line's (mm, + away from the lens)";
  if (!result.dispersive) {
    spec.note = "no glass of this lens has an Abbe number (V_d): no colour";
    return spec;
  }
  if (!result.focalShift) {
    spec.note = result.focalShiftWhyNot;
    return spec;
  }
  spec.note =
      formatted("F - C = %.4f mm (F 486 nm, d 588 nm, C 656 nm); ", result.focalShift->fMinusCMm) +
      objectText(result.setup);
  PlotSeries curve{"focus shift", {}, {}, 0xf0f0f0ffu, false};
  for (const optics::FocalShiftPoint& p : result.focalShift->curve) {
    curve.x.push_back(p.wavelengthNm);
    curve.y.push_back(p.shiftMm);
  }
  spec.series = {curve};
  return spec;
}

PlotSpec lateralColourPlot(const ColourResult& result) {
  PlotSpec spec;
  spec.title = "Lateral colour";
  spec.x.label = "image height (mm)";
  spec.x.min = 0.0;
  spec.y.label = "chief ray at F minus at C (um)";
  if (!result.dispersive) {
    spec.note = "no glass of this lens has an Abbe number (V_d): no colour";
    return spec;
  }
  spec.note = "real chief rays from the d line's object point; " + objectText(result.setup);
  PlotSeries real{"real rays", {}, {}, kLateralColour, false};
  for (const optics::LateralColour& p : result.curve) {
    if (!p.lateralColourUm) continue;
    real.x.push_back(p.imageHeightMm);
    real.y.push_back(*p.lateralColourUm);
  }
  spec.series = {real};
  if (result.seidel && result.seidel->chromatic && result.seidel->fieldHeightMm > 0.0) {
    // Third order: linear in the field.
    PlotSeries third{"third order (C_T)", {}, {}, 0xb0b0b0ffu, true};
    const double perMm =
        1000.0 * result.seidel->transverse.lateralColourMm / result.seidel->fieldHeightMm;
    for (double h : {0.0, fieldRadiusMm(result.setup)}) {
      third.x.push_back(h);
      third.y.push_back(perMm * h);
    }
    spec.series.push_back(third);
  }
  if (!real.x.empty() && real.x.back() > 0.0) spec.x.max = fieldRadiusMm(result.setup);
  return spec;
}

}  // namespace lenslab::app
