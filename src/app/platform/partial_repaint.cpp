#include "app/platform/partial_repaint.h"

#include <glad/gl.h>
// glad must come before GLFW so GLFW does not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <dlfcn.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace lenslab::app {

namespace {

bool softwareRasterizer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer == nullptr) return false;
  const std::string name(renderer);
  for (const char* software : {"llvmpipe", "softpipe", "swrast"}) {
    if (name.find(software) != std::string::npos) return true;
  }
  return false;
}

// GLFW's native-access functions, looked up at run time: their declarations need the X11
// headers, and a GLFW built for Wayland has none of them (then there is no partial repaint).
template <typename Function>
Function glfwNative(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

std::vector<std::uint8_t> readBackBuffer(int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return rgba;
}

}  // namespace

std::unique_ptr<PartialRepaint> PartialRepaint::detect(GLFWwindow* window) {
  if (const char* full = std::getenv("LENSLAB_FULL_REDRAW"); full && std::strcmp(full, "1") == 0) {
    return nullptr;
  }
  if (!softwareRasterizer() || !glfwExtensionSupported("GLX_MESA_copy_sub_buffer")) return nullptr;
  const auto copy =
      reinterpret_cast<CopySubBufferFunction>(glfwGetProcAddress("glXCopySubBufferMESA"));
  const auto getDisplay = glfwNative<void* (*)()>("glfwGetX11Display");
  const auto getGlxWindow = glfwNative<unsigned long (*)(GLFWwindow*)>("glfwGetGLXWindow");
  if (copy == nullptr || getDisplay == nullptr || getGlxWindow == nullptr) return nullptr;
  std::unique_ptr<PartialRepaint> partial(new PartialRepaint);
  partial->copySubBuffer_ = copy;
  partial->display_ = getDisplay();
  partial->drawable_ = getGlxWindow(window);
  if (partial->display_ == nullptr || partial->drawable_ == 0) return nullptr;
  if (const char* check = std::getenv("LENSLAB_CHECK_REPAINT")) {
    if (std::strcmp(check, "1") == 0) partial->checkMode_ = CheckMode::Check;
    if (std::strcmp(check, "shrink") == 0) partial->checkMode_ = CheckMode::Shrink;
  }
  return partial;
}

void PartialRepaint::paintRegion(const PixelRect& region, int framebufferHeight,
                                 const float clearColor[4]) {
  ImDrawData* data = ImGui::GetDrawData();
  glEnable(GL_SCISSOR_TEST);
  glScissor(region.x0, framebufferHeight - region.y1, region.x1 - region.x0, region.y1 - region.y0);
  glClearColor(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  if (data == nullptr) return;
  // Every command clipped to the region: its new clip rect makes the backend compute exactly the
  // intersection of its old scissor box and the region (whole pixels, scale 1; see paint()).
  std::vector<ImVec4> saved;
  const ImVec2 offset = data->DisplayPos;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    for (ImDrawCmd& command : data->CmdLists[n]->CmdBuffer) {
      saved.push_back(command.ClipRect);
      const PixelRect clipped = intersect(scissorOf(command, *data, framebufferHeight), region);
      command.ClipRect = clipped.empty() ? ImVec4(0, 0, 0, 0)  // the backend skips it
                                         : ImVec4(clipped.x0 + offset.x, clipped.y0 + offset.y,
                                                  clipped.x1 + offset.x, clipped.y1 + offset.y);
    }
  }
  ImGui_ImplOpenGL3_RenderDrawData(data);
  std::size_t next = 0;
  for (int n = 0; n < data->CmdListsCount; ++n) {
    for (ImDrawCmd& command : data->CmdLists[n]->CmdBuffer) command.ClipRect = saved[next++];
  }
}

void PartialRepaint::paint(std::span<const PixelRect> regions, int framebufferWidth,
                           int framebufferHeight, const float clearColor[4]) {
  const PixelRect whole{0, 0, framebufferWidth, framebufferHeight};
  std::vector<PixelRect> wanted(regions.begin(), regions.end());
  const ImDrawData* data = ImGui::GetDrawData();
  const bool wholePixels = data != nullptr && data->FramebufferScale.x == 1.0f &&
                           data->FramebufferScale.y == 1.0f &&
                           data->DisplayPos.x == std::floor(data->DisplayPos.x) &&
                           data->DisplayPos.y == std::floor(data->DisplayPos.y);
  if (!wholePixels) wanted = {whole};
  glViewport(0, 0, framebufferWidth, framebufferHeight);
  for (PixelRect region : wanted) {
    region = intersect(region, whole);
    if (region.empty()) continue;
    if (checkMode_ == CheckMode::Shrink) region.x1 = region.x0 + (region.x1 - region.x0 + 1) / 2;
    paintRegion(region, framebufferHeight, clearColor);
    painted_.push_back(region);
    ++regionsPainted_;
    pixelsPainted_ += region.area();
  }
  if (checkMode_ != CheckMode::Off && !wanted.empty()) {
    check(wanted, framebufferWidth, framebufferHeight, clearColor);
  }
}

void PartialRepaint::check(std::span<const PixelRect> regions, int framebufferWidth,
                           int framebufferHeight, const float clearColor[4]) {
  const std::vector<std::uint8_t> partial = readBackBuffer(framebufferWidth, framebufferHeight);
  paintRegion({0, 0, framebufferWidth, framebufferHeight}, framebufferHeight, clearColor);
  const std::vector<std::uint8_t> full = readBackBuffer(framebufferWidth, framebufferHeight);
  long long differing = 0;
  int firstX = -1, firstY = -1;
  for (std::size_t i = 0; i + 3 < full.size(); i += 4) {
    if (std::memcmp(&partial[i], &full[i], 3) != 0) {
      if (differing++ == 0) {
        const auto pixel = static_cast<int>(i / 4);
        firstX = pixel % framebufferWidth;
        firstY = framebufferHeight - 1 - pixel / framebufferWidth;  // rows run bottom to top
      }
    }
  }
  if (differing == 0) return;
  ++checkFailures_;
  std::string where;
  for (const PixelRect& r : regions) {
    where += " [" + std::to_string(r.x0) + "," + std::to_string(r.y0) + ")-[" +
             std::to_string(r.x1) + "," + std::to_string(r.y1) + ")";
  }
  std::fprintf(stderr,
               "lenslab: repaint check: %lld pixels differ from a full repaint, the first at "
               "(%d, %d); repainted:%s\n",
               differing, firstX, firstY, where.c_str());
}

void PartialRepaint::present(int framebufferHeight) {
  for (const PixelRect& r : painted_) {
    copySubBuffer_(display_, drawable_, r.x0, framebufferHeight - r.y1, r.x1 - r.x0, r.y1 - r.y0);
  }
  painted_.clear();
}

}  // namespace lenslab::app
