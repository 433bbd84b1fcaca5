#include "app/analysis/reference_lens.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/lens_caption.h"
#include "app/viewer_state.h"
#include "optics/focus.h"
#include "optics/glass.h"

namespace lenslab::app {

ReferenceAnalyses computeReferenceAnalyses(const ReferenceSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  ReferenceAnalyses analyses;
  analyses.settings = settings;
  const AnalysisRequest& request = settings.request;
  const auto& lens = request.lens;
  // What each panel's worker computes for the current lens, with the same functions.
  analyses.illumination = computeIllumination(lens, settings.filmDiagonalMm, settings.rims);
  analyses.rays = computeRayAnalysis(request);
  analyses.distortion = computeDistortion(request);
  analyses.colour = computeColour(lens, analysisSetupFor(request));
  analyses.colour.request = request;
  analyses.mtf = computeMtf(request, settings.mtfRangeCyclesPerMm);
  analyses.figures = computeLensFigures(lens, /*withBeamFigures=*/true);
  const optics::InfinityImage image = optics::infinityImage(*lens);
  if (!image.ok()) analyses.noImage = image.whyNot.empty() ? "no real image" : image.whyNot;
  analyses.computeMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return analyses;
}

ReferenceSettings referenceSettingsOf(const ViewerState& state, const ReferenceLens& reference) {
  ReferenceSettings settings;
  settings.request.lens = reference.lens;
  settings.request.fieldFractions = state.fanSettings.fieldFractions;
  settings.request.filmHalfDiagonalMm = 0.5 * state.filmDiagonalMm;
  settings.filmDiagonalMm = state.filmDiagonalMm;
  settings.rims = state.falloff.rims;
  settings.mtfRangeCyclesPerMm = chosenMtfRange(state.mtf);
  return settings;
}

std::optional<std::string> pinReference(ViewerState& state) {
  if (!state.lensSystem || !state.lensSystemIsCurrent)
    return "there is no valid lens to pin as the reference";
  ReferenceLens reference;
  // The LensSystem is immutable: sharing it is keeping a copy of the lens as it is now; an edit
  // builds a new one for the document.
  reference.lens = state.lensSystem;
  reference.title = lensTitle(state);
  state.reference.emplace(std::move(reference));
  state.crossSectionNeedsFit = true;  // both lenses at one scale
  state.log.info("Pinned " + state.reference->title + " as the reference");
  return std::nullopt;
}

void unpinReference(ViewerState& state) {
  if (!state.reference) return;
  state.log.info("Unpinned the reference " + state.reference->title);
  state.reference.reset();
  state.crossSectionNeedsFit = true;
}

const CrossSectionDrawing& referenceCrossSection(ViewerState& state) {
  ReferenceLens& reference = *state.reference;
  ReferenceCrossSection& cached = reference.crossSection;
  const FanSettings& fans = state.fanSettings;
  const std::optional<double> object =
      fans.objectAtInfinity ? std::nullopt : std::optional(fans.objectDistanceMm);
  if (cached.drawn && cached.fieldFractions == fans.fieldFractions &&
      cached.raysPerFan == fans.raysPerFan && cached.showBlocked == fans.showBlocked &&
      cached.colourFans == fans.colourFans && cached.rims == state.falloff.rims &&
      cached.objectDistanceFromFilmMm == object && cached.filmDiagonalMm == state.filmDiagonalMm)
    return cached.drawing;
  cached = ReferenceCrossSection{true,
                                 fans.fieldFractions,
                                 fans.raysPerFan,
                                 fans.showBlocked,
                                 fans.colourFans,
                                 state.falloff.rims,
                                 object,
                                 state.filmDiagonalMm,
                                 {}};
  const optics::LensSystem& lens = *reference.lens;
  cached.drawing =
      drawLens(optics::computeLensOutline(lens.prescription()), 0.5 * state.filmDiagonalMm);
  // The fans as refreshLens traces the current lens's (viewer_state.cpp), for the reference.
  optics::FanSpec spec;
  spec.raysPerFan = fans.raysPerFan;
  spec.fieldFractions = fans.fieldFractions;
  spec.filmHalfDiagonalMm = 0.5 * state.filmDiagonalMm;
  if (object) spec.objectDistanceMm = std::max(*object - lens.totalTrackMm(), 1.0);
  if (fans.colourFans) spec.otherWavelengthsNm = {optics::kWavelengthFNm, optics::kWavelengthCNm};
  const auto rendered = state.falloff.rims
                            ? reference.lens
                            : lens.withApertureClipping(optics::ApertureClipping::StopOnly);
  drawRayFans(cached.drawing, optics::computeRayFans(*rendered, spec), fans.showBlocked);
  return cached.drawing;
}

namespace {

void requestReference(ReferenceLens& reference, const ReferenceSettings& settings) {
  if (reference.job && settings == reference.requested) return;
  if (!reference.job) reference.job = std::make_unique<LatestJob<ReferenceAnalyses>>();
  reference.requested = settings;
  reference.job->request(++reference.requests,
                         [settings] { return computeReferenceAnalyses(settings); });
}

}  // namespace

std::shared_ptr<const ReferenceAnalyses> referenceAnalyses(ViewerState& state, bool* computing) {
  if (computing) *computing = false;
  if (!state.reference) return nullptr;
  const ReferenceSettings settings = referenceSettingsOf(state, *state.reference);
  requestReference(*state.reference, settings);
  auto result = state.reference->job->latest();
  if (result && result->settings == settings) return result;
  if (computing) *computing = true;
  return nullptr;
}

bool referenceSettled(const ViewerState& state) {
  if (!state.reference) return true;
  const ReferenceLens& reference = *state.reference;
  const ReferenceSettings settings = referenceSettingsOf(state, reference);
  if (!reference.job || !(reference.requested == settings)) return true;
  const auto result = reference.job->latest();
  return result && result->settings == settings && reference.drawn.settled(state.frameNumber);
}

namespace {

std::optional<double> fNumberOf(const std::string& text) {
  if (text.rfind("f/", 0) != 0) return std::nullopt;
  try {
    return std::stod(text.substr(2));
  } catch (...) {
    return std::nullopt;
  }
}

std::string mmText(double value, const char* format = "%.2f mm") {
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

std::vector<FirstOrderComparisonRow> compareFirstOrder(const optics::LensSystem& lens,
                                                       const std::string& lensFNumberText,
                                                       const ReferenceLens& reference,
                                                       const ReferenceAnalyses* analyses,
                                                       double filmDiagonalMm) {
  const optics::FirstOrderData& a = lens.firstOrder();
  const optics::FirstOrderData& b = reference.lens->firstOrder();
  std::vector<FirstOrderComparisonRow> rows;
  // A length of both lenses (none when either is afocal and the figure is infinite).
  auto lengths = [&](const char* name, double ofLens, double ofReference, bool finite = true,
                     const char* format = "%.2f mm", const char* differenceFormat = "%+.2f mm") {
    FirstOrderComparisonRow row{name, "-", "-", ""};
    const bool lensHas = finite && !a.afocal && std::isfinite(ofLens);
    const bool referenceHas = finite && !b.afocal && std::isfinite(ofReference);
    if (lensHas) row.lens = mmText(ofLens, format);
    if (referenceHas) row.reference = mmText(ofReference, format);
    if (lensHas && referenceHas) row.difference = mmText(ofLens - ofReference, differenceFormat);
    rows.push_back(std::move(row));
  };
  lengths("EFL", a.eflMm, b.eflMm, true, "%.3f mm", "%+.3f mm");
  {
    FirstOrderComparisonRow row{"f-number", lensFNumberText.empty() ? "-" : lensFNumberText,
                                analyses ? analyses->figures.fNumberText : "...", ""};
    const auto x = fNumberOf(row.lens), y = fNumberOf(row.reference);
    if (x && y) row.difference = mmText(*x - *y, "%+.2f");
    rows.push_back(std::move(row));
  }
  lengths("BFL", a.bflMm, b.bflMm, true, "%.3f mm", "%+.3f mm");
  lengths("Track", a.totalTrackMm, b.totalTrackMm);
  lengths("FOV", a.fieldOfViewDeg(filmDiagonalMm), b.fieldOfViewDeg(filmDiagonalMm), true,
          "%.1f deg", "%+.1f deg");
  lengths("Entrance pupil", a.entrancePupil.diameterMm, b.entrancePupil.diameterMm,
          !a.entrancePupil.atInfinity && !b.entrancePupil.atInfinity);
  lengths("Exit pupil", a.exitPupil.diameterMm, b.exitPupil.diameterMm,
          !a.exitPupil.atInfinity && !b.exitPupil.atInfinity);
  lengths("Film distance", lens.filmDistanceMm(), reference.lens->filmDistanceMm());
  return rows;
}

std::uint32_t referenceRgba(std::uint32_t rgba) {
  // Rounded to the nearest; no channel of a white series stays above the exports' 0xc0, past
  // which plot_picture draws a colour in ink.
  auto channel = [&](int shift) {
    const std::uint32_t c = (rgba >> shift) & 0xffu, tint = (kReferenceTintRgba >> shift) & 0xffu;
    return ((45u * c + 55u * tint + 50u) / 100u) << shift;
  };
  return channel(24) | channel(16) | channel(8) | 0xffu;
}

namespace {

PlotSeries referenceLegendEntry(const std::string& name) {
  PlotSeries entry{name, {}, {}, kReferenceTintRgba, true};
  entry.guide = true;  // no data: not in the CSV, the readout or the axes' range
  return entry;
}

void growAxis(PlotAxis& axis, const PlotAxis& other) {
  if (axis.min && other.min) axis.min = std::min(*axis.min, *other.min);
  if (axis.max && other.max) axis.max = std::max(*axis.max, *other.max);
}

}  // namespace

void addReference(PlotSpec& spec, const PlotSpec& reference, const std::string& title,
                  const std::string& whyNot) {
  std::size_t added = 0;
  for (const PlotSeries& series : reference.series) {
    if (series.guide || series.kind != PlotSeriesKind::Line) continue;
    bool any = false;
    for (std::size_t i = 0; i < std::min(series.x.size(), series.y.size()) && !any; ++i)
      any = std::isfinite(series.x[i]) && std::isfinite(series.y[i]);
    if (!any) continue;
    PlotSeries copy = series;
    copy.name = "reference: " + series.name;
    copy.rgba = referenceRgba(series.rgba);
    copy.dashed = !series.points;
    copy.inLegend = false;
    // A spot's rays under the lens's (drawn first), whose spot is the one being edited; curves
    // over them.
    if (copy.points)
      spec.series.insert(spec.series.begin(), std::move(copy));
    else
      spec.series.push_back(std::move(copy));
    ++added;
  }
  if (added == 0) {
    addReferenceNote(spec, title, whyNot.empty() ? "nothing to draw" : whyNot);
    return;
  }
  growAxis(spec.x, reference.x);
  growAxis(spec.y, reference.y);
  spec.series.push_back(
      referenceLegendEntry("reference: " + title + (whyNot.empty() ? "" : ": " + whyNot)));
}

void addReferenceNote(PlotSpec& spec, const std::string& title, const std::string& why) {
  spec.series.push_back(referenceLegendEntry("reference: " + title + ": " + why));
}

void addPinnedReference(ViewerState& state, PlotSpec& spec,
                        const std::function<PlotSpec(const ReferenceAnalyses&)>& referencePlot) {
  if (!state.reference) return;
  bool computing = false;
  const auto analyses = referenceAnalyses(state, &computing);
  state.reference->drawn.note(state.frameNumber, analyses != nullptr);
  if (!analyses) {
    addReferenceNote(spec, state.reference->title, "computing...");
    return;
  }
  addReference(spec, referencePlot(*analyses), state.reference->title,
               analyses->noImage.empty() ? "" : "forms no image (" + analyses->noImage + ")");
}

void addPinnedReference(
    ViewerState& state, PlotFigure& figure,
    const std::function<PlotFigure(const ReferenceAnalyses&)>& referenceFigure) {
  if (!state.reference) return;
  const std::string& title = state.reference->title;
  bool computing = false;
  const auto analyses = referenceAnalyses(state, &computing);
  state.reference->drawn.note(state.frameNumber, analyses != nullptr);
  if (!analyses) {
    for (PlotSpec& plot : figure.plots) addReferenceNote(plot, title, "computing...");
    return;
  }
  const PlotFigure reference = referenceFigure(*analyses);
  const std::string whyNot =
      analyses->noImage.empty() ? "" : "forms no image (" + analyses->noImage + ")";
  for (std::size_t i = 0; i < figure.plots.size(); ++i) {
    if (i < reference.plots.size())
      addReference(figure.plots[i], reference.plots[i], title, whyNot);
    else
      addReferenceNote(figure.plots[i], title, whyNot.empty() ? "no such field" : whyNot);
    if (i < figure.captions.size()) {
      // "RMS 12.3 um  GEO 40.1 um  ref: RMS 11.1": the reference's RMS alone, so that the line
      // fits under a plot a third of a slide wide (or why it has no spot).
      std::string theirs = i < reference.captions.size() ? reference.captions[i] : "";
      if (theirs.rfind("RMS ", 0) == 0) theirs = theirs.substr(0, theirs.find(" um"));
      figure.captions[i] += "  ref: " + (theirs.empty() ? std::string("none") : theirs);
    }
  }
  // The panel's note line names the reference, when its plots have no room for a legend.
  figure.note +=
      (figure.note.empty() ? "" : "; ") + std::string("dashed violet: reference ") + title;
}

}  // namespace lenslab::app
