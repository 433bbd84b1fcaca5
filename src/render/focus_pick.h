#pragma once
// "Click to focus": how far the scene point under a pixel is from the film.

#include <memory>
#include <optional>

#include "optics/lens_system.h"
#include "render/scene.h"
#include "render/scene_description.h"

namespace lenslab::render {

// Casts rays through the pixel (raster coordinates of a width x height image)
// with the camera makeLensCamera builds for `lens`, trying the middle of the
// pupil first, and returns the axial distance from the film to the first
// surface hit, in millimetres; nullopt when nothing is hit (sky) or no ray
// passes.
std::optional<double> objectDistanceUnderPixelMm(const SceneDescription& description,
                                                 const Scene& scene,
                                                 std::shared_ptr<const optics::LensSystem> lens,
                                                 int width, int height, double x, double y);

}  // namespace lenslab::render
