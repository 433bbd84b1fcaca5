#pragma once
// What the display server shows of the window, read back from it (X11 only). With partial
// repaints (partial_repaint.h) the window is built up from copied regions; comparing it with the
// back buffer, which holds the whole drawn frame, checks that every change reached the screen.

#include <optional>
#include <string>

#include "app/platform/screenshot.h"

struct GLFWwindow;

namespace lenslab::app {

// The window's pixels from the X server, or nullopt with `error` set (no X11 window: Wayland).
std::optional<FramebufferImage> readWindowFromDisplay(GLFWwindow* window, std::string* error);

// "" when the images are equal in RGB; else how many pixels differ and where the first is.
std::string describeDifference(const FramebufferImage& shown, const FramebufferImage& drawn);

}  // namespace lenslab::app
