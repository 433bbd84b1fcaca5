#include "app/platform/window_pixels.h"

#include <GLFW/glfw3.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <dlfcn.h>

#include <bit>
#include <cstring>

namespace lenslab::app {

namespace {

// GLFW's native-access functions, looked up at run time (see partial_repaint.cpp).
template <typename Function>
Function glfwNative(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

std::uint8_t channel(unsigned long pixel, unsigned long mask) {
  if (mask == 0) return 0;
  const int shift = std::countr_zero(mask);
  const unsigned long value = (pixel & mask) >> shift;
  const unsigned long maximum = mask >> shift;
  return static_cast<std::uint8_t>(value * 255 / maximum);
}

}  // namespace

std::optional<FramebufferImage> readWindowFromDisplay(GLFWwindow* window, std::string* error) {
  const auto getDisplay = glfwNative<Display* (*)()>("glfwGetX11Display");
  const auto getWindow = glfwNative<::Window (*)(GLFWwindow*)>("glfwGetX11Window");
  Display* display = getDisplay != nullptr ? getDisplay() : nullptr;
  const ::Window handle = getWindow != nullptr ? getWindow(window) : 0;
  if (display == nullptr || handle == 0) {
    *error = "the window is not an X11 window";
    return std::nullopt;
  }
  XSync(display, False);  // the copies to the window are done before it is read
  XWindowAttributes attributes;
  if (XGetWindowAttributes(display, handle, &attributes) == 0) {
    *error = "cannot read the window's attributes from the X server";
    return std::nullopt;
  }
  XImage* image = XGetImage(display, handle, 0, 0, static_cast<unsigned>(attributes.width),
                            static_cast<unsigned>(attributes.height), AllPlanes, ZPixmap);
  if (image == nullptr) {
    *error = "the X server did not return the window's pixels";
    return std::nullopt;
  }
  FramebufferImage out;
  out.width = attributes.width;
  out.height = attributes.height;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const unsigned long pixel = XGetPixel(image, x, y);
      std::uint8_t* rgba = &out.rgba[4 * (static_cast<std::size_t>(y) * out.width + x)];
      rgba[0] = channel(pixel, image->red_mask);
      rgba[1] = channel(pixel, image->green_mask);
      rgba[2] = channel(pixel, image->blue_mask);
      rgba[3] = 255;
    }
  }
  XDestroyImage(image);
  return out;
}

std::string describeDifference(const FramebufferImage& shown, const FramebufferImage& drawn) {
  if (shown.width != drawn.width || shown.height != drawn.height) {
    return "the window is " + std::to_string(shown.width) + "x" + std::to_string(shown.height) +
           " pixels, the drawn frame " + std::to_string(drawn.width) + "x" +
           std::to_string(drawn.height);
  }
  long long differing = 0;
  int firstX = -1, firstY = -1;
  for (std::size_t i = 0; i + 3 < shown.rgba.size(); i += 4) {
    if (std::memcmp(&shown.rgba[i], &drawn.rgba[i], 3) != 0 && differing++ == 0) {
      firstX = static_cast<int>(i / 4) % shown.width;
      firstY = static_cast<int>(i / 4) / shown.width;
    }
  }
  if (differing == 0) return "";
  return std::to_string(differing) +
         " pixels of the window differ from the drawn frame, the first at (" +
         std::to_string(firstX) + ", " + std::to_string(firstY) + ")";
}

}  // namespace lenslab::app
