#include "app/analysis/lens_figures.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>

#include "common/distance_text.h"
#include "optics/analysis/chromatic.h"
#include "optics/axial_beam_area.h"
#include "optics/focus.h"
#include "optics/limiting_aperture.h"
#include "optics/unvignetted_field.h"

namespace lenslab::app {

std::string colourFocusText(const optics::LensSystem& lens) {
  std::string whyNot;
  const auto shift = optics::chromaticFocalShiftFromInfinityMm(lens, &whyNot);
  // Short enough for one line of the first-order table (the tooltip says the rest).
  if (!shift)
    return optics::lensHasDispersion(lens.prescription()) ? "- (" + whyNot + ")" : "- (no V_d)";
  char text[128];
  // Negative: F (blue) focuses nearer the lens than C (red), as in a single positive lens.
  std::snprintf(text, sizeof text, "%+.4f mm, %s", *shift,
                *shift < 0   ? "blue nearer the lens"
                : *shift > 0 ? "red nearer the lens"
                             : "F and C together");
  return text;
}

namespace {

std::string fNumberText(const optics::LensSystem& lens, const optics::LimitingAperture& limit) {
  // The paraxial f-number of the beam that passes (EFL / limited entrance pupil), as `info`
  // prints it: not the iris's alone, which opened past the rims reads f/0.87 for an f/2 lens.
  const double fNumber = limit.paraxial && std::isfinite(limit.paraxial->workingFNumber)
                             ? limit.paraxial->workingFNumber
                             : lens.firstOrder().fNumber;
  char text[32];
  std::snprintf(text, sizeof text, "f/%.2f", fNumber);
  return text;
}

}  // namespace

std::string fNumberText(const optics::LensSystem& lens) {
  return fNumberText(lens,
                     optics::findLimitingAperture(lens, std::numeric_limits<double>::infinity()));
}

LensFigures computeLensFigures(std::shared_ptr<const optics::LensSystem> lensSystem,
                               bool withBeamFigures) {
  LensFigures figures;
  figures.lens = lensSystem;
  if (!lensSystem) return figures;
  const optics::LensSystem& lens = *lensSystem;
  const optics::FocusResult inFocus =
      optics::objectDistanceForFilmDistance(lens, lens.filmDistanceMm());
  if (inFocus.ok()) {
    figures.inFocusText = distanceText(*inFocus.valueMm) + " from the film";
  } else {
    // "nothing: the film is nearer the lens than ...", not "nothing (...: nothing is in focus)".
    std::string why = inFocus.whyNot;
    const std::string_view repeated = ": nothing is in focus";
    if (why.ends_with(repeated)) why.erase(why.size() - repeated.size());
    figures.inFocusText = "nothing: " + why;
  }
  figures.inFocusMm = inFocus.valueMm;
  figures.colourFocusText = colourFocusText(lens);
  if (!withBeamFigures) return figures;

  figures.hasBeamFigures = true;
  const optics::LimitingAperture limit =
      optics::findLimitingAperture(lens, std::numeric_limits<double>::infinity());
  const int surface = limit.limitingSurface();
  char text[160];
  if (!limit.real || surface < 0) {
    figures.axialBeamText = "no axial beam passes the lens";
  } else if (limit.limitedByStop(lens.stopIndex())) {
    std::snprintf(text, sizeof text, "the iris (surface %zu): working f/%.2f", lens.stopIndex() + 1,
                  limit.real->workingFNumber);
    figures.axialBeamText = text;
  } else {
    std::snprintf(text, sizeof text, "surface %d, %s the iris: working f/%.2f", surface + 1,
                  surface < static_cast<int>(lens.stopIndex()) ? "before" : "after",
                  limit.real->workingFNumber);
    figures.axialBeamText = text;
  }
  figures.fNumberText = fNumberText(lens, limit);
  if (!lens.stopShape().isCircle()) {
    if (const auto beam = optics::axialBeamAreaFromInfinity(lens)) {
      std::snprintf(text, sizeof text, "f/%.2f (a %.1f mm2 beam from infinity)",
                    beam->fNumberByArea, beam->areaMm2);
      figures.areaFNumberText = text;
    } else {
      figures.areaFNumberText = "- (no axial beam passes)";
    }
  }
  if (const auto unvignetted = optics::unvignettedFieldOfViewDeg(lens)) {
    std::snprintf(text, sizeof text, "%.1f deg from infinity", *unvignetted);
    figures.unvignettedText = text;
  } else {
    figures.unvignettedText = "- (no axial beam passes)";
  }
  return figures;
}

void requestLensFigures(LensFiguresView& view,
                        const std::shared_ptr<const optics::LensSystem>& lens, bool dragging) {
  if (!lens) return;
  const bool withBeam = !dragging;
  if (lens == view.requestedLens && (view.requestedBeamFigures || !withBeam)) return;
  if (!view.job) view.job = std::make_unique<LatestJob<LensFigures>>();
  view.requestedLens = lens;
  view.requestedBeamFigures = withBeam;
  view.job->request(++view.requests,
                    [lens, withBeam] { return computeLensFigures(lens, withBeam); });
}

std::shared_ptr<const LensFigures> latestLensFigures(const LensFiguresView& view) {
  return view.job ? view.job->latest() : nullptr;
}

bool lensFiguresCurrent(const LensFiguresView& view,
                        const std::shared_ptr<const optics::LensSystem>& lens) {
  const auto latest = latestLensFigures(view);
  return latest && latest->lens == lens && latest->hasBeamFigures;
}

}  // namespace lenslab::app
