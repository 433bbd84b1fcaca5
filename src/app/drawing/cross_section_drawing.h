#pragma once
// What the cross-section shows, as plain primitives in lens millimetres: the panel maps them to
// pixels with ImGui, and the SVG export writes the same primitives, so the slide and the screen
// never disagree. No ImGui here, so it is unit-tested.

#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "optics/film_point_bundle.h"
#include "optics/lens_outline.h"
#include "optics/ray_fan.h"

namespace lenslab::app {

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

// What a line shows, so an export can recolour it for its theme and group it by part.
enum class DrawingPart { GlassEdge, Stop, Axis, Film, Ray, ChiefRay, MarginalRay };

// Points are (z, y) in the lens frame: z along the axis (film at 0, object side positive).
struct Polyline {
  std::vector<optics::OutlinePoint> points;
  Colour colour;
  float widthPx = 1.0f;
  bool closed = false;
  bool dashed = false;
  DrawingPart part = DrawingPart::GlassEdge;
  int fanIndex = -1;  // a fan's ray: which fan (its field), for the colour
  // A colour fan's ray (FanSettings::colourFans): the Fraunhofer line it was traced at, which
  // gives its colour instead of the field; 0 for the field-coloured rays.
  double wavelengthNm = 0;
  bool blocked = false;  // a ray that does not reach the film
  // A film point's bundle's ray (drawFilmPointBundle): coloured by what becomes of it, not by a
  // field: the passing colour, or its stopping surface's (stopSurface, 0-based) when blocked.
  bool bundleRay = false;
  int stopSurface = -1;
};

struct FilledQuads {
  std::vector<optics::OutlinePoint> corners;  // four per quad
  Colour colour;
};

struct BoundsMm {
  double minZ = 0, maxZ = 0, minY = 0, maxY = 0;
  bool hasPoints = false;
  void include(const optics::OutlinePoint& point);
};

struct CrossSectionDrawing {
  std::vector<FilledQuads> fills;  // drawn first
  std::vector<Polyline> lines;     // then outlines, stop, axis, film and rays
  BoundsMm bounds;                 // of the lens, the stop and the film
};

namespace palette {
// The canvas's background, and the window's clear colour (window.cpp).
inline constexpr Colour kBackground{18, 20, 26, 255};
inline constexpr Colour kGlassFill{92, 140, 200, 90};
inline constexpr Colour kGlassEdge{170, 200, 240, 255};
inline constexpr Colour kStop{235, 200, 80, 255};
inline constexpr Colour kAxis{110, 110, 120, 255};
inline constexpr Colour kFilm{240, 240, 240, 255};
// One colour per field position: on axis, 0.7 field, full field (and more if asked).
inline constexpr Colour kFieldColours[] = {
    {80, 220, 120, 255}, {250, 180, 60, 255}, {235, 90, 200, 255}, {90, 170, 255, 255}};
inline constexpr Colour kChiefRay{255, 255, 255, 255};
// A film point's bundle: the rays that reach it, and those stopped, in the colour of the surface
// that stops them (cycled by surface number). Twelve, so that no two surfaces of a lens of up to
// twelve (every stock lens but the 13-surface wide angle) share one: with eight, the double
// Gauss's surfaces 1 and 9 were both red in one legend.
inline constexpr Colour kBundlePassing{120, 235, 140, 255};
inline constexpr Colour kStoppingSurfaceColours[] = {
    {255, 110, 90, 255},  {255, 190, 60, 255},  {200, 120, 255, 255}, {80, 180, 255, 255},
    {255, 120, 200, 255}, {170, 220, 60, 255},  {255, 150, 120, 255}, {120, 140, 255, 255},
    {60, 215, 190, 255},  {235, 235, 100, 255}, {205, 155, 105, 255}, {200, 200, 215, 255}};
inline Colour stoppingSurfaceColour(int surface) {
  constexpr int kCount = static_cast<int>(std::size(kStoppingSurfaceColours));
  return kStoppingSurfaceColours[((surface % kCount) + kCount) % kCount];
}
inline constexpr Colour kMarginalRay{90, 230, 240, 255};
// Colour fans: each Fraunhofer line in a colour near its own (F 486 nm blue, d 588 nm yellow,
// C 656 nm red), bright enough on the dark canvas.
inline constexpr Colour kLineF{90, 150, 255, 255};
inline constexpr Colour kLineD{245, 215, 60, 255};
inline constexpr Colour kLineC{255, 75, 65, 255};
}  // namespace palette

// The colour of a colour fan's ray at `wavelengthNm`: the nearest of F, d and C.
Colour fraunhoferLineColour(double wavelengthNm);

// filmHalfDiagonalMm: half the film diagonal, drawn as the film plane's extent.
CrossSectionDrawing drawLens(const optics::LensOutline& outline, double filmHalfDiagonalMm);

// What the cross-section fits its view to: the drawing's lens and film (drawLens, before rays are
// added), with room in front for the incoming bundles (where the fans start, at least a quarter
// of the lens length in front of it, at most half), but not the rays themselves: a near object
// would shrink the lens to a dot.
BoundsMm crossSectionFitBounds(const CrossSectionDrawing& lensDrawing,
                               const optics::LensOutline& outline, const optics::RayFans& fans);

// Adds the fans' rays: each ends at the film, or at the surface that blocked it (blocked rays are
// fainter, and left out when showBlocked is false). Chief rays dashed, the marginal ray cyan.
// Fans traced at other wavelengths too (RayFan::atOtherWavelengths) are drawn by wavelength: every
// ray, the lens's own d line's included, in its Fraunhofer line's colour: d first, then the
// others from red to blue.
void drawRayFans(CrossSectionDrawing& drawing, const optics::RayFans& fans, bool showBlocked);

// Adds a film point's bundle (optics/film_point_bundle.h) in place of the fans: rays that reach
// the point in kBundlePassing, stopped rays up to their rim in that surface's colour, the chief
// ray dashed.
void drawFilmPointBundle(CrossSectionDrawing& drawing, const optics::FilmPointBundle& bundle);

// What a film point's bundle legend says, in the panel and on the slide: "reaches it 64%" in the
// passing colour (surface -1), then each surface that stops a share, largest first ("surface 3:
// 20%", with " (front)", " (rear)" or " (stop)" where it is one of those), in its colour; or
// "no ray from it reaches the stop" (surface -2) for an empty bundle.
struct BundleLegendEntry {
  int surface = -1;  // -1: the passing share; -2: nothing passes the stop; else 0-based
  std::string text;
};
std::vector<BundleLegendEntry> bundleLegend(const optics::FilmPointBundle& bundle,
                                            std::size_t surfaceCount, std::size_t stopIndex);

}  // namespace lenslab::app
