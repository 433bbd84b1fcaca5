#include "app/analysis/illumination_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/distance_text.h"

namespace lenslab::app {

void requestIllumination(IlluminationView& view,
                         const std::shared_ptr<const optics::LensSystem>& lens,
                         double filmDiagonalMm, bool rims) {
  if (!lens) return;
  if (lens == view.requestedLens && filmDiagonalMm == view.requestedFilmDiagonalMm &&
      rims == view.requestedRims)
    return;
  if (!view.job) view.job = std::make_unique<LatestJob<IlluminationResult>>();
  view.requestedLens = lens;
  view.requestedFilmDiagonalMm = filmDiagonalMm;
  view.requestedRims = rims;
  view.job->request(++view.requests, [lens, filmDiagonalMm, rims] {
    return computeIllumination(lens, filmDiagonalMm, rims);
  });
}

IlluminationResult computeIllumination(const std::shared_ptr<const optics::LensSystem>& lens,
                                       double filmDiagonalMm, bool rims) {
  IlluminationResult result{lens, filmDiagonalMm, rims, std::nullopt, std::nullopt};
  const double halfDiagonalMm = 0.5 * filmDiagonalMm;
  if (rims) {
    result.curve = optics::relativeIllumination(*lens, halfDiagonalMm, kIlluminationPoints, {},
                                                /*withRearDiskTotal=*/true);
  } else {
    // The render then samples the exit pupil, not the rear disk: no course curve.
    const auto stopOnly = lens->withApertureClipping(optics::ApertureClipping::StopOnly);
    result.curve = optics::relativeIllumination(*stopOnly, halfDiagonalMm, kIlluminationPoints);
    result.withRims = optics::relativeIllumination(*lens, halfDiagonalMm, kIlluminationPoints);
  }
  return result;
}

bool illuminationIsFor(const IlluminationResult& result,
                       const std::shared_ptr<const optics::LensSystem>& lens, double filmDiagonalMm,
                       bool rims) {
  return result.lens == lens && result.filmDiagonalMm == filmDiagonalMm && result.rims == rims;
}

std::string renderFalloffNote(render::FalloffToggles falloff) {
  return falloff.allOn() ? std::string() : "render: " + falloff.describe();
}

PlotSpec illuminationPlot(const IlluminationResult& result, bool againstFieldAngle,
                          bool sceneSamplesRearDisk, render::FalloffToggles falloff,
                          const MeasuredFalloff* measured) {
  PlotSpec spec;
  spec.title = "Relative illumination";
  spec.x.label = againstFieldAngle ? "field angle (deg)" : "image height (mm)";
  spec.x.min = 0.0;
  spec.y.label = "relative to the axis";
  spec.y.min = 0.0;
  spec.y.max = 1.05;
  spec.note = "film diagonal " + millimetresText(result.filmDiagonalMm) + "; film distance " +
              millimetresText(result.lens ? result.lens->filmDistanceMm() : 0.0);
  if (!falloff.allOn()) spec.note += "; " + renderFalloffNote(falloff);
  if (!result.curve) {
    spec.note += "; no light reaches the centre of the film";
    return spec;
  }
  // Colours for the dark theme (plot_svg darkens them on white).
  PlotSeries total{"total", {}, {}, 0xf0f0f0ffu, false};
  PlotSeries cos4{"cos4 (chief ray)", {}, {}, 0xffb347ffu, true};
  PlotSeries vignetting{"vignetting (apertures)", {}, {}, 0x5ec8ffffu, false};
  PlotSeries rearDisk{"course: rear-disk sampling", {}, {}, 0xff6b9dffu, true};
  PlotSeries totalWithRims{"total with the rims", {}, {}, 0x9a9a9affu, true};
  if (!result.rims) {
    // The curves below are the lens as rendered; the total with its rims for comparison.
    spec.note += "; curves as rendered (the stop alone clips)";
    if (result.withRims) {
      for (const optics::RelativeIlluminationPoint& p : result.withRims->points) {
        if (againstFieldAngle && !p.fieldAngleDeg) continue;
        totalWithRims.x.push_back(againstFieldAngle ? *p.fieldAngleDeg : p.imageHeightMm);
        totalWithRims.y.push_back(p.total);
      }
    }
  }
  for (const optics::RelativeIlluminationPoint& p : result.curve->points) {
    double x = p.imageHeightMm;
    if (againstFieldAngle) {
      if (!p.fieldAngleDeg) continue;  // beyond where a chief ray exists
      x = *p.fieldAngleDeg;
    }
    total.x.push_back(x);
    total.y.push_back(p.total);
    if (p.cos4 > 0.0) {
      cos4.x.push_back(x);
      cos4.y.push_back(p.cos4);
      vignetting.x.push_back(x);
      vignetting.y.push_back(p.vignetting);
    }
    if (p.rearDiskTotal) {
      rearDisk.x.push_back(x);
      rearDisk.y.push_back(*p.rearDiskTotal);
    }
  }
  // The axis ends at the film corner (or its field angle), not at the next round tick.
  if (!total.x.empty() && total.x.back() > 0.0) spec.x.max = total.x.back();
  spec.series = {total, cos4, vignetting};
  if (!totalWithRims.x.empty()) spec.series.push_back(totalWithRims);
  if (sceneSamplesRearDisk && falloff.rims) {  // rims off samples the exit pupil instead
    spec.series.push_back(rearDisk);
    spec.note += "; the render samples the rear element's disk, as the course did";
  }
  if (measured && measured->lens == result.lens && !measured->imageHeightMm.empty()) {
    PlotSeries fromRender{
        "measured from render (" + std::to_string(measured->samplesPerPixel) + " spp)",
        {},
        {},
        0x7ee08affu,
        false};
    const auto& points = result.curve->points;
    for (std::size_t i = 0; i < measured->imageHeightMm.size(); ++i) {
      double x = measured->imageHeightMm[i];
      if (againstFieldAngle) {
        // The field angle at that height, interpolated along the curve (none beyond the last
        // chief ray).
        const double step = points.size() > 1 ? points[1].imageHeightMm : 0.0;
        if (!(step > 0.0)) continue;
        const std::size_t j = std::min(static_cast<std::size_t>(x / step), points.size() - 2);
        if (!points[j].fieldAngleDeg || !points[j + 1].fieldAngleDeg) continue;
        const double t = std::clamp(x / step - static_cast<double>(j), 0.0, 1.0);
        x = *points[j].fieldAngleDeg * (1 - t) + *points[j + 1].fieldAngleDeg * t;
      }
      fromRender.x.push_back(x);
      fromRender.y.push_back(measured->relative[i]);
    }
    // With a toggle off the render can be brighter off the axis than on it (the wide-angle's
    // pupil grows): the axis makes room rather than cutting the curve off.
    for (double y : fromRender.y)
      if (std::isfinite(y) && y + 0.02 > *spec.y.max) spec.y.max = std::ceil((y + 0.02) * 20) / 20;
    spec.series.push_back(std::move(fromRender));
  }
  return spec;
}

}  // namespace lenslab::app
