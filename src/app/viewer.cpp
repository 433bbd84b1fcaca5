#include "app/viewer.h"

#include <glad/gl.h>
// glad must come before GLFW so GLFW does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/panels/panels.h"
#include "app/screenshot.h"
#include "app/viewer_state.h"
#include "render/image_io.h"

namespace lenslab::app {

namespace {

constexpr const char* kHeadlessHint = "lenslab render SCENE --out image.png";

std::string lastGlfwError;

void recordGlfwError(int /*code*/, const char* description) {
  lastGlfwError = description != nullptr ? description : "unknown GLFW error";
}

// The first TTF font of the list that exists; ImGui's built-in bitmap font otherwise.
void loadFonts(float contentScale) {
  ImGuiIO& io = ImGui::GetIO();
  const float pixels = 15.0f * contentScale;
  for (const char* candidate : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                "/usr/share/fonts/TTF/DejaVuSans.ttf"}) {
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

// ImGui 1.86 indexes keys by the backend's key codes (GLFW's here).
void handleShortcuts(ViewerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) state.windowScreenshotRequested = true;
  if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Q, false)) state.quitRequested = true;
}

void drawFrame(ViewerState& state, float windowWidth, float windowHeight) {
  handleShortcuts(state);
  const float menuHeight = drawMainMenu(state);
  state.settings.layout = clampFractions(state.settings.layout, windowWidth,
                                         std::max(0.0f, windowHeight - menuHeight));
  state.layout = computeLayout(windowWidth, windowHeight, menuHeight, state.settings.layout,
                               state.showLog);
  drawSplitters(state, windowWidth, windowHeight);
  drawLensTablePanel(state, state.layout.lensTable);
  drawCrossSectionPanel(state, state.layout.crossSection);
  drawRenderPreviewPanel(state, state.layout.renderPreview);
  if (state.showLog) drawLogPanel(state, state.layout.log);
  drawAboutWindow(state);
}

void saveWindowScreenshot(ViewerState& state, int framebufferWidth, int framebufferHeight) {
  const std::filesystem::path path =
      render::nonClobberingPath(std::filesystem::current_path(), "lenslab-window", ".png");
  const render::WriteResult result = saveFramebufferPng(path, framebufferWidth, framebufferHeight);
  if (result.ok) {
    state.log.info("Saved window screenshot to " + path.string());
  } else {
    state.log.error(result.error);
  }
}

}  // namespace

bool displayAvailable() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

int runViewer(const ViewerOptions& options) {
  if (!displayAvailable()) {
    std::fprintf(stderr,
                 "lenslab: no display (DISPLAY and WAYLAND_DISPLAY are unset); without one, "
                 "render headless: %s\n",
                 kHeadlessHint);
    return 2;
  }
  glfwSetErrorCallback(recordGlfwError);
  if (!glfwInit()) {
    std::fprintf(stderr, "lenslab: cannot open the display (%s); without one, render headless: %s\n",
                 lastGlfwError.c_str(), kHeadlessHint);
    return 2;
  }

  ViewerState state;
  const bool testMode = options.screenshotPath.has_value();
  // Tests must neither read nor change the user's settings.
  if (!testMode) {
    if (const std::filesystem::path directory = configDirectory(); !directory.empty()) {
      state.settingsFile = directory / "settings.json";
      std::string warning;
      state.settings = loadSettings(state.settingsFile, &warning);
      if (!warning.empty()) state.log.warning(warning);
    }
  }
  const int width = options.width.value_or(state.settings.windowWidth);
  const int height = options.height.value_or(state.settings.windowHeight);

  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // In test mode the framebuffer must be exactly the requested size.
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, testMode ? GLFW_FALSE : GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, "lenslab", nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "lenslab: cannot create a GL 3.3 core window (%s)\n",
                 lastGlfwError.c_str());
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(testMode ? 0 : 1);
  if (gladLoadGL(glfwGetProcAddress) == 0) {
    std::fprintf(stderr, "lenslab: cannot load the OpenGL 3.3 functions\n");
    glfwDestroyWindow(window);
    glfwTerminate();
    return 1;
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout persists in settings.json, in the config directory
  float contentScaleX = 1.0f, contentScaleY = 1.0f;
  glfwGetWindowContentScale(window, &contentScaleX, &contentScaleY);
  const float contentScale = testMode ? 1.0f : std::max(1.0f, contentScaleX);
  applyStyle(contentScale);
  loadFonts(contentScale);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  state.log.info(std::string("lenslab ") + LENSLAB_VERSION + ", OpenGL " +
                 reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  if (!state.settingsFile.empty()) state.log.info("Settings: " + state.settingsFile.string());

  int exitCode = 0;
  for (int frame = 0; !glfwWindowShouldClose(window) && !state.quitRequested; ++frame) {
    // Idle when nothing happens: wake for input, or at least a few times a second.
    if (testMode) {
      glfwPollEvents();
    } else {
      glfwWaitEventsTimeout(0.25);
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    drawFrame(state, static_cast<float>(windowWidth), static_cast<float>(windowHeight));
    ImGui::Render();

    int framebufferWidth = 0, framebufferHeight = 0;
    glfwGetFramebufferSize(window, &framebufferWidth, &framebufferHeight);
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    glClearColor(0.10f, 0.10f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (state.windowScreenshotRequested) {
      state.windowScreenshotRequested = false;
      saveWindowScreenshot(state, framebufferWidth, framebufferHeight);
    }
    if (testMode && frame + 1 >= options.frames) {
      const render::WriteResult result =
          saveFramebufferPng(*options.screenshotPath, framebufferWidth, framebufferHeight);
      if (!result.ok) {
        std::fprintf(stderr, "lenslab: %s\n", result.error.c_str());
        exitCode = 1;
      }
      break;
    }
    glfwSwapBuffers(window);
  }

  if (!testMode && !state.settingsFile.empty()) {
    glfwGetWindowSize(window, &state.settings.windowWidth, &state.settings.windowHeight);
    if (const std::string error = saveSettings(state.settingsFile, state.settings);
        !error.empty()) {
      std::fprintf(stderr, "lenslab: %s\n", error.c_str());
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exitCode;
}

}  // namespace lenslab::app
