#pragma once
// File > Export cross-section... and the script's export-cross-section: the cross-section as the
// panel traces it (the lens, its ray fans, the film), laid out for a slide (slide_layout.h) and
// written as a PNG of a chosen size and DPI or as an SVG, off screen: the window's size plays no
// part.

#include <filesystem>
#include <string>
#include <variant>

#include "app/drawing/slide_layout.h"

namespace lenslab::app {

struct ViewerState;

struct CrossSectionExportSettings {
  SlideOptions slide;  // size in pixels, theme, labels
  // 144 DPI: a 1920-pixel-wide picture fills a 13.33-inch (16:9) slide when inserted.
  double dotsPerInch = 144.0;
  bool svg = false;  // the dialog's format; a path's extension decides
};

inline constexpr int kMinExportSidePx = 16, kMaxExportSidePx = 10000;
inline constexpr double kMaxExportPixels = 50e6;

// Why these settings cannot be exported, or "".
std::string checkExportSettings(const CrossSectionExportSettings& settings);

// The caption of the current lens: its name (lens_caption.h: the file's first header comment
// without its nominal f-number, else the file name), the file name, the f-number as the
// first-order section writes it and the focal length, the object distance, and the fans' field
// angles (or object heights for a near object); with a film point chosen, the point and its
// bundle's shares instead of the fields.
SlideCaption crossSectionCaption(ViewerState& state);

// A field's legend text: "0°" on axis, else the angle with one decimal ("14.2°").
std::string fieldAngleText(double degrees);

// Everything an export needs, copied from the viewer's state, so that it runs on a thread of its
// own while the viewer goes on (a 4K picture takes half a second to draw and deflate).
struct CrossSectionExportJob {
  std::filesystem::path path;
  CrossSectionExportSettings settings;
  CrossSectionDrawing drawing;
  optics::LensOutline outline;
  BoundsMm fit;
  SlideCaption caption;
};

struct CrossSectionExportResult {
  std::string error;    // "" when written; else naming the path
  std::string summary;  // what was written: "PNG, 1600×900 px, 300 DPI, light theme"
};

// The job for the current lens and fans, or why it cannot be exported (the extension is not
// .png or .svg, the settings are out of range, the lens is invalid).
std::variant<CrossSectionExportJob, std::string> prepareCrossSectionExport(
    ViewerState& state, const std::filesystem::path& path,
    const CrossSectionExportSettings& settings);

// Lays the picture out and writes it (PNG or SVG, from the extension) atomically. Touches no
// viewer state: safe on any thread.
CrossSectionExportResult runCrossSectionExport(const CrossSectionExportJob& job);

}  // namespace lenslab::app
