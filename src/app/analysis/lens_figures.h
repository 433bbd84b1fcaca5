#pragma once
// The first-order section's figures that take real-ray searches, in the words `lenslab info`
// uses: the object distance in focus (focus.h), the aperture that limits the axial beam with its
// working f-number (limiting_aperture.h) and the unvignetted field (unvignetted_field.h), with
// the paraxial chromatic focal shift (analysis/chromatic.h, microseconds) beside them. Each
// takes a few milliseconds per lens, so they are computed off the UI thread (a LatestJob) and
// the section shows the newest finished ones.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "app/analysis/latest_job.h"
#include "optics/lens_system.h"

namespace lenslab::app {

struct LensFigures {
  std::shared_ptr<const optics::LensSystem> lens;  // the lens they describe
  std::string inFocusText;                         // "3.600 m from the film", "nothing (why)"
  std::optional<double> inFocusMm;                 // the object distance in focus, from the film
  // The paraxial back focus at F minus at C from infinity ("-0.1619 mm, blue nearer the
  // lens"), or why there is none (no glass with V_d).
  std::string colourFocusText;
  // The beam figures; absent when they were not asked for (while a value is dragged).
  bool hasBeamFigures = false;
  std::string fNumberText;      // "f/2.07": EFL over the paraxial beam that passes every rim
  std::string axialBeamText;    // "surface 3, before the iris: working f/2.03"
  std::string unvignettedText;  // "1.1 deg from infinity"
  // With a stop other than the circle: "f/2.21 (a 514.3 mm2 beam from infinity)", the f-number of
  // the circle that admits as much light (optics/axial_beam_area.h); empty for the circle.
  std::string areaFNumberText;
};

// "F-C" of the first-order data: the paraxial focus at F minus at C, object at infinity.
std::string colourFocusText(const optics::LensSystem& lens);

// "f/2.48": the paraxial f-number of the beam that passes every rim from infinity, as the
// first-order section, dump-ui's `f_number` and the exports' titles write it.
std::string fNumberText(const optics::LensSystem& lens);

// Pure: the figures of `lens` (the beam ones too when withBeamFigures).
LensFigures computeLensFigures(std::shared_ptr<const optics::LensSystem> lens,
                               bool withBeamFigures);

struct LensFiguresView {
  std::shared_ptr<const optics::LensSystem> requestedLens;
  bool requestedBeamFigures = false;
  std::uint64_t requests = 0;
  std::unique_ptr<LatestJob<LensFigures>> job;
  // The lens whose finished figures were last copied into the state.
  std::shared_ptr<const optics::LensSystem> shownLens;
};

// Asks for the figures of `lens` when they have not been asked for yet; while `dragging`, only
// the in-focus distance (the beam figures catch up when the drag ends).
void requestLensFigures(LensFiguresView& view,
                        const std::shared_ptr<const optics::LensSystem>& lens, bool dragging);

// The newest finished figures (null before the first).
std::shared_ptr<const LensFigures> latestLensFigures(const LensFiguresView& view);

// The figures of `lens`, beam figures included, have finished.
bool lensFiguresCurrent(const LensFiguresView& view,
                        const std::shared_ptr<const optics::LensSystem>& lens);

}  // namespace lenslab::app
