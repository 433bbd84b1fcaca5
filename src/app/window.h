#pragma once
// The GLFW window with its GL 3.3 core context and Dear ImGui, created and torn down together.

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace lenslab::app {

class Window {
 public:
  struct Options {
    int width = 1600, height = 900;
    bool testMode = false;  // exact framebuffer size, no vsync, scale 1
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
  void beginFrame();
  // Renders ImGui's draw data into the back buffer.
  void renderFrame();
  void swapBuffers();

  int width() const;  // screen coordinates
  int height() const;
  int framebufferWidth() const;
  int framebufferHeight() const;
  float contentScale() const { return contentScale_; }
  std::string glVersion() const;

  // Files dropped onto the window since the last call.
  std::vector<std::string> takeDroppedFiles();

 private:
  Window() = default;
  static void onDrop(GLFWwindow* window, int count, const char** paths);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onContentScale(GLFWwindow* window, float scaleX, float scaleY);
  // Rebuilds fonts and style sizes after the window moved to a monitor with another scale.
  void applyContentScale();
  void holdTappedKeys();

  GLFWwindow* window_ = nullptr;
  bool imguiReady_ = false;
  float contentScale_ = 1.0f;
  float pendingContentScale_ = 0.0f;  // set by the callback, applied before the next frame
  bool testMode_ = false;
  std::vector<std::string> dropped_;
  // Keys pressed since the last frame, and keys held down artificially for one frame (see
  // holdTappedKeys).
  struct KeyPress {
    int key;
    int mods;
  };
  std::vector<KeyPress> pressedKeys_;
  std::vector<int> heldKeys_;
};

// True when a display server is named in the environment (DISPLAY or WAYLAND_DISPLAY).
bool displayAvailable();

}  // namespace lenslab::app
