#include "app/platform/frame_damage.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

#include "app/platform/sequence_diff.h"

namespace lenslab::app {

namespace {

// A word-at-a-time multiplicative hash: well under a millisecond for a busy frame's few hundred
// kilobytes of vertices, against tens of milliseconds to rasterize them in software.
class Hash {
 public:
  void mix(std::uint64_t word) {
    value_ = (value_ ^ word) * 0xBF58476D1CE4E5B9ull;
    value_ ^= value_ >> 31;
  }
  void mixBytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, bytes + i, 8);
      mix(word);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, bytes + i, size - i);
    mix(tail ^ (static_cast<std::uint64_t>(size) << 56));
  }
  std::uint64_t value() const { return value_; }

 private:
  std::uint64_t value_ = 0x9E3779B97F4A7C15ull;
};

std::uint64_t ownerHash(const ImDrawList& list) {
  Hash hash;
  if (list._OwnerName != nullptr) {
    const std::string_view name(list._OwnerName);
    hash.mixBytes(name.data(), name.size());
  }
  return hash.value();
}

// Whether `list`'s commands are the ones recorded in `before`: clip rects, textures, callbacks
// and the ranges of vertices and indices they draw.
bool sameCommands(const ImDrawList& list, const std::vector<FrameDamageCommand>& before) {
  if (static_cast<std::size_t>(list.CmdBuffer.Size) != before.size()) return false;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const ImDrawCmd& command = list.CmdBuffer[static_cast<int>(i)];
    const FrameDamageCommand& c = before[i];
    if (std::memcmp(&command.ClipRect, &c.clipRect, sizeof c.clipRect) != 0 ||
        command.TextureId != c.texture || command.UserCallback != c.callback ||
        command.VtxOffset != c.vertexOffset || command.IdxOffset != c.indexOffset ||
        command.ElemCount != c.indexCount) {
      return false;
    }
  }
  return true;
}

// The pixels a bounding box of triangles (in ImGui's coordinates) can change: one pixel wider
// on each side for rasterization rounding, inside the command's scissor box.
PixelRect boxToPixels(float minX, float minY, float maxX, float maxY, const PixelRect& scissor,
                      ImVec2 offset, ImVec2 scale) {
  if (scissor.empty() || !(minX <= maxX) || !(minY <= maxY)) return {};
  // Clamped before the conversion: a vertex far off screen must not overflow an int.
  const auto toPixel = [](float value) {
    return static_cast<int>(std::clamp(value, -1.0e6f, 1.0e6f));
  };
  const PixelRect box{toPixel(std::floor((minX - offset.x) * scale.x)) - 1,
                      toPixel(std::floor((minY - offset.y) * scale.y)) - 1,
                      toPixel(std::ceil((maxX - offset.x) * scale.x)) + 1,
                      toPixel(std::ceil((maxY - offset.y) * scale.y)) + 1};
  return intersect(box, scissor);
}

// The pixels a command's triangles can change.
PixelRect commandPixels(const ImDrawList& list, const ImDrawCmd& command, const PixelRect& scissor,
                        ImVec2 offset, ImVec2 scale) {
  float minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
  const ImDrawIdx* indices = list.IdxBuffer.Data + command.IdxOffset;
  const ImDrawVert* vertices = list.VtxBuffer.Data + command.VtxOffset;
  for (unsigned i = 0; i < command.ElemCount; ++i) {
    const ImVec2 p = vertices[indices[i]].pos;
    minX = std::min(minX, p.x);
    minY = std::min(minY, p.y);
    maxX = std::max(maxX, p.x);
    maxY = std::max(maxY, p.y);
  }
  return boxToPixels(minX, minY, maxX, maxY, scissor, offset, scale);
}

bool nearEnoughToMerge(const PixelRect& a, const PixelRect& b) {
  // When their bounding rect is hardly (10%) larger than the two (overlapping, or side by side),
  // one region costs less than two. Not merely touching: two panels meeting at a corner span the
  // window.
  return unite(a, b).area() <= (a.area() + b.area()) * 11 / 10;
}

std::vector<PixelRect> merged(std::vector<PixelRect> rects, const PixelRect& whole) {
  std::erase_if(rects, [](const PixelRect& r) { return r.empty(); });
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < rects.size() && !changed; ++i) {
      for (std::size_t j = i + 1; j < rects.size() && !changed; ++j) {
        if (nearEnoughToMerge(rects[i], rects[j])) {
          rects[i] = unite(rects[i], rects[j]);
          rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(j));
          changed = true;
        }
      }
    }
  }
  // Too many: merge the two whose bounding rect adds the fewest pixels, until few enough.
  while (rects.size() > static_cast<std::size_t>(FrameDamage::kMaxRegions)) {
    std::size_t bestI = 0, bestJ = 1;
    long long bestGrowth = -1;
    for (std::size_t i = 0; i < rects.size(); ++i) {
      for (std::size_t j = i + 1; j < rects.size(); ++j) {
        const long long growth =
            unite(rects[i], rects[j]).area() - rects[i].area() - rects[j].area();
        if (bestGrowth < 0 || growth < bestGrowth) {
          bestGrowth = growth;
          bestI = i;
          bestJ = j;
        }
      }
    }
    rects[bestI] = unite(rects[bestI], rects[bestJ]);
    rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(bestJ));
  }
  long long area = 0;
  for (const PixelRect& r : rects) area += r.area();
  if (area > FrameDamage::kFullRepaintFraction * static_cast<double>(whole.area())) return {whole};
  return rects;
}

}  // namespace

PixelRect unite(const PixelRect& a, const PixelRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  const PixelRect r{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                    std::min(a.y1, b.y1)};
  return r.empty() ? PixelRect{} : r;
}

PixelRect scissorOf(const ImDrawCmd& command, const ImDrawData& data, int framebufferHeight) {
  // As imgui_impl_opengl3.cpp (1.86) turns ClipRect into glScissor(x, y, w, h), y from the
  // bottom.
  const ImVec2 offset = data.DisplayPos, scale = data.FramebufferScale;
  const float minX = (command.ClipRect.x - offset.x) * scale.x;
  const float minY = (command.ClipRect.y - offset.y) * scale.y;
  const float maxX = (command.ClipRect.z - offset.x) * scale.x;
  const float maxY = (command.ClipRect.w - offset.y) * scale.y;
  if (!(maxX > minX) || !(maxY > minY)) return {};
  const auto toInt = [](float value) {
    return static_cast<int>(std::clamp(value, -1.0e6f, 1.0e6f));
  };
  const int x = toInt(minX);
  const int yFromBottom = toInt(static_cast<float>(framebufferHeight) - maxY);
  const int width = toInt(maxX - minX);
  const int height = toInt(maxY - minY);
  const int top = framebufferHeight - yFromBottom - height;
  return {x, top, x + width, top + height};
}

namespace {

// A list's triangles in drawing order, across its commands (ImGui splits a window's drawing into
// commands wherever the clip rect or texture changes, so an edit can change their number).
struct TriangleRef {
  const ImDrawVert* corners[3];
  const FrameDamageCommand* command;
};

}  // namespace

std::vector<PixelRect> FrameDamage::changedPart(const ListRecord& before, const ListRecord& now) {
  const PixelRect everything = unite(before.covered, now.covered);
  const auto triangles = [](const ListRecord& list, std::vector<TriangleRef>& out) {
    out.clear();
    for (const CommandRecord& command : list.commands) {
      if (command.callback == ImDrawCallback_ResetRenderState) continue;  // draws nothing
      if (command.callback != nullptr) return false;  // draws anything: not comparable
      const ImDrawIdx* indices = list.indices.data() + command.indexOffset;
      const ImDrawVert* vertices = list.vertices.data() + command.vertexOffset;
      for (unsigned i = 0; i + 3 <= command.indexCount; i += 3) {
        out.push_back(
            {{&vertices[indices[i]], &vertices[indices[i + 1]], &vertices[indices[i + 2]]},
             &command});
      }
    }
    return true;
  };
  std::vector<TriangleRef> a, b;
  if (!triangles(before, a) || !triangles(now, b)) return {everything};
  const auto same = [](const TriangleRef& x, const TriangleRef& y) {
    if (x.command->texture != y.command->texture ||
        std::memcmp(&x.command->clipRect, &y.command->clipRect, sizeof(ImVec4)) != 0) {
      return false;
    }
    for (int corner = 0; corner < 3; ++corner) {
      if (std::memcmp(x.corners[corner], y.corners[corner], sizeof(ImDrawVert)) != 0) return false;
    }
    return true;
  };
  const std::size_t shorter = std::min(a.size(), b.size());
  std::size_t prefix = 0;
  while (prefix < shorter && same(a[prefix], b[prefix])) ++prefix;
  std::size_t suffix = 0;
  while (suffix < shorter - prefix && same(a[a.size() - 1 - suffix], b[b.size() - 1 - suffix])) {
    ++suffix;
  }
  const std::span<const TriangleRef> middleA(a.data() + prefix, a.size() - suffix - prefix);
  const std::span<const TriangleRef> middleB(b.data() + prefix, b.size() - suffix - prefix);

  // The boxes of runs of triangles (consecutive, of one command) that `changed` marks, or of all
  // of them, each inside its command's scissor box.
  const auto boxesOfRuns = [](std::span<const TriangleRef> list, const std::vector<bool>* changed,
                              const ListRecord& record, std::vector<PixelRect>& out) {
    float minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    const FrameDamageCommand* command = nullptr;
    const auto flush = [&] {
      if (command != nullptr) {
        out.push_back(
            boxToPixels(minX, minY, maxX, maxY, command->scissor, record.offset, record.scale));
      }
      command = nullptr;
      minX = minY = INFINITY;
      maxX = maxY = -INFINITY;
    };
    for (std::size_t t = 0; t < list.size(); ++t) {
      if (changed != nullptr && !(*changed)[t]) {
        flush();
        continue;
      }
      if (list[t].command != command) {
        flush();
        command = list[t].command;
      }
      for (const ImDrawVert* corner : list[t].corners) {
        minX = std::min(minX, corner->pos.x);
        minY = std::min(minY, corner->pos.y);
        maxX = std::max(maxX, corner->pos.x);
        maxY = std::max(maxY, corner->pos.y);
      }
    }
    flush();
  };
  const auto unionOf = [](const std::vector<PixelRect>& rects) {
    PixelRect all;
    for (const PixelRect& rect : rects) all = unite(all, rect);
    return all;
  };

  // Between the prefix and the suffix, unchanged triangles can sit among changed ones (the
  // preview's background between its status line and its image). The triangles that a shortest
  // edit script keeps are drawn alike and in the same order before and now, so only the others
  // damage pixels: any pixel outside their boxes is covered by the same triangles, blended in
  // the same order. Past kMaxEdits (a cross-section whose rays all moved) the whole middles.
  const auto keysOf = [](std::span<const TriangleRef> list) {
    std::vector<std::uint64_t> keys;
    keys.reserve(list.size());
    for (const TriangleRef& triangle : list) {
      Hash hash;
      hash.mix(reinterpret_cast<std::uintptr_t>(triangle.command->texture));
      hash.mixBytes(&triangle.command->clipRect, sizeof(ImVec4));
      for (const ImDrawVert* corner : triangle.corners) hash.mixBytes(corner, sizeof(ImDrawVert));
      keys.push_back(hash.value());
    }
    return keys;
  };
  std::vector<bool> changedA, changedB;
  std::vector<PixelRect> rects;
  if (markUnmatched(
          keysOf(middleA), keysOf(middleB),
          [&](std::size_t i, std::size_t j) { return same(middleA[i], middleB[j]); }, kMaxEdits,
          changedA, changedB)) {
    boxesOfRuns(middleA, &changedA, before, rects);
    boxesOfRuns(middleB, &changedB, now, rects);
    std::erase_if(rects, [](const PixelRect& r) { return r.empty(); });
    // Many scattered runs: their merging would cost more than it saves.
    if (rects.size() > kMaxRuns) rects = {unionOf(rects)};
    return rects;
  }
  boxesOfRuns(middleA, nullptr, before, rects);
  boxesOfRuns(middleB, nullptr, now, rects);
  return {unionOf(rects)};
}

bool FrameDamage::sameAs(const ImDrawList& list, const ImDrawData& data, const ListRecord& before) {
  const auto sameBytes = [](const auto& vector, const auto& copy) {
    return static_cast<std::size_t>(vector.Size) == copy.size() &&
           (copy.empty() ||
            std::memcmp(vector.Data, copy.data(), copy.size() * sizeof copy[0]) == 0);
  };
  return data.DisplayPos.x == before.offset.x && data.DisplayPos.y == before.offset.y &&
         data.FramebufferScale.x == before.scale.x && data.FramebufferScale.y == before.scale.y &&
         sameCommands(list, before.commands) && sameBytes(list.IdxBuffer, before.indices) &&
         sameBytes(list.VtxBuffer, before.vertices);
}

std::vector<PixelRect> FrameDamage::compare(const ImDrawData& data, int framebufferWidth,
                                            int framebufferHeight,
                                            std::span<const ImTextureID> changedTextures) {
  const PixelRect whole{0, 0, framebufferWidth, framebufferHeight};
  std::vector<ListRecord> now(static_cast<std::size_t>(std::max(0, data.CmdListsCount)));
  std::vector<PixelRect> damage;
  const bool comparable = valid_ && framebufferWidth == width_ && framebufferHeight == height_ &&
                          now.size() == lists_.size();
  bool wholeFrame = !comparable;
  const auto damageByChangedTextures = [&](const ListRecord& record) {
    for (const CommandRecord& c : record.commands) {
      if (std::find(changedTextures.begin(), changedTextures.end(), c.texture) !=
          changedTextures.end()) {
        damage.push_back(c.covered);
      }
    }
  };
  for (std::size_t n = 0; n < now.size(); ++n) {
    const ImDrawList& list = *data.CmdLists[n];
    ListRecord& record = now[n];
    record.owner = ownerHash(list);
    // Most lists are the same as in the previous frame (every list, in a frame that only waits
    // for the renderer): compared with the copy kept of them, they are taken over without a new
    // copy or a new walk over their triangles.
    if (comparable && record.owner == lists_[n].owner && sameAs(list, data, lists_[n])) {
      record = std::move(lists_[n]);
      damageByChangedTextures(record);
      continue;
    }
    record.offset = data.DisplayPos;
    record.scale = data.FramebufferScale;
    record.vertices.assign(list.VtxBuffer.begin(), list.VtxBuffer.end());
    record.indices.assign(list.IdxBuffer.begin(), list.IdxBuffer.end());
    for (const ImDrawCmd& command : list.CmdBuffer) {
      CommandRecord c;
      c.clipRect = command.ClipRect;
      c.texture = command.TextureId;
      c.callback = command.UserCallback;
      c.vertexOffset = command.VtxOffset;
      c.indexOffset = command.IdxOffset;
      c.indexCount = command.ElemCount;
      c.scissor = scissorOf(command, data, framebufferHeight);
      if (c.callback != nullptr) {
        // ImGui's render-state reset draws nothing; another callback may draw anywhere it may.
        c.covered = c.callback == ImDrawCallback_ResetRenderState ? PixelRect{} : c.scissor;
      } else {
        c.covered = commandPixels(list, command, c.scissor, data.DisplayPos, data.FramebufferScale);
      }
      record.covered = unite(record.covered, c.covered);
      record.commands.push_back(c);
    }
    damageByChangedTextures(record);
    if (wholeFrame) continue;
    if (record.owner != lists_[n].owner) {
      wholeFrame = true;  // windows appeared, closed or changed order
    } else {
      for (const PixelRect& rect : changedPart(lists_[n], record)) damage.push_back(rect);
    }
  }

  lists_ = std::move(now);
  width_ = framebufferWidth;
  height_ = framebufferHeight;
  valid_ = true;
  if (wholeFrame) return whole.empty() ? std::vector<PixelRect>{} : std::vector<PixelRect>{whole};
  for (PixelRect& rect : damage) rect = intersect(rect, whole);
  return merged(std::move(damage), whole);
}

}  // namespace lenslab::app
