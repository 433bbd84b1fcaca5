#include "app/drawing/slide_raster.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImDrawListSharedData: draw lists without an ImGui context

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "app/drawing/im_colour.h"
#include "app/resources.h"

namespace lenslab::app {

namespace {

// The UI's font (platform/window.cpp loads the same files).
std::string findFontFile() {
  for (const char* candidate : kUiFontFiles) {
    std::error_code error;
    if (std::filesystem::exists(candidate, error)) return candidate;
  }
  return {};
}

// DejaVu Sans: ImGui sizes a font by its ascender-to-descender height (1901 + 483 font units);
// CSS sizes it by its em (2048 units).
constexpr double kDejaVuEmPerSize = 2048.0 / (1901.0 + 483.0);

ImVec2 toImVec(const CanvasPoint& point) {
  return ImVec2(static_cast<float>(point.x), static_cast<float>(point.y));
}

struct Canvas {
  int width, height;
  std::vector<std::uint8_t>& rgba;
  const std::uint8_t* texture;  // the font atlas, 8-bit alpha
  int textureWidth, textureHeight;

  float textureAlpha(float u, float v) const {
    // Bilinear: glyph quads sit at fractional positions and are oversampled horizontally.
    const float x = u * static_cast<float>(textureWidth) - 0.5f;
    const float y = v * static_cast<float>(textureHeight) - 0.5f;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    const auto at = [&](int tx, int ty) {
      tx = std::clamp(tx, 0, textureWidth - 1);
      ty = std::clamp(ty, 0, textureHeight - 1);
      return static_cast<float>(texture[static_cast<std::size_t>(ty) * textureWidth + tx]);
    };
    const float top = at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx;
    const float bottom = at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx;
    return (top * (1 - fy) + bottom * fy) / 255.0f;
  }

  void blend(int x, int y, const float colour[4], float coverage) {
    const float alpha = colour[3] * coverage;
    if (alpha <= 0.0f) return;
    std::uint8_t* pixel = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    for (int c = 0; c < 3; ++c) {
      const float mixed = colour[c] * alpha + static_cast<float>(pixel[c]) * (1 - alpha);
      pixel[c] = static_cast<std::uint8_t>(std::clamp(std::lround(mixed), 0L, 255L));
    }
  }

  // Fills a triangle of ImGui vertices, interpolating colour and texture coordinates across it.
  // Pixel centres exactly on an edge shared by two triangles go to one of them only (a top-left
  // style rule on the edge's direction), so anti-aliased fringes are not blended twice.
  void triangle(const ImDrawVert& a, const ImDrawVert& b0, const ImDrawVert& c0,
                const ImVec4& clip) {
    const ImDrawVert* b = &b0;
    const ImDrawVert* c = &c0;
    const auto edge = [](const ImVec2& p, const ImVec2& q, float x, float y) {
      return (x - p.x) * (q.y - p.y) - (y - p.y) * (q.x - p.x);
    };
    float area = edge(a.pos, b->pos, c->pos.x, c->pos.y);
    if (std::abs(area) < 1e-12f || !std::isfinite(area)) return;
    if (area < 0) {
      std::swap(b, c);
      area = -area;
    }
    const ImVec2 p[3] = {a.pos, b->pos, c->pos};
    const ImDrawVert* v[3] = {&a, b, c};
    const float minX = std::max({clip.x, 0.0f, std::min({p[0].x, p[1].x, p[2].x})});
    const float maxX =
        std::min({clip.z, static_cast<float>(width), std::max({p[0].x, p[1].x, p[2].x})});
    const float minY = std::max({clip.y, 0.0f, std::min({p[0].y, p[1].y, p[2].y})});
    const float maxY =
        std::min({clip.w, static_cast<float>(height), std::max({p[0].y, p[1].y, p[2].y})});
    if (!(minX < maxX && minY < maxY)) return;
    float colours[3][4];
    for (int k = 0; k < 3; ++k) {
      const ImU32 col = v[k]->col;
      colours[k][0] = static_cast<float>((col >> IM_COL32_R_SHIFT) & 0xFF);
      colours[k][1] = static_cast<float>((col >> IM_COL32_G_SHIFT) & 0xFF);
      colours[k][2] = static_cast<float>((col >> IM_COL32_B_SHIFT) & 0xFF);
      colours[k][3] = static_cast<float>((col >> IM_COL32_A_SHIFT) & 0xFF) / 255.0f;
    }
    const bool flat = colours[0][3] == colours[1][3] && colours[1][3] == colours[2][3];
    // Edge k runs opposite vertex k: from p[k+1] to p[k+2].
    const auto owns = [&](int k) {
      const ImVec2& from = p[(k + 1) % 3];
      const ImVec2& to = p[(k + 2) % 3];
      return to.y > from.y || (to.y == from.y && to.x < from.x);
    };
    const bool ownsEdge[3] = {owns(0), owns(1), owns(2)};
    const int y0 = static_cast<int>(std::floor(minY)), y1 = static_cast<int>(std::ceil(maxY));
    for (int y = y0; y < y1; ++y) {
      const float py = static_cast<float>(y) + 0.5f;
      // Each edge function is linear in x along the row: narrow the row to where all three are
      // non-negative before testing pixels (long thin rays have huge bounding boxes).
      float spanMin = minX, spanMax = maxX;
      for (int k = 0; k < 3; ++k) {
        const ImVec2& from = p[(k + 1) % 3];
        const ImVec2& to = p[(k + 2) % 3];
        const float slope = to.y - from.y;  // d(edge)/dx
        const float atZero = edge(from, to, 0.0f, py);
        if (slope > 0) spanMin = std::max(spanMin, -atZero / slope - 1.0f);
        if (slope < 0) spanMax = std::min(spanMax, -atZero / slope + 1.0f);
        if (slope == 0 && atZero < 0) spanMax = spanMin;
      }
      const int x0 = std::max(static_cast<int>(std::floor(spanMin)), static_cast<int>(minX));
      const int x1 =
          std::min(static_cast<int>(std::ceil(spanMax)), static_cast<int>(std::ceil(maxX)));
      for (int x = std::max(0, x0); x < std::min(width, x1); ++x) {
        const float px = static_cast<float>(x) + 0.5f;
        if (px < clip.x || px >= clip.z || py < clip.y || py >= clip.w) continue;
        float w[3];
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
          w[k] = edge(p[(k + 1) % 3], p[(k + 2) % 3], px, py);
          inside = w[k] > 0 || (w[k] == 0 && ownsEdge[k]);
        }
        if (!inside) continue;
        float colour[4];
        for (int c2 = 0; c2 < 4; ++c2) {
          colour[c2] =
              (w[0] * colours[0][c2] + w[1] * colours[1][c2] + w[2] * colours[2][c2]) / area;
        }
        if (flat) colour[3] = colours[0][3];
        const float u = (w[0] * v[0]->uv.x + w[1] * v[1]->uv.x + w[2] * v[2]->uv.x) / area;
        const float tv = (w[0] * v[0]->uv.y + w[1] * v[1]->uv.y + w[2] * v[2]->uv.y) / area;
        blend(x, y, colour, textureAlpha(u, tv));
      }
    }
  }
};

}  // namespace

struct SlideFont::Atlas {
  ImFontAtlas atlas;
  std::map<int, ImFont*> fonts;  // by size in 1/4 pixels
};

namespace {

constexpr double kMeasuringSizePx = 64.0;

// An atlas with the font at each of `sizes` (pixels).
std::unique_ptr<SlideFont::Atlas> buildAtlas(const std::string& file,
                                             const std::vector<double>& sizes);

}  // namespace

SlideFont::SlideFont() : file_(findFontFile()) {
  // Measured at one size and scaled: glyph advances are not snapped to pixels, so widths are
  // linear in the size.
  measuring_ = buildAtlas(file_, {kMeasuringSizePx});
}

SlideFont::~SlideFont() = default;

SlideTextMetrics SlideFont::metrics() const {
  ImFont* font = measuring_->fonts.begin()->second;
  SlideTextMetrics metrics;
  metrics.widthPx = [font](const std::string& text, double sizePx) {
    return static_cast<double>(
        font->CalcTextSizeA(static_cast<float>(sizePx), FLT_MAX, 0.0f, text.c_str()).x);
  };
  metrics.ascentPerSize = font->Ascent / font->FontSize;
  metrics.emPerSize = file_.empty() ? 1.0 : kDejaVuEmPerSize;
  return metrics;
}

namespace {

int sizeKey(double sizePx) { return static_cast<int>(std::lround(sizePx * 4)); }

std::unique_ptr<SlideFont::Atlas> buildAtlas(const std::string& file,
                                             const std::vector<double>& sizes) {
  auto result = std::make_unique<SlideFont::Atlas>();
  ImFontAtlas& atlas = result->atlas;
  atlas.Flags |= ImFontAtlasFlags_NoBakedLines;  // lines are tessellated, not textured
  for (double size : sizes) {
    const int key = sizeKey(size);
    if (result->fonts.count(key) != 0) continue;
    const float pixels = static_cast<float>(key) / 4.0f;
    ImFont* font = nullptr;
    if (!file.empty()) font = atlas.AddFontFromFileTTF(file.c_str(), pixels);
    if (font == nullptr) {
      ImFontConfig config;
      config.SizePixels = pixels;
      font = atlas.AddFontDefault(&config);
    }
    result->fonts[key] = font;
  }
  atlas.Build();
  return result;
}

}  // namespace

SlideImage rasterizeSlide(const SlidePicture& picture, const SlideFont& font) {
  SlideImage image;
  image.width = std::max(0, picture.widthPx);
  image.height = std::max(0, picture.heightPx);
  image.rgba.assign(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = picture.background.r;
    image.rgba[i + 1] = picture.background.g;
    image.rgba[i + 2] = picture.background.b;
  }
  if (image.width == 0 || image.height == 0) return image;

  // Text at exactly the sizes the picture uses, so glyphs are not scaled.
  std::vector<double> sizes;
  for (const SlideText& text : picture.texts) sizes.push_back(text.sizePx);
  if (sizes.empty()) sizes.push_back(13.0);
  const std::unique_ptr<SlideFont::Atlas> atlas = buildAtlas(font.file(), sizes);
  unsigned char* texture = nullptr;
  int textureWidth = 0, textureHeight = 0;
  atlas->atlas.GetTexDataAsAlpha8(&texture, &textureWidth, &textureHeight);

  ImDrawListSharedData shared;
  shared.TexUvWhitePixel = atlas->atlas.TexUvWhitePixel;
  shared.TexUvLines = atlas->atlas.TexUvLines;
  shared.Font = atlas->fonts.begin()->second;
  shared.FontSize = shared.Font->FontSize;
  shared.CurveTessellationTol = 1.25f;
  shared.SetCircleTessellationMaxError(0.3f);
  shared.ClipRectFullscreen =
      ImVec4(0, 0, static_cast<float>(image.width), static_cast<float>(image.height));
  shared.InitialFlags = ImDrawListFlags_AntiAliasedLines | ImDrawListFlags_AntiAliasedFill |
                        ImDrawListFlags_AllowVtxOffset;
  ImDrawList list(&shared);
  list._ResetForNewFrame();
  list.PushClipRectFullScreen();
  list.PushTextureID(ImTextureID{});

  // Glass quads share edges: without anti-aliasing their fringes do not leave seams (the
  // outline drawn over them is anti-aliased).
  list.Flags &= ~ImDrawListFlags_AntiAliasedFill;
  for (const SlideFill& fill : picture.fills) {
    std::vector<ImVec2> points;
    for (const CanvasPoint& point : fill.polygon) points.push_back(toImVec(point));
    list.AddConvexPolyFilled(points.data(), static_cast<int>(points.size()),
                             toImColour(fill.colour));
  }
  list.Flags |= ImDrawListFlags_AntiAliasedFill;
  const CanvasRect everything =
      CanvasRect{0, 0, static_cast<double>(image.width), static_cast<double>(image.height)}
          .expanded(8);
  for (const SlideLine& line : picture.lines) {
    const ImU32 colour = toImColour(line.colour);
    const float width = static_cast<float>(line.widthPx);
    if (line.dashed) {
      for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
        for (const CanvasSegment& dash : dashSegment({line.points[i], line.points[i + 1]},
                                                     everything, line.dashPx, line.gapPx)) {
          list.AddLine(toImVec(dash.a), toImVec(dash.b), colour, width);
        }
      }
      continue;
    }
    std::vector<ImVec2> points;
    for (const CanvasPoint& point : line.points) points.push_back(toImVec(point));
    list.AddPolyline(points.data(), static_cast<int>(points.size()), colour,
                     line.closed ? ImDrawFlags_Closed : ImDrawFlags_None, width);
  }
  for (const SlideText& text : picture.texts) {
    ImFont* textFont = atlas->fonts.at(sizeKey(text.sizePx));
    list.AddText(textFont, textFont->FontSize,
                 ImVec2(static_cast<float>(text.leftPx), static_cast<float>(text.topPx)),
                 toImColour(text.colour), text.text.c_str());
  }

  Canvas canvas{image.width, image.height, image.rgba, texture, textureWidth, textureHeight};
  for (const ImDrawCmd& command : list.CmdBuffer) {
    if (command.UserCallback != nullptr) continue;
    for (unsigned i = 0; i + 2 < command.ElemCount; i += 3) {
      const ImDrawIdx* index = &list.IdxBuffer[static_cast<int>(command.IdxOffset + i)];
      const ImDrawVert* vertices = &list.VtxBuffer[static_cast<int>(command.VtxOffset)];
      canvas.triangle(vertices[index[0]], vertices[index[1]], vertices[index[2]], command.ClipRect);
    }
  }
  return image;
}

}  // namespace lenslab::app
