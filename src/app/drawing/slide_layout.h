#pragma once
// The cross-section laid out as a picture for a slide, in the picture's pixels: the lens drawing
// (recoloured for a light or dark theme) fitted between a title at the top and a legend and scale
// bar at the bottom, with the surfaces numbered as in the lens table and the stop and film
// labelled. The PNG rasteriser (slide_raster.h) and the SVG writer (slide_svg.h) both draw this
// one picture, so the two files show the same thing. Plain data and arithmetic: no ImGui, so it
// is unit-tested.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/drawing/canvas_clip.h"
#include "app/drawing/cross_section_drawing.h"
#include "optics/lens_outline.h"

namespace lenslab::app {

enum class SlideTheme { Light, Dark };

// The colours of a theme. Light: for slides (white background, dark outlines, light-blue glass,
// ray colours dark enough to read on white); dark: the panel's colours.
struct SlidePalette {
  Colour background, glassFill, glassEdge, stop, axis, film, chiefRay, marginalRay;
  Colour text, mutedText;
  std::vector<Colour> fans;                      // one per field position, as the panel's
  Colour lineF, lineD, lineC;                    // colour fans' rays (FanSettings::colourFans)
  Colour lineColour(double wavelengthNm) const;  // the nearest of the three
  // A film point's bundle: the rays that reach it, and those stopped, in their surface's colour
  // (cycled by surface number, as palette::stoppingSurfaceColour).
  Colour bundlePassing;
  std::vector<Colour> stoppingSurfaces;
  Colour stoppingSurfaceColour(int surface) const;
};
SlidePalette slidePalette(SlideTheme theme);

struct SlideOptions {
  int widthPx = 1920, heightPx = 1080;
  SlideTheme theme = SlideTheme::Light;
  bool title = true;           // the lens name, f-number, focal length and object distance
  bool surfaceNumbers = true;  // 1..N as in the lens table
  bool stopAndFilm = true;     // "Stop" and "Film" labels
  bool scaleBar = true;        // a millimetre scale bar
  bool legend = true;          // the fans' fields with their angles, or the bundle's shares
};

// A field in the legend: its text ("14.2°", or "12 mm" for a finite object) in its fan's colour.
struct SlideLegendField {
  int fanIndex = 0;
  std::string text;
};

// What the picture says besides the drawing.
// A colour fan's line in the legend: "F 486 nm" in its colour.
struct SlideLegendLine {
  double wavelengthNm = 0;
  std::string text;
};

// A film point's bundle drawn instead of the fans: its legend names the point and gives the
// shares, each in the colour its rays are drawn in (bundleLegend, as the panel's).
struct SlideBundleLegend {
  std::string heading;  // "Film point 12.0 mm:"
  std::vector<BundleLegendEntry> entries;
};

struct SlideCaption {
  std::string title;     // the lens's name
  std::string subtitle;  // "f/2.48 · EFL 50.36 mm · object at infinity"
  std::vector<SlideLegendField> fields;
  // With colour fans: their lines, and the fields then listed without colours (the rays are
  // coloured by wavelength, not by field).
  std::vector<SlideLegendLine> lines;
  // Set when the drawing is a film point's bundle: the legend is its shares, not the fields.
  std::optional<SlideBundleLegend> bundle;
};

// Text widths in pixels for a font size in pixels (ImGui's convention: the size is the height
// from the font's ascender to its descender). The rasteriser's font measures them; tests pass an
// approximation.
struct SlideTextMetrics {
  std::function<double(const std::string& text, double sizePx)> widthPx;
  double ascentPerSize = 0.8;  // baseline below the line's top, as a fraction of the size
  double emPerSize = 0.86;     // the CSS font-size (one em) of a size, for SVG
};

struct SlideLine {
  std::vector<CanvasPoint> points;  // picture pixels, y down
  Colour colour;
  double widthPx = 1;
  bool closed = false;
  bool dashed = false;
  double dashPx = 8, gapPx = 5;
  std::string group;  // "glass", "stop", "axis", "film", "rays", "scale-bar", "legend"
};

struct SlideFill {
  std::vector<CanvasPoint> polygon;  // convex
  Colour colour;
  std::string group;
};

struct SlideText {
  std::string text;
  double leftPx = 0, topPx = 0;  // the line's box: baseline at topPx + ascent
  double widthPx = 0, sizePx = 0;
  Colour colour;
  // "title", "subtitle", "surface-number", "stop-label", "film-label", "scale-bar-label",
  // "legend-field" (a field's angle), "legend-share" (a bundle's share), "legend"
  std::string kind;
  double right() const { return leftPx + widthPx; }
  double bottom() const { return topPx + sizePx; }
};

struct SlidePicture {
  int widthPx = 0, heightPx = 0;
  Colour background;
  std::vector<SlideFill> fills;  // drawn first
  std::vector<SlideLine> lines;
  std::vector<SlideText> texts;  // drawn last
  SlideTextMetrics metrics;
  // The drawing's scale and where the lens frame's origin (film on the axis) lies.
  double pixelsPerMm = 1;
  CanvasPoint originPx;
  CanvasRect drawingArea;  // the lens and its rays are clipped to it
  double scaleBarMm = 0;   // 0: no scale bar
};

// The largest of 1, 2 or 5 x 10^k mm that is at most `maxMm` (for a scale bar).
double roundScaleBarLengthMm(double maxMm);

// "10 mm", "0.5 mm", "200 mm": a round length as its label reads.
std::string scaleBarLabel(double lengthMm);

// Lays out the drawing of `lens` (with the fans drawn into `drawing`) to fill the picture. `fit`
// is the lens-frame rectangle to show (the panel's fit bounds: the lens, the film and room for
// the incoming rays).
SlidePicture layoutSlide(const CrossSectionDrawing& drawing, const optics::LensOutline& outline,
                         const BoundsMm& fit, const SlideCaption& caption,
                         const SlideOptions& options, const SlideTextMetrics& metrics);

}  // namespace lenslab::app
