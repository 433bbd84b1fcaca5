#pragma once
// The GLFW window with its GL 3.3 core context and Dear ImGui, created and torn down together.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "app/platform/pixel_rect.h"

struct GLFWwindow;
struct GLFWcursor;

namespace lenslab::app {

class PartialRepaint;

class Window {
 public:
  struct Options {
    int width = 1600, height = 900;
    bool testMode = false;  // exact framebuffer size, no vsync, scale 1 (unless LENSLAB_UI_SCALE)
  };

  // Returns the window, or nullopt with `error` set to a one-line explanation.
  static std::unique_ptr<Window> open(const Options& options, std::string* error);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool shouldClose() const;
  // Waits for input at most `seconds` (0: just polls).
  void waitEvents(double seconds) const;
  // Ends a waitEvents() early; safe to call from any thread (glfwPostEmptyEvent).
  static void wakeFromAnyThread();
  void beginFrame();
  // Ends the ImGui frame: its draw data is ready (nothing is drawn yet).
  void endFrame();
  // Draws the ended frame into the back buffer (GL: a software rasterizer spends tens of
  // milliseconds of CPU here on a large window).
  void drawFrame();
  // With a software rasterizer (partial_repaint.h) repaints only `regions`, which must hold
  // every pixel that differs from the last drawn frame (FrameDamage); otherwise drawFrame().
  void drawRegions(std::span<const PixelRect> regions);
  bool repaintsRegionsOnly() const { return partial_ != nullptr; }
  // Partial repaint figures; null without partial repaints.
  const PartialRepaint* partialRepaint() const { return partial_.get(); }
  // Shows what was drawn: swaps the buffers, or copies the repainted regions to the window.
  void swapBuffers();
  // The window system asked for a redraw (exposed, resized) since the last call.
  bool takeRefreshRequest() { return std::exchange(refreshRequested_, false); }

  int width() const;  // screen coordinates
  int height() const;
  int framebufferWidth() const;
  int framebufferHeight() const;
  float contentScale() const { return contentScale_; }
  void setTitle(const std::string& title);
  // Hands paths to the viewer exactly as a drop onto the window does (scripts, tests).
  void simulateDrop(const std::vector<std::string>& paths);
  std::string glVersion() const;
  // The monitor's refresh rate, 60 when it does not say.
  double refreshRateHz() const;

  // Files dropped onto the window since the last call.
  std::vector<std::string> takeDroppedFiles();

 private:
  Window() = default;
  static void onDrop(GLFWwindow* window, int count, const char** paths);
  void addDropped(const std::vector<std::string>& paths);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onContentScale(GLFWwindow* window, float scaleX, float scaleY);
  static void onRefresh(GLFWwindow* window);
  // Rebuilds fonts and style sizes after the window moved to a monitor with another scale.
  void applyContentScale();
  void holdTappedKeys();

  // ImGui's platform input for a frame (window and framebuffer size, time step, mouse, cursor
  // shape) from what GLFW's callbacks reported, in place of ImGui_ImplGlfw_NewFrame: on X11 that
  // asks the server four questions a frame and waits for each answer (window size, framebuffer
  // size, focus, pointer), which cost the UI thread 0.5-0.8 ms of CPU in one frame in a hundred
  // and up to 28 ms now and then on a loaded machine (issue 21's 4 ms budget). window_input.cpp.
  void installInputCallbacks();  // before ImGui's backend installs its own, which chain to these
  void readInitialInputState();
  void newImGuiPlatformFrame();
  void destroyCursors();
  static void onWindowSize(GLFWwindow* window, int width, int height);
  static void onFramebufferSize(GLFWwindow* window, int width, int height);
  static void onCursorPos(GLFWwindow* window, double x, double y);
  static void onCursorEnter(GLFWwindow* window, int entered);
  static void onFocus(GLFWwindow* window, int focused);
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);

  GLFWwindow* window_ = nullptr;
  std::unique_ptr<PartialRepaint> partial_;
  bool imguiReady_ = false;
  float contentScale_ = 1.0f;
  float pendingContentScale_ = 0.0f;  // set by the callback, applied before the next frame
  bool testMode_ = false;
  bool refreshRequested_ = true;
  bool scaleForced_ = false;  // LENSLAB_UI_SCALE set: the monitor's scale is not followed
  std::vector<std::string> dropped_;
  // Keys pressed since the last frame, and keys held down artificially for one frame (see
  // holdTappedKeys).
  struct KeyPress {
    int key;
    int mods;
  };
  std::vector<KeyPress> pressedKeys_;
  std::vector<int> heldKeys_;
  bool modifiersOverridden_ = false;  // a press's modifiers stand in for released ones

  // What the callbacks last reported (screen coordinates; the framebuffer's in pixels).
  int windowWidth_ = 0, windowHeight_ = 0;
  int framebufferWidth_ = 0, framebufferHeight_ = 0;
  double cursorX_ = 0, cursorY_ = 0;
  bool cursorInside_ = false, focused_ = false;
  // A press since the last frame shows as held in the next even if released already, so that a
  // click shorter than a frame is not lost.
  std::array<bool, 5> mouseJustPressed_{};
  double lastFrameSeconds_ = 0;
  int shownCursor_ = -2;              // the ImGuiMouseCursor last shown; -2 none yet
  std::vector<GLFWcursor*> cursors_;  // by ImGuiMouseCursor
};

// True when a display server is named in the environment (DISPLAY or WAYLAND_DISPLAY).
bool displayAvailable();

}  // namespace lenslab::app
