// ImGui's per-frame platform input, kept from GLFW's callbacks so that a frame asks the window
// system nothing (window.h says why). The GLFW backend of ImGui 1.86 still handles keys,
// characters, the wheel and focus events through its own callbacks, which chain to these.

// glad before GLFW, as in every file of the viewer: a unity build that puts a file including
// glad after this one would otherwise see GL's own header first and stop.
#include <glad/gl.h>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cfloat>

#include "app/platform/window.h"

namespace lenslab::app {

namespace {

Window& windowOf(GLFWwindow* handle) {
  return *static_cast<Window*>(glfwGetWindowUserPointer(handle));
}

}  // namespace

void Window::installInputCallbacks() {
  glfwSetWindowSizeCallback(window_, onWindowSize);
  glfwSetFramebufferSizeCallback(window_, onFramebufferSize);
  glfwSetCursorPosCallback(window_, onCursorPos);
  glfwSetCursorEnterCallback(window_, onCursorEnter);
  glfwSetWindowFocusCallback(window_, onFocus);
  glfwSetMouseButtonCallback(window_, onMouseButton);
}

void Window::readInitialInputState() {
  // Asked once; the callbacks keep them from here on.
  glfwGetWindowSize(window_, &windowWidth_, &windowHeight_);
  glfwGetFramebufferSize(window_, &framebufferWidth_, &framebufferHeight_);
  glfwGetCursorPos(window_, &cursorX_, &cursorY_);
  focused_ = glfwGetWindowAttrib(window_, GLFW_FOCUSED) != 0;
  cursorInside_ = glfwGetWindowAttrib(window_, GLFW_HOVERED) != 0;
  // The shapes GLFW 3.3 has; the others show the arrow, as ImGui's backend does.
  cursors_.assign(ImGuiMouseCursor_COUNT, nullptr);
  const auto standard = [&](ImGuiMouseCursor cursor, int shape) {
    cursors_[static_cast<std::size_t>(cursor)] = glfwCreateStandardCursor(shape);
  };
  standard(ImGuiMouseCursor_Arrow, GLFW_ARROW_CURSOR);
  standard(ImGuiMouseCursor_TextInput, GLFW_IBEAM_CURSOR);
  standard(ImGuiMouseCursor_ResizeNS, GLFW_VRESIZE_CURSOR);
  standard(ImGuiMouseCursor_ResizeEW, GLFW_HRESIZE_CURSOR);
  standard(ImGuiMouseCursor_Hand, GLFW_HAND_CURSOR);
}

void Window::destroyCursors() {
  for (GLFWcursor* cursor : cursors_) {
    if (cursor != nullptr) glfwDestroyCursor(cursor);
  }
  cursors_.clear();
}

void Window::onWindowSize(GLFWwindow* handle, int width, int height) {
  Window& window = windowOf(handle);
  window.windowWidth_ = width;
  window.windowHeight_ = height;
}

void Window::onFramebufferSize(GLFWwindow* handle, int width, int height) {
  Window& window = windowOf(handle);
  window.framebufferWidth_ = width;
  window.framebufferHeight_ = height;
}

void Window::onCursorPos(GLFWwindow* handle, double x, double y) {
  Window& window = windowOf(handle);
  window.cursorX_ = x;
  window.cursorY_ = y;
}

void Window::onCursorEnter(GLFWwindow* handle, int entered) {
  windowOf(handle).cursorInside_ = entered != 0;
}

void Window::onFocus(GLFWwindow* handle, int focused) { windowOf(handle).focused_ = focused != 0; }

void Window::onMouseButton(GLFWwindow* handle, int button, int action, int /*mods*/) {
  Window& window = windowOf(handle);
  if (action == GLFW_PRESS && button >= 0 &&
      button < static_cast<int>(window.mouseJustPressed_.size())) {
    window.mouseJustPressed_[static_cast<std::size_t>(button)] = true;
  }
}

void Window::newImGuiPlatformFrame() {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(windowWidth_), static_cast<float>(windowHeight_));
  if (windowWidth_ > 0 && windowHeight_ > 0) {
    io.DisplayFramebufferScale =
        ImVec2(static_cast<float>(framebufferWidth_) / static_cast<float>(windowWidth_),
               static_cast<float>(framebufferHeight_) / static_cast<float>(windowHeight_));
  }
  const double now = glfwGetTime();
  io.DeltaTime = lastFrameSeconds_ > 0.0 && now > lastFrameSeconds_
                     ? static_cast<float>(now - lastFrameSeconds_)
                     : 1.0f / 60.0f;
  lastFrameSeconds_ = now;

  // GLFW keeps the buttons' state from the events it has read: no request to the server.
  static_assert(IM_ARRAYSIZE(io.MouseDown) >= 5);
  for (std::size_t button = 0; button < mouseJustPressed_.size(); ++button) {
    io.MouseDown[button] =
        mouseJustPressed_[button] || glfwGetMouseButton(window_, static_cast<int>(button)) != 0;
    mouseJustPressed_[button] = false;
  }
  // As ImGui's backend: the pointer counts while over the window, or anywhere while the window
  // has the focus (a drag that leaves it keeps going).
  io.MousePos = cursorInside_ || focused_
                    ? ImVec2(static_cast<float>(cursorX_), static_cast<float>(cursorY_))
                    : ImVec2(-FLT_MAX, -FLT_MAX);

  // The pointer's shape, told to the server only when it changes.
  const ImGuiMouseCursor wanted =
      io.MouseDrawCursor ? ImGuiMouseCursor_None : ImGui::GetMouseCursor();
  if (wanted != shownCursor_ && !(io.ConfigFlags & ImGuiConfigFlags_NoMouseCursorChange)) {
    shownCursor_ = wanted;
    if (wanted == ImGuiMouseCursor_None) {
      glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);
    } else {
      const std::size_t index = static_cast<std::size_t>(wanted);
      GLFWcursor* shape = index < cursors_.size() && cursors_[index] != nullptr
                              ? cursors_[index]
                              : cursors_[ImGuiMouseCursor_Arrow];
      glfwSetCursor(window_, shape);
      glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
    }
  }
}

}  // namespace lenslab::app
