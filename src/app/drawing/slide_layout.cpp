#include "app/drawing/slide_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace lenslab::app {

SlidePalette slidePalette(SlideTheme theme) {
  SlidePalette colours;
  if (theme == SlideTheme::Dark) {
    colours = {palette::kBackground,
               palette::kGlassFill,
               palette::kGlassEdge,
               palette::kStop,
               palette::kAxis,
               palette::kFilm,
               palette::kChiefRay,
               palette::kMarginalRay,
               {232, 232, 238, 255},
               {150, 150, 162, 255},
               {},
               palette::kLineF,
               palette::kLineD,
               palette::kLineC,
               palette::kBundlePassing,
               {}};
    colours.fans.assign(std::begin(palette::kFieldColours), std::end(palette::kFieldColours));
    colours.stoppingSurfaces.assign(std::begin(palette::kStoppingSurfaceColours),
                                    std::end(palette::kStoppingSurfaceColours));
    return colours;
  }
  // On white, the panel's bright ray colours wash out: the same hues, darker (each at least
  // 3:1 against white), the glass an opaque light blue that rays stay visible on.
  colours = {{255, 255, 255, 255},
             {196, 222, 246, 255},
             {28, 48, 84, 255},
             {20, 20, 20, 255},
             {125, 125, 135, 255},
             {0, 0, 0, 255},
             {45, 45, 50, 255},
             {0, 125, 145, 255},
             {20, 20, 26, 255},
             {85, 85, 96, 255},
             {},
             // F, d and C darkened for white, as the fields' colours.
             {20, 80, 215, 255},
             {170, 130, 0, 255},
             {205, 30, 30, 255},
             // The bundle's passing rays as the axis's field.
             {0, 135, 60, 255},
             {}};
  colours.fans = {{0, 135, 60, 255}, {205, 100, 0, 255}, {180, 30, 140, 255}, {30, 85, 200, 255}};
  // The stopping rims' colours in the same order as the panel's, each hue darkened for white.
  colours.stoppingSurfaces = {{210, 55, 35, 255},  {185, 120, 0, 255},  {135, 55, 210, 255},
                              {0, 115, 195, 255},  {200, 40, 140, 255}, {95, 140, 0, 255},
                              {165, 75, 45, 255},  {60, 75, 205, 255},  {0, 140, 125, 255},
                              {125, 125, 15, 255}, {20, 40, 110, 255},  {90, 100, 125, 255}};
  return colours;
}

Colour SlidePalette::stoppingSurfaceColour(int surface) const {
  if (stoppingSurfaces.empty()) return text;
  const int count = static_cast<int>(stoppingSurfaces.size());
  return stoppingSurfaces[static_cast<std::size_t>(((surface % count) + count) % count)];
}

Colour SlidePalette::lineColour(double wavelengthNm) const {
  const Colour nearest = fraunhoferLineColour(wavelengthNm);
  if (nearest.r == palette::kLineF.r && nearest.g == palette::kLineF.g) return lineF;
  if (nearest.r == palette::kLineD.r && nearest.g == palette::kLineD.g) return lineD;
  return lineC;
}

double roundScaleBarLengthMm(double maxMm) {
  if (!(maxMm > 0) || !std::isfinite(maxMm)) return 0;
  const double decade = std::pow(10.0, std::floor(std::log10(maxMm)));
  for (double step : {5.0, 2.0, 1.0}) {
    // A relative tolerance: 10 must not fall to 5 because log10 rounded 10 to 9.999...
    if (step * decade <= maxMm * (1 + 1e-9)) return step * decade;
  }
  return decade;
}

std::string scaleBarLabel(double lengthMm) {
  char text[32];
  std::snprintf(text, sizeof text, "%g mm", lengthMm);
  return text;
}

namespace {

const char* groupOf(DrawingPart part) {
  switch (part) {
    case DrawingPart::GlassEdge:
      return "glass";
    case DrawingPart::Stop:
      return "stop";
    case DrawingPart::Axis:
      return "axis";
    case DrawingPart::Film:
      return "film";
    case DrawingPart::Ray:
    case DrawingPart::ChiefRay:
    case DrawingPart::MarginalRay:
      return "rays";
  }
  return "";
}

Colour withAlpha(Colour colour, std::uint8_t alpha) {
  colour.a = alpha;
  return colour;
}

Colour colourOf(const Polyline& line, const SlidePalette& colours) {
  switch (line.part) {
    case DrawingPart::GlassEdge:
      return colours.glassEdge;
    case DrawingPart::Stop:
      return colours.stop;
    case DrawingPart::Axis:
      return colours.axis;
    case DrawingPart::Film:
      return colours.film;
    case DrawingPart::Ray:
      if (line.bundleRay) {
        return line.stopSurface >= 0 ? colours.stoppingSurfaceColour(line.stopSurface)
                                     : colours.bundlePassing;
      }
      // Blocked rays keep the panel's fainter alpha.
      if (line.wavelengthNm > 0)
        return withAlpha(colours.lineColour(line.wavelengthNm), line.colour.a);
      return withAlpha(
          colours.fans[static_cast<std::size_t>(std::max(0, line.fanIndex)) % colours.fans.size()],
          line.colour.a);
    case DrawingPart::ChiefRay:
      return colours.chiefRay;
    case DrawingPart::MarginalRay:
      return colours.marginalRay;
  }
  return line.colour;
}

bool overlaps(const SlideText& a, const SlideText& b, double padPx) {
  return a.leftPx < b.right() + padPx && b.leftPx < a.right() + padPx &&
         a.topPx < b.bottom() + padPx && b.topPx < a.bottom() + padPx;
}

// Where each surface's number goes: above its upper edge (the element's rim where the glass
// continues beyond the clear aperture as a flat annulus; the stop's bar for the stop).
std::vector<optics::OutlinePoint> surfaceTops(const optics::LensOutline& outline) {
  std::vector<optics::OutlinePoint> tops(outline.surfaceProfiles.size());
  for (std::size_t i = 0; i < outline.surfaceProfiles.size(); ++i) {
    const auto& profile = outline.surfaceProfiles[i];
    for (const auto& point : profile) {
      if (point.yMm >= tops[i].yMm) tops[i] = point;
    }
    if (profile.empty() && i < outline.vertexZMm.size()) tops[i].zMm = outline.vertexZMm[i];
  }
  const auto raise = [&](std::size_t surface, const std::vector<optics::OutlinePoint>& edge) {
    if (surface < tops.size() && !edge.empty() && edge.back().yMm > tops[surface].yMm) {
      tops[surface] = edge.back();
    }
  };
  for (const optics::ElementOutline& element : outline.elements) {
    raise(element.frontSurface, element.front);
    raise(element.frontSurface + 1, element.rear);
  }
  if (outline.stop && outline.stop->surface < tops.size()) {
    tops[outline.stop->surface] = {outline.stop->zMm, outline.stop->outerRadiusMm};
  }
  return tops;
}

struct Sizes {
  double textPx, titlePx, marginPx, lineScale, gapPx;
};

Sizes sizesFor(const SlideOptions& options) {
  const double width = options.widthPx, height = options.heightPx;
  Sizes sizes;
  // About 28 px at 1080 lines: readable from the back of a room, small beside the lens.
  sizes.textPx = std::max(10.0, std::round(std::min(height, 0.75 * width) * 0.026));
  sizes.titlePx = std::round(sizes.textPx * 1.3);
  sizes.marginPx = std::round(std::max(6.0, 0.035 * std::min(width, height)));
  sizes.lineScale = std::max(1.0, std::min(width, height) / 700.0);
  sizes.gapPx = std::round(0.3 * sizes.textPx);
  return sizes;
}

}  // namespace

SlidePicture layoutSlide(const CrossSectionDrawing& drawing, const optics::LensOutline& outline,
                         const BoundsMm& fit, const SlideCaption& caption,
                         const SlideOptions& options, const SlideTextMetrics& metrics) {
  const SlidePalette colours = slidePalette(options.theme);
  const Sizes sizes = sizesFor(options);
  const double width = options.widthPx, height = options.heightPx;
  SlidePicture picture;
  picture.widthPx = options.widthPx;
  picture.heightPx = options.heightPx;
  picture.background = colours.background;
  picture.metrics = metrics;
  const auto text = [&](std::string words, double sizePx, Colour colour, std::string kind) {
    SlideText item;
    item.widthPx = metrics.widthPx(words, sizePx);
    item.text = std::move(words);
    item.sizePx = sizePx;
    item.colour = colour;
    item.kind = std::move(kind);
    return item;
  };
  const double usableWidth = std::max(1.0, width - 2 * sizes.marginPx);
  // A line of text as wide as the picture allows: too long a title gets a smaller size.
  const auto fitted = [&](std::string words, double sizePx, Colour colour, std::string kind) {
    SlideText item = text(words, sizePx, colour, kind);
    if (item.widthPx > usableWidth)
      item = text(words, sizePx * usableWidth / item.widthPx, colour, kind);
    return item;
  };

  // The title band.
  double top = sizes.marginPx;
  if (options.title) {
    for (const auto& [words, sizePx, kind] :
         {std::tuple{caption.title, sizes.titlePx, "title"},
          std::tuple{caption.subtitle, sizes.textPx, "subtitle"}}) {
      if (words.empty()) continue;
      SlideText line = fitted(
          words, sizePx, kind == std::string("title") ? colours.text : colours.mutedText, kind);
      line.leftPx = sizes.marginPx;
      line.topPx = top;
      top += line.sizePx * 1.25;
      picture.texts.push_back(std::move(line));
    }
    top += sizes.gapPx;
  }

  // The bottom band: the legend flows from the left, the scale bar sits at the right.
  const double bottom = height - sizes.marginPx;
  const double scaleBarRoom = options.scaleBar ? 0.25 * usableWidth : 0.0;
  const double legendWidth = std::max(1.0, usableWidth - scaleBarRoom - 2 * sizes.textPx);
  const double rowPx = std::round(sizes.textPx * 1.3);
  struct LegendItem {
    SlideText label;
    bool hasSwatch = false, dashed = false;
    Colour swatch;
  };
  std::vector<LegendItem> legend;
  if (options.legend && caption.bundle) {
    // A film point's bundle: its shares in the colours its rays are drawn in.
    legend.push_back({text(caption.bundle->heading, sizes.textPx, colours.mutedText, "legend"),
                      false,
                      false,
                      {}});
    for (const BundleLegendEntry& entry : caption.bundle->entries) {
      if (entry.surface == -2) {
        legend.push_back(
            {text(entry.text, sizes.textPx, colours.mutedText, "legend-share"), false, false, {}});
        continue;
      }
      const Colour colour = entry.surface == -1 ? colours.bundlePassing
                                                : colours.stoppingSurfaceColour(entry.surface);
      legend.push_back(
          {text(entry.text, sizes.textPx, colour, "legend-share"), true, false, colour});
    }
    legend.push_back(
        {text("chief ray", sizes.textPx, colours.text, "legend"), true, true, colours.chiefRay});
  } else if (options.legend && !caption.fields.empty()) {
    legend.push_back(
        {text("Fields:", sizes.textPx, colours.mutedText, "legend"), false, false, {}});
    for (const SlideLegendField& field : caption.fields) {
      if (!caption.lines.empty()) {
        // Rays coloured by wavelength: the fields are named without a swatch.
        legend.push_back(
            {text(field.text, sizes.textPx, colours.text, "legend-field"), false, false, {}});
        continue;
      }
      const Colour colour =
          colours.fans[static_cast<std::size_t>(std::max(0, field.fanIndex)) % colours.fans.size()];
      legend.push_back(
          {text(field.text, sizes.textPx, colour, "legend-field"), true, false, colour});
    }
    for (const SlideLegendLine& line : caption.lines) {
      const Colour colour = colours.lineColour(line.wavelengthNm);
      legend.push_back({text(line.text, sizes.textPx, colour, "legend-line"), true, false, colour});
    }
    legend.push_back(
        {text("chief ray", sizes.textPx, colours.text, "legend"), true, true, colours.chiefRay});
    legend.push_back({text("marginal ray", sizes.textPx, colours.text, "legend"), true, false,
                      colours.marginalRay});
  }
  const double swatchPx = std::round(1.6 * sizes.textPx), swatchGapPx = sizes.gapPx;
  const double itemGapPx = std::round(0.9 * sizes.textPx);
  // Rows of legend items, each item's left edge.
  std::vector<std::vector<std::pair<std::size_t, double>>> legendRows;
  {
    double x = 0;
    for (std::size_t i = 0; i < legend.size(); ++i) {
      const double itemWidth =
          (legend[i].hasSwatch ? swatchPx + swatchGapPx : 0.0) + legend[i].label.widthPx;
      if (legendRows.empty() || (x > 0 && x + itemWidth > legendWidth)) {
        legendRows.emplace_back();
        x = 0;
      }
      legendRows.back().push_back({i, x});
      x += itemWidth + itemGapPx;
    }
  }
  const double scaleBarBlockPx = options.scaleBar ? rowPx + 0.4 * sizes.textPx : 0.0;
  const double bandPx = std::max(static_cast<double>(legendRows.size()) * rowPx, scaleBarBlockPx);
  const double bandTop = bottom - bandPx;

  // The drawing area, and room in it above the lens for the surface numbers and below for the
  // stop's and the film's labels.
  CanvasRect area{sizes.marginPx, top, width - sizes.marginPx,
                  std::max(top + 1.0, bandTop - (bandPx > 0 ? sizes.gapPx : 0.0))};
  picture.drawingArea = area;
  const double fitWidthMm = std::max(1e-3, fit.maxZ - fit.minZ);
  const double fitHeightMm = std::max(1e-3, fit.maxY - fit.minY);
  const double labelRowPx = std::round(sizes.textPx * 1.15);
  double reserveTop = options.surfaceNumbers ? labelRowPx + sizes.gapPx : 0.0;
  double reserveBottom = options.stopAndFilm ? labelRowPx + sizes.gapPx : 0.0;
  const std::vector<optics::OutlinePoint> tops = surfaceTops(outline);
  std::vector<SlideText> labels;
  double pixelsPerMm = 1;
  CanvasPoint origin;
  const auto toPixels = [&](const optics::OutlinePoint& point) {
    return CanvasPoint{origin.x - point.zMm * pixelsPerMm, origin.y - point.yMm * pixelsPerMm};
  };
  // Labels that would leave the area widen its reserve and the drawing is fitted again (the
  // labels then move with the smaller drawing, so a few rounds settle it).
  for (int round = 0; round < 4; ++round) {
    const double availableHeight = std::max(1.0, area.y1 - area.y0 - reserveTop - reserveBottom);
    const double availableWidth = std::max(1.0, area.x1 - area.x0);
    pixelsPerMm = std::min(availableWidth / fitWidthMm, availableHeight / fitHeightMm);
    const double centreX = 0.5 * (area.x0 + area.x1);
    const double centreY = area.y0 + reserveTop + 0.5 * availableHeight;
    origin = {centreX + 0.5 * (fit.minZ + fit.maxZ) * pixelsPerMm,
              centreY + 0.5 * (fit.minY + fit.maxY) * pixelsPerMm};
    labels.clear();
    const double padPx = 0.2 * sizes.textPx;
    // What labels must not cover: every line of the drawing (outlines, stop, film, rays).
    std::vector<CanvasSegment> obstacles;
    for (const Polyline& line : drawing.lines) {
      for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
        const CanvasSegment segment{toPixels(line.points[i]), toPixels(line.points[i + 1])};
        if (const auto shown = clipSegment(segment, area)) obstacles.push_back(*shown);
      }
    }
    const auto coversLabel = [&](const SlideText& candidate) {
      return std::any_of(labels.begin(), labels.end(),
                         [&](const SlideText& other) { return overlaps(candidate, other, padPx); });
    };
    const auto coversLine = [&](const SlideText& candidate) {
      const CanvasRect box =
          CanvasRect{candidate.leftPx, candidate.topPx, candidate.right(), candidate.bottom()}
              .expanded(0.5 * padPx);
      return std::any_of(obstacles.begin(), obstacles.end(),
                         [&](const CanvasSegment& segment) { return clipSegment(segment, box); });
    };
    const auto inside = [&](const SlideText& candidate) {
      return candidate.topPx >= area.y0 && candidate.bottom() <= area.y1;
    };
    // A label goes next to one of its anchors (a point of the drawing, the label above or below
    // it), a row further away at each try, where it covers neither another label nor a line; a
    // label that would cover its left neighbour may first move right a little (the two surfaces
    // of a thin element). Failing that, the first place that covers no other label.
    struct Anchor {
      CanvasPoint at;
      bool above;
    };
    const auto place = [&](SlideText label, const std::vector<Anchor>& anchors) {
      std::vector<SlideText> candidates;
      for (int row = 0; row < 4; ++row) {
        for (const Anchor& anchor : anchors) {
          SlideText candidate = label;
          candidate.leftPx = std::clamp(anchor.at.x - 0.5 * label.widthPx, 0.5 * sizes.marginPx,
                                        width - 0.5 * sizes.marginPx - label.widthPx);
          candidate.topPx = anchor.above
                                ? anchor.at.y - sizes.gapPx - sizes.textPx - row * labelRowPx
                                : anchor.at.y + sizes.gapPx + row * labelRowPx;
          candidates.push_back(candidate);
          SlideText nudged = candidate;
          for (const SlideText& other : labels) {
            if (overlaps(nudged, other, padPx)) nudged.leftPx = other.right() + padPx + 0.5;
          }
          if (nudged.leftPx - candidate.leftPx <= 0.6 * sizes.textPx &&
              nudged.right() <= width - 0.5 * sizes.marginPx) {
            candidates.push_back(nudged);
          }
        }
      }
      for (const SlideText& candidate : candidates) {
        if (inside(candidate) && !coversLabel(candidate) && !coversLine(candidate)) {
          labels.push_back(candidate);
          return;
        }
      }
      for (const SlideText& candidate : candidates) {
        if (!coversLabel(candidate)) {
          labels.push_back(candidate);
          return;
        }
      }
      labels.push_back(candidates.front());
    };
    if (options.surfaceNumbers) {
      for (std::size_t i = 0; i < tops.size(); ++i) {
        place(text(std::to_string(i + 1), sizes.textPx, colours.text, "surface-number"),
              {{toPixels(tops[i]), true}, {toPixels({tops[i].zMm, -tops[i].yMm}), false}});
      }
    }
    if (options.stopAndFilm) {
      if (outline.stop) {
        const optics::StopOutline& stop = *outline.stop;
        place(text("Stop", sizes.textPx, colours.text, "stop-label"),
              {{toPixels({stop.zMm, -stop.outerRadiusMm}), false},
               {toPixels({stop.zMm, stop.outerRadiusMm}), true}});
      }
      // The film's ends: the drawing's film line (half its diagonal either side of the axis).
      double filmHalfMm = 0;
      for (const Polyline& line : drawing.lines) {
        if (line.part != DrawingPart::Film) continue;
        for (const auto& point : line.points)
          filmHalfMm = std::max(filmHalfMm, std::abs(point.yMm));
      }
      place(text("Film", sizes.textPx, colours.text, "film-label"),
            {{toPixels({0.0, -filmHalfMm}), false}, {toPixels({0.0, filmHalfMm}), true}});
    }
    double overTop = 0, overBottom = 0;
    for (const SlideText& label : labels) {
      overTop = std::max(overTop, area.y0 - label.topPx);
      overBottom = std::max(overBottom, label.bottom() - area.y1);
    }
    if (overTop <= 0.5 && overBottom <= 0.5) break;
    reserveTop += std::max(0.0, overTop);
    reserveBottom += std::max(0.0, overBottom);
  }
  picture.pixelsPerMm = pixelsPerMm;
  picture.originPx = origin;

  // The drawing, clipped to its area.
  for (const FilledQuads& fill : drawing.fills) {
    Colour colour = colours.glassFill;
    for (std::size_t i = 0; i + 3 < fill.corners.size(); i += 4) {
      std::vector<CanvasPoint> corners;
      for (std::size_t k = 0; k < 4; ++k) corners.push_back(toPixels(fill.corners[i + k]));
      std::vector<CanvasPoint> shown = clipPolygon(corners, area);
      if (shown.size() >= 3) picture.fills.push_back({std::move(shown), colour, "glass"});
    }
  }
  for (const Polyline& line : drawing.lines) {
    std::vector<CanvasPoint> points;
    for (const auto& point : line.points) points.push_back(toPixels(point));
    if (line.closed && !points.empty()) points.push_back(points.front());
    for (std::vector<CanvasPoint>& run : clipPolyline(points, area)) {
      SlideLine shown;
      shown.points = std::move(run);
      shown.colour = colourOf(line, colours);
      shown.widthPx = line.widthPx * sizes.lineScale;
      shown.dashed = line.dashed;
      shown.dashPx = 8 * sizes.lineScale;
      shown.gapPx = 5 * sizes.lineScale;
      shown.group = groupOf(line.part);
      picture.lines.push_back(std::move(shown));
    }
  }
  for (SlideText& label : labels) picture.texts.push_back(std::move(label));

  // The legend, each row centred on its line.
  for (std::size_t row = 0; row < legendRows.size(); ++row) {
    const double rowTop = bandTop + static_cast<double>(row) * rowPx + 0.5 * (rowPx - sizes.textPx);
    const double middle = rowTop + 0.55 * sizes.textPx;
    for (const auto& [index, x] : legendRows[row]) {
      LegendItem& item = legend[index];
      double left = sizes.marginPx + x;
      if (item.hasSwatch) {
        SlideLine swatch;
        swatch.points = {{left, middle}, {left + swatchPx, middle}};
        swatch.colour = item.swatch;
        swatch.widthPx = 2.5 * sizes.lineScale;
        swatch.dashed = item.dashed;
        swatch.dashPx = 0.4 * swatchPx;
        swatch.gapPx = 0.2 * swatchPx;
        swatch.group = "legend";
        picture.lines.push_back(std::move(swatch));
        left += swatchPx + swatchGapPx;
      }
      item.label.leftPx = left;
      item.label.topPx = rowTop;
      picture.texts.push_back(std::move(item.label));
    }
  }

  // The scale bar: a round length no longer than a fifth of the drawing's width, its label
  // centred above it.
  if (options.scaleBar) {
    const double lengthMm = roundScaleBarLengthMm(0.2 * (area.x1 - area.x0) / pixelsPerMm);
    if (lengthMm > 0) {
      picture.scaleBarMm = lengthMm;
      const double barPx = lengthMm * pixelsPerMm;
      const double right = width - sizes.marginPx, left = right - barPx;
      const double thickPx = std::max(2.0, 0.14 * sizes.textPx);
      const double barY = bottom - 0.5 * thickPx - 0.15 * sizes.textPx;
      const double tickPx = 0.35 * sizes.textPx;
      SlideLine bar;
      bar.points = {{left, barY}, {right, barY}};
      bar.colour = colours.text;
      bar.widthPx = thickPx;
      bar.group = "scale-bar";
      picture.lines.push_back(bar);
      for (double x : {left, right}) {
        SlideLine tick = bar;
        tick.points = {{x, barY - tickPx}, {x, barY + 0.5 * thickPx}};
        tick.widthPx = std::max(1.0, 0.5 * thickPx);
        picture.lines.push_back(std::move(tick));
      }
      SlideText label =
          text(scaleBarLabel(lengthMm), sizes.textPx, colours.text, "scale-bar-label");
      label.leftPx = std::min(right - label.widthPx, 0.5 * (left + right) - 0.5 * label.widthPx);
      label.topPx = barY - tickPx - sizes.textPx - 0.1 * sizes.textPx;
      picture.texts.push_back(std::move(label));
    }
  }
  return picture;
}

}  // namespace lenslab::app
