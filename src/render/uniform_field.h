#pragma once
// Whether a scene is a flat field, like the vignetting demo (scenes/vignetting.pbrt): every ray
// the camera sends out meets the same radiance, so the brightness of its render across the film
// is the lens's relative illumination and nothing else. The viewer then overlays the fall-off
// measured from the preview on the Illumination plot.

#include "render/scene.h"
#include "render/scene_description.h"

namespace lenslab::render {

// True when the scene is nothing but emitters of one radiance that reflect nothing (area lights
// on black matte surfaces; no other lights, no instances) and they fill the view: rays from the
// camera's position within 75 degrees of its axis all meet the emitting side of one of them.
// Structural, not a guess from the file's name: vignetting-chart.pbrt (the same field behind a
// grid of lines) is not one, and neither is a copy of the demo with a sphere added.
bool isUniformField(const SceneDescription& description, const Scene& scene);

}  // namespace lenslab::render
