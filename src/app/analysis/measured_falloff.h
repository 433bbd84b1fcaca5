#pragma once
// The fall-off measured from the render preview (issue 21): on a flat-field scene
// (render/uniform_field.h) the radial average of the picture's luminance over rings, relative to
// the centre, is the relative illumination the renderer integrated; the Illumination plot draws
// it over the computed `total` so that the plot and the picture can be seen to agree. Computed on
// a LatestJob from the newest full preview pass, never on the UI thread.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "app/analysis/latest_job.h"
#include "optics/lens_system.h"
#include "render/progressive_renderer.h"

namespace lenslab::app {

struct MeasuredFalloff {
  std::shared_ptr<const optics::LensSystem> lens;  // the lens the picture was rendered through
  int samplesPerPixel = 0;
  std::vector<double> imageHeightMm;  // each ring's mean film radius, from the centre out
  std::vector<double> relative;       // each ring's mean luminance over the centre's
};

// Rings `ringWidthMm` wide on the film (whose diagonal is the picture's), from the centre to the
// corner; the centre is the mean of the pixels within 1 mm of it. Rings with fewer than 8 pixels
// are left out. nullopt for an empty picture or a black centre.
std::optional<MeasuredFalloff> measureFalloff(const render::RenderSnapshot& picture,
                                              double filmDiagonalMm, double ringWidthMm = 0.5);

struct MeasuredFalloffView {
  std::uint64_t requestedGeneration = 0;  // the preview pass last asked about
  int requestedSpp = -1;
  std::unique_ptr<LatestJob<std::optional<MeasuredFalloff>>> job;
};

// Asks for the measurement of `picture` (a full pass, not the coarse look) rendered through
// `lens`, unless it was the last asked for.
// The newest measurement, or null (none yet, or the picture had no light in its centre).
const MeasuredFalloff* latestMeasuredFalloff(const MeasuredFalloffView& view,
                                             std::shared_ptr<const void>& keepAlive);

void requestMeasuredFalloff(MeasuredFalloffView& view,
                            std::shared_ptr<const render::RenderSnapshot> picture,
                            std::shared_ptr<const optics::LensSystem> lens, double filmDiagonalMm);

}  // namespace lenslab::app
