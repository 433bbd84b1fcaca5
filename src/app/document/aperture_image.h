#pragma once
// An image aperture for the stop, loaded for an edit (the lens panel's Load button, the script's
// "set aperture image FILE"): the file read and thresholded now, so that the SetStopShape command
// carries the mask and the undo history keeps it.

#include <optional>
#include <string>

#include "optics/aperture_shape.h"

namespace lenslab::app {

// The image shape for `path`, or nullopt with the reason in `error` (missing, unreadable, not
// square, all black): the caller logs it and the stop keeps its shape.
std::optional<optics::ApertureShape> loadImageAperture(const std::string& path, std::string* error);

}  // namespace lenslab::app
