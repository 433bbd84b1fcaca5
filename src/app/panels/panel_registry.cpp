#include "app/panels/panel_registry.h"

#include "app/panels/panels.h"

namespace lenslab::app {

namespace {

// One line per panel. The first panel of an area is its default tab.
constexpr PanelSpec kPanels[] = {
    {"lens", "Lens", DockArea::Left, drawLensTablePanel},
    {"cross-section", "Cross-section", DockArea::Centre, drawCrossSectionPanel},
    {"preview", "Render preview", DockArea::Right, drawRenderPreviewPanel},
    {"log", "Log", DockArea::Bottom, drawLogPanel},
    {"lens-file", "Lens file", DockArea::Bottom, drawLensFilePanel},
    {"illumination", "Illumination", DockArea::Bottom, drawIlluminationPanel, true},
    {"seidel", "Seidel", DockArea::Bottom, drawSeidelPanel, true},
    {"colour", "Colour", DockArea::Bottom, drawColourPanel, true},
    {"ray-fan", "Ray fan", DockArea::Bottom, drawRayFanPanel, true},
    {"spot", "Spot", DockArea::Bottom, drawSpotPanel, true},
    {"distortion", "Distortion", DockArea::Bottom, drawDistortionPanel, true},
    {"field-curves", "Field curves", DockArea::Bottom, drawFieldCurvesPanel, true},
    {"mtf", "MTF", DockArea::Bottom, drawMtfPanel, true},
    // The library browser: at the plots' height, for two rows of cards.
    {"library", "Library", DockArea::Bottom, drawLibraryPanel, true},
};

}  // namespace

const char* dockAreaName(DockArea area) {
  switch (area) {
    case DockArea::Left:
      return "left";
    case DockArea::Centre:
      return "centre";
    case DockArea::Right:
      return "right";
    case DockArea::Bottom:
      return "bottom";
  }
  return "?";
}

std::span<const PanelSpec> registeredPanels() { return kPanels; }

std::vector<const PanelSpec*> panelsIn(DockArea area) {
  std::vector<const PanelSpec*> panels;
  for (const PanelSpec& panel : kPanels) {
    if (panel.area == area) panels.push_back(&panel);
  }
  return panels;
}

const PanelSpec* findPanel(std::string_view id) {
  for (const PanelSpec& panel : kPanels) {
    if (panel.id == id) return &panel;
  }
  return nullptr;
}

}  // namespace lenslab::app
