#include "app/platform/window.h"

#include <glad/gl.h>
// glad must come before GLFW so GLFW does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <utility>

#include "app/drawing/cross_section_drawing.h"
#include "app/platform/gl_driver_pin.h"
#include "app/platform/partial_repaint.h"
#include "app/platform/ui_scale.h"
#include "app/resources.h"

namespace lenslab::app {

namespace {

// GLFW reports errors through a callback; the last one explains a failed call in one line.
std::string& lastGlfwError() {
  static std::string error;
  return error;
}

void recordGlfwError(int /*code*/, const char* description) {
  lastGlfwError() = description != nullptr ? description : "unknown GLFW error";
}

// The first TTF font of the list that exists; ImGui's built-in bitmap font otherwise.
void loadFonts(float contentScale) {
  ImGuiIO& io = ImGui::GetIO();
  const float pixels = 15.0f * contentScale;
  for (const char* candidate : kUiFontFiles) {
    if (std::filesystem::exists(candidate) &&
        io.Fonts->AddFontFromFileTTF(candidate, pixels) != nullptr) {
      return;
    }
  }
  ImFontConfig config;
  config.SizePixels = 13.0f * contentScale;
  io.Fonts->AddFontDefault(&config);
}

void applyStyle(float contentScale) {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.WindowBorderSize = 1.0f;
  style.FrameRounding = 3.0f;
  style.ScaleAllSizes(contentScale);
}

}  // namespace

bool displayAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

std::unique_ptr<Window> Window::open(const Options& options, std::string* error) {
  glfwSetErrorCallback(recordGlfwError);
  if (!glfwInit()) {
    *error = "cannot open the display (" + lastGlfwError() + ")";
    return nullptr;
  }
  std::unique_ptr<Window> window(new Window);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // In test mode the framebuffer must be exactly the requested size.
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, options.testMode ? GLFW_FALSE : GLFW_TRUE);
  window->window_ = glfwCreateWindow(options.width, options.height, "lenslab", nullptr, nullptr);
  if (window->window_ == nullptr) {
    *error = "cannot create a GL 3.3 core window (" + lastGlfwError() + ")";
    return nullptr;
  }
  glfwSetWindowUserPointer(window->window_, window.get());
  glfwSetDropCallback(window->window_, onDrop);
  // Installed before ImGui's backend, which chains to it.
  glfwSetKeyCallback(window->window_, onKey);
  glfwSetWindowContentScaleCallback(window->window_, onContentScale);
  glfwSetWindowRefreshCallback(window->window_, onRefresh);
  window->installInputCallbacks();
  window->testMode_ = options.testMode;
  glfwMakeContextCurrent(window->window_);
  glfwSwapInterval(options.testMode ? 0 : 1);
  if (gladLoadGL(glfwGetProcAddress) == 0) {
    *error = "cannot load the OpenGL 3.3 functions";
    return nullptr;
  }
  keepGlDriverLoadedUntilExit();  // only in the sanitizer build (gl_driver_pin.cpp says why)

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout persists in settings.json, in the config directory
  float scaleX = 1.0f, scaleY = 1.0f;
  glfwGetWindowContentScale(window->window_, &scaleX, &scaleY);
  const std::optional<float> forced = forcedUiScale();
  window->scaleForced_ = forced.has_value();
  window->contentScale_ = forced ? *forced : options.testMode ? 1.0f : std::max(1.0f, scaleX);
  setUiScale(window->contentScale_);
  applyStyle(window->contentScale_);
  loadFonts(window->contentScale_);
  ImGui_ImplGlfw_InitForOpenGL(window->window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  window->readInitialInputState();
  window->imguiReady_ = true;
  window->partial_ = PartialRepaint::detect(window->window_);
  return window;
}

Window::~Window() {
  if (imguiReady_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  destroyCursors();
  if (window_ != nullptr) glfwDestroyWindow(window_);
  glfwTerminate();
}

void Window::onDrop(GLFWwindow* handle, int count, const char** paths) {
  auto* window = static_cast<Window*>(glfwGetWindowUserPointer(handle));
  window->addDropped(std::vector<std::string>(paths, paths + count));
}

void Window::addDropped(const std::vector<std::string>& paths) {
  dropped_.insert(dropped_.end(), paths.begin(), paths.end());
}

void Window::simulateDrop(const std::vector<std::string>& paths) { addDropped(paths); }

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::onRefresh(GLFWwindow* handle) {
  static_cast<Window*>(glfwGetWindowUserPointer(handle))->refreshRequested_ = true;
}

void Window::onContentScale(GLFWwindow* handle, float scaleX, float /*scaleY*/) {
  auto* window = static_cast<Window*>(glfwGetWindowUserPointer(handle));
  if (!window->testMode_ && !window->scaleForced_) {
    window->pendingContentScale_ = std::max(1.0f, scaleX);
  }
}

void Window::applyContentScale() {
  const float scale = std::exchange(pendingContentScale_, 0.0f);
  if (scale <= 0.0f || scale == contentScale_) return;
  contentScale_ = scale;
  setUiScale(contentScale_);
  applyStyle(contentScale_);
  ImGui::GetIO().Fonts->Clear();
  loadFonts(contentScale_);
  // The GL backend rebuilds its font texture from the new atlas.
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}

void Window::onKey(GLFWwindow* handle, int key, int /*scancode*/, int action, int mods) {
  auto* window = static_cast<Window*>(glfwGetWindowUserPointer(handle));
  if (action == GLFW_PRESS && key >= 0) window->pressedKeys_.push_back({key, mods});
}

// Dear ImGui 1.86 samples key state once per frame, so a key pressed and released between two
// frames (a quick tap, or xdotool's "key Return") is never seen as pressed. Keep such a key down
// for one frame, as ImGui 1.87's input queue would. Likewise the modifiers: xdotool's "key
// ctrl+o" releases Ctrl before O, and when both events land in one frame ImGui would see O
// pressed without Ctrl. A press is seen with the modifiers that were down when it happened.
void Window::holdTappedKeys() {
  ImGuiIO& io = ImGui::GetIO();
  constexpr int kKeyCount = static_cast<int>(IM_ARRAYSIZE(io.KeysDown));
  for (int key : heldKeys_) {
    if (key < kKeyCount && glfwGetKey(window_, key) == GLFW_RELEASE) io.KeysDown[key] = false;
  }
  heldKeys_.clear();
  if (std::exchange(modifiersOverridden_, false)) {
    // Back to the modifiers' real state.
    const auto down = [&](int a, int b) {
      return glfwGetKey(window_, a) == GLFW_PRESS || glfwGetKey(window_, b) == GLFW_PRESS;
    };
    io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
  }
  for (const KeyPress& press : pressedKeys_) {
    if (press.key >= kKeyCount) continue;
    if (!io.KeysDown[press.key]) {
      io.KeysDown[press.key] = true;
      heldKeys_.push_back(press.key);
    }
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    const bool shift = (press.mods & GLFW_MOD_SHIFT) != 0;
    const bool alt = (press.mods & GLFW_MOD_ALT) != 0;
    if ((ctrl && !io.KeyCtrl) || (shift && !io.KeyShift) || (alt && !io.KeyAlt)) {
      io.KeyCtrl |= ctrl;
      io.KeyShift |= shift;
      io.KeyAlt |= alt;
      modifiersOverridden_ = true;
    }
  }
  pressedKeys_.clear();
}

std::vector<std::string> Window::takeDroppedFiles() { return std::exchange(dropped_, {}); }

void Window::wakeFromAnyThread() { glfwPostEmptyEvent(); }

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

void Window::waitEvents(double seconds) const {
  if (seconds <= 0) {
    glfwPollEvents();
  } else {
    glfwWaitEventsTimeout(seconds);
  }
}

void Window::beginFrame() {
  applyContentScale();
  ImGui_ImplOpenGL3_NewFrame();
  newImGuiPlatformFrame();
  holdTappedKeys();
  ImGui::NewFrame();
}

void Window::endFrame() { ImGui::Render(); }

namespace {
// The cross-section's background: its canvas is left to the clear that every repaint does
// anyway, one fill fewer per pixel for a software rasterizer (cross_section_panel.cpp). The same
// colour shows in the gaps between the panels.
constexpr float kClearColor[4] = {palette::kBackground.r / 255.0f, palette::kBackground.g / 255.0f,
                                  palette::kBackground.b / 255.0f, 1.0f};
}  // namespace

void Window::drawFrame() {
  if (partial_) {
    const PixelRect whole{0, 0, framebufferWidth(), framebufferHeight()};
    partial_->paint({&whole, 1}, whole.x1, whole.y1, kClearColor);
    return;
  }
  glViewport(0, 0, framebufferWidth(), framebufferHeight());
  glClearColor(kClearColor[0], kClearColor[1], kClearColor[2], kClearColor[3]);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::drawRegions(std::span<const PixelRect> regions) {
  if (!partial_) return drawFrame();
  partial_->paint(regions, framebufferWidth(), framebufferHeight(), kClearColor);
}

void Window::swapBuffers() {
  if (partial_) return partial_->present(framebufferHeight());
  glfwSwapBuffers(window_);
}

// As the size callbacks last reported them: asking the X server is a round trip each time.
int Window::width() const { return windowWidth_; }
int Window::height() const { return windowHeight_; }
int Window::framebufferWidth() const { return framebufferWidth_; }
int Window::framebufferHeight() const { return framebufferHeight_; }

double Window::refreshRateHz() const {
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor != nullptr ? glfwGetVideoMode(monitor) : nullptr;
  return mode != nullptr && mode->refreshRate >= 30 ? mode->refreshRate : 60.0;
}

std::string Window::glVersion() const {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return version != nullptr ? version : "unknown";
}

}  // namespace lenslab::app
