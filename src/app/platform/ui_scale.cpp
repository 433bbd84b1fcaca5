#include "app/platform/ui_scale.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace lenslab::app {

namespace {
// A plain value, not a resource: the window writes it, panels read it, on the UI thread only.
float currentScale = 1.0f;
}  // namespace

float uiScale() { return currentScale; }

void setUiScale(float scale) { currentScale = std::isfinite(scale) && scale > 0.0f ? scale : 1.0f; }

std::optional<float> forcedUiScale() {
  const char* text = std::getenv("LENSLAB_UI_SCALE");
  if (text == nullptr || *text == '\0') return std::nullopt;
  float value = 0;
  const char* end = text + std::strlen(text);
  const auto [stop, error] = std::from_chars(text, end, value);
  if (error != std::errc() || stop != end || !(value >= 0.5f && value <= 4.0f)) return std::nullopt;
  return value;
}

}  // namespace lenslab::app
