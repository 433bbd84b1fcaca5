// The Library panel (Lens > Library > Browse library...): every lens of the bundled library as a
// card, its cross-section with its fans over its name, type and year, focal length, f-number and
// field, elements and aspheric surfaces; a search box and filters above them. A click selects a
// card, a double-click (or its Open button) opens the lens as File > Open does: focused for the
// scene, one undo step. The reading and the thumbnails come from the catalogue's worker
// (library/library_catalogue.h); this file only uploads the finished pictures and draws.

#include <imgui.h>
#include <imgui_internal.h>  // RenderTextEllipsis: a long name ends in "..." inside its card

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "app/automation/item_rect.h"
#include "app/library/library_browser.h"
#include "app/panels/panel_window.h"
#include "app/panels/panels.h"
#include "app/panels/wrap_row.h"
#include "app/platform/ui_scale.h"

namespace lenslab::app {

namespace {

using LibraryClock = LibraryBrowserState::Clock;

double libraryMsSince(LibraryClock::time_point start) {
  return std::chrono::duration<double, std::milli>(LibraryClock::now() - start).count();
}

// Uploads what the worker finished since the last frame (a few 100 kB at most per frame).
void uploadLibraryThumbnails(LibraryBrowserState& library) {
  for (LibraryCatalogue::Thumbnail& thumbnail : library.catalogue->takeThumbnails()) {
    auto texture = std::make_unique<PreviewTexture>();
    texture->upload(thumbnail.image.width, thumbnail.image.height, thumbnail.image.rgba);
    library.thumbnails[thumbnail.contentHash] = std::move(texture);
  }
}

// The search box and the filters, wrapped like words when the panel is narrow.
void drawLibraryFilters(ViewerState& state, const LibraryCatalogue::Snapshot& snapshot) {
  const std::vector<LibraryEntry>& entries = snapshot.entries;
  LibraryBrowserState& library = state.library;
  LibraryFilter& filter = library.filter;
  WrapRow row;
  const float searchWidth = px(220);
  row.next(searchWidth);
  ImGui::SetNextItemWidth(searchWidth);
  ImGui::InputTextWithHint("##library-search", "Search name, type, source", library.searchText,
                           sizeof library.searchText);
  recordItemRect(state, "library/search");
  filter.search = library.searchText;

  // Each combo's label before it, as the range fields' check boxes ("any Type any Aspheric" read
  // as one phrase with the labels after).
  const std::vector<std::string> types = libraryTypes(entries);
  const float comboWidth = px(170);
  const float labelGap = ImGui::GetStyle().ItemInnerSpacing.x;
  row.next(comboWidth + ImGui::CalcTextSize("Type").x + labelGap);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Type");
  ImGui::SameLine(0, labelGap);
  ImGui::SetNextItemWidth(comboWidth);
  if (ImGui::BeginCombo("##type", filter.type.empty() ? "any" : filter.type.c_str())) {
    if (ImGui::Selectable("any", filter.type.empty())) filter.type.clear();
    for (const std::string& type : types)
      if (ImGui::Selectable(type.c_str(), type == filter.type)) filter.type = type;
    ImGui::EndCombo();
  }

  const char* asphericLabels[] = {"any", "with aspheres", "all spherical"};
  int aspheric = static_cast<int>(filter.aspheric);
  const float asphericWidth = px(130);
  row.next(asphericWidth + ImGui::CalcTextSize("Aspheric").x + labelGap);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Aspheric");
  ImGui::SameLine(0, labelGap);
  ImGui::SetNextItemWidth(asphericWidth);
  if (ImGui::Combo("##aspheric", &aspheric, asphericLabels, 3))
    filter.aspheric = static_cast<AsphericChoice>(aspheric);

  // A range: its check box turns it on, two fields give its ends.
  const float fieldWidth = px(64);
  const float rangeWidth = WrapRow::checkboxWidth("Focal length") + 2 * fieldWidth +
                           ImGui::CalcTextSize("to mm").x + 4 * ImGui::GetStyle().ItemSpacing.x;
  row.next(rangeWidth);
  ImGui::Checkbox("Focal length", &library.eflRange);
  ImGui::SameLine();
  ImGui::BeginDisabled(!library.eflRange);
  ImGui::SetNextItemWidth(fieldWidth);
  ImGui::InputDouble("##efl-from", &library.eflFromMm, 0, 0, "%.0f");
  ImGui::SameLine();
  ImGui::TextUnformatted("to");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(fieldWidth);
  ImGui::InputDouble("mm##efl-to", &library.eflToMm, 0, 0, "%.0f");
  ImGui::EndDisabled();
  filter.minEflMm = library.eflRange ? std::optional(library.eflFromMm) : std::nullopt;
  filter.maxEflMm = library.eflRange ? std::optional(library.eflToMm) : std::nullopt;

  row.next(WrapRow::checkboxWidth("Year") + 2 * fieldWidth + ImGui::CalcTextSize("to").x +
           3 * ImGui::GetStyle().ItemSpacing.x);
  ImGui::Checkbox("Year", &library.yearRange);
  ImGui::SameLine();
  ImGui::BeginDisabled(!library.yearRange);
  ImGui::SetNextItemWidth(fieldWidth);
  ImGui::InputInt("##year-from", &library.yearFrom, 0);
  ImGui::SameLine();
  ImGui::TextUnformatted("to");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(fieldWidth);
  ImGui::InputInt("##year-to", &library.yearTo, 0);
  ImGui::EndDisabled();
  filter.minYear = library.yearRange ? std::optional(library.yearFrom) : std::nullopt;
  filter.maxYear = library.yearRange ? std::optional(library.yearTo) : std::nullopt;

  row.next(ImGui::CalcTextSize("Clear").x + 2 * ImGui::GetStyle().FramePadding.x);
  ImGui::BeginDisabled(!filter.active());
  if (ImGui::Button("Clear")) {
    library.searchText[0] = '\0';
    library.eflRange = library.yearRange = false;
    filter = {};
  }
  ImGui::EndDisabled();

  // What is shown of how many, or how far the reading is; the folder in its tooltip.
  char status[160];
  if (library.folder.empty()) {
    std::snprintf(status, sizeof status, "no lenses/ folder found");
  } else if (!snapshot.listed) {
    std::snprintf(status, sizeof status, "reading %zu of %zu lens files...", entries.size(),
                  snapshot.files);
  } else {
    std::snprintf(status, sizeof status, "%zu of %zu lenses", filterLibrary(entries, filter).size(),
                  entries.size());
  }
  if (snapshot.listed && !snapshot.finished) {
    const std::size_t used = std::strlen(status);
    std::snprintf(status + used, sizeof status - used, ", drawing thumbnails (%zu done)",
                  snapshot.thumbnailsDrawn + snapshot.thumbnailsFromDisk);
  }
  row.next(ImGui::CalcTextSize(status).x + ImGui::CalcTextSize("Reload").x +
           2 * ImGui::GetStyle().FramePadding.x + ImGui::GetStyle().ItemSpacing.x);
  ImGui::TextDisabled("%s", status);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", library.folder.string().c_str());
  ImGui::SameLine();
  // Files added or changed since: read again (unchanged ones keep their thumbnails).
  if (ImGui::SmallButton("Reload")) showLibraryBrowser(state, library.folder, true);
}

// "50.0 mm   f/2.5   ±23.4°": the focal length, f-number and half field.
std::string libraryFiguresLine(const LibraryEntry& entry) {
  std::string line;
  char text[48];
  const auto add = [&](const char* format, double value) {
    std::snprintf(text, sizeof text, format, value);
    line += (line.empty() ? "" : "   ") + std::string(text);
  };
  if (entry.eflMm) {
    add(std::abs(*entry.eflMm) < 10 ? "%.2f mm" : "%.1f mm", *entry.eflMm);
  } else {
    line = "afocal";
  }
  if (entry.fNumber) add("f/%.2f", *entry.fNumber);
  if (entry.halfFieldDeg) add("\xC2\xB1%.1f\xC2\xB0", *entry.halfFieldDeg);
  return line;
}

std::string libraryMakeupLine(const LibraryEntry& entry) {
  std::string line =
      std::to_string(entry.elements) + (entry.elements == 1 ? " element" : " elements");
  if (entry.asphericSurfaces > 0)
    line += " \xC2\xB7 " + std::to_string(entry.asphericSurfaces) + " aspheric";
  return line;
}

std::string libraryTypeLine(const LibraryEntry& entry) {
  std::string line = entry.type.empty() ? std::string("type not stated") : entry.type;
  if (entry.year) line += " \xC2\xB7 " + std::to_string(*entry.year);
  return line;
}

// One card: returns true when it asks to open its lens (a double-click).
bool drawLibraryCard(ViewerState& state, const LibraryEntry& entry, float cardWidth,
                     float cardHeight) {
  LibraryBrowserState& library = state.library;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::PushID(entry.fileName.c_str());
  ImGui::InvisibleButton("card", ImVec2(cardWidth, cardHeight));
  const bool hovered = ImGui::IsItemHovered();
  const bool selected = library.selectedPath == entry.path.string();
  if (ImGui::IsItemClicked()) library.selectedPath = entry.path.string();
  bool open = hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && entry.usable();
  recordItemRect(state, "library/card/" + entry.fileName);
  ImGui::PopID();

  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec2 end(origin.x + cardWidth, origin.y + cardHeight);
  const ImU32 background = ImGui::GetColorU32(selected  ? ImGuiCol_HeaderActive
                                              : hovered ? ImGuiCol_HeaderHovered
                                                        : ImGuiCol_FrameBg);
  draw->AddRectFilled(origin, end, background, style.FrameRounding);
  const float pad = px(6);
  const ImVec2 imageMin(origin.x + pad, origin.y + pad);
  const ImVec2 imageMax(imageMin.x + px(kLibraryThumbnailWidth),
                        imageMin.y + px(kLibraryThumbnailHeight));
  const auto texture = library.thumbnails.find(entry.contentHash);
  const ImU32 muted = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  if (texture != library.thumbnails.end() && entry.usable()) {
    draw->AddImage(texture->second->imguiId(), imageMin, imageMax);
  } else {
    draw->AddRectFilled(imageMin, imageMax, IM_COL32(18, 20, 26, 255));
    const char* note = entry.usable() ? "drawing..." : "cannot be opened";
    const ImVec2 size = ImGui::CalcTextSize(note);
    draw->AddText(ImVec2(0.5f * (imageMin.x + imageMax.x - size.x),
                         0.5f * (imageMin.y + imageMax.y - size.y)),
                  entry.usable() ? muted : IM_COL32(255, 120, 100, 255), note);
  }
  // The text lines under the picture, each cut with "..." at the card's edge.
  float y = imageMax.y + px(4);
  const float lineHeight = ImGui::GetTextLineHeightWithSpacing();
  const float textRight = end.x - pad;
  const auto line = [&](const std::string& text, ImU32 colour) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::RenderTextEllipsis(draw, ImVec2(imageMin.x, y), ImVec2(textRight, y + lineHeight),
                              textRight, textRight, text.c_str(), nullptr, nullptr);
    ImGui::PopStyleColor();
    y += lineHeight;
  };
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  // The name on two lines at most, broken between words; the second ends in "..." if need be.
  const char* name = entry.name.c_str();
  const char* nameEnd = name + entry.name.size();
  const char* wrap =
      ImGui::GetFont()->CalcWordWrapPositionA(1.0f, name, nameEnd, textRight - imageMin.x);
  if (wrap <= name || wrap >= nameEnd) {
    line(entry.name, text);
    y += lineHeight;  // the cards keep one height: their figures line up across a row
  } else {
    line(std::string(name, wrap), text);
    while (wrap < nameEnd && *wrap == ' ') ++wrap;
    line(std::string(wrap, nameEnd), text);
  }
  if (!entry.usable()) {
    line(entry.fileName, muted);
    line(entry.error, IM_COL32(255, 120, 100, 255));
  } else {
    line(libraryTypeLine(entry), IM_COL32(150, 200, 255, 255));
    line(libraryFiguresLine(entry), text);
    line(libraryMakeupLine(entry), muted);
  }
  if (selected)
    draw->AddRect(origin, end, IM_COL32(120, 180, 255, 255), style.FrameRounding, 0, px(2));
  if (hovered) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(px(460));
    ImGui::TextUnformatted(entry.name.c_str());
    ImGui::TextDisabled("%s", entry.fileName.c_str());
    if (!entry.source.empty()) ImGui::Text("Source: %s", entry.source.c_str());
    if (entry.halfFieldDeg)
      ImGui::TextDisabled("Field: half angle, %s", entry.halfFieldFrom.c_str());
    if (!entry.usable())
      ImGui::TextUnformatted(entry.error.c_str());
    else
      ImGui::TextDisabled("Double-click to open");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  return open;
}

// How long everything took to show, from the request (the first frame that shows each).
void noteLibraryTiming(ViewerState& state, const LibraryCatalogue::Snapshot& snapshot,
                       std::size_t usable) {
  LibraryBrowserState& library = state.library;
  if (!library.requestedAt) return;
  const double ms = libraryMsSince(*library.requestedAt);
  if (!library.panelShownMs) {
    library.panelShownMs = ms;
    library.panelShownAfterFrames = state.frameNumber - library.requestedInFrame;
  }
  if (!library.listedMs && snapshot.listed) library.listedMs = ms;
  if (!library.thumbnailsShownMs && snapshot.finished && library.thumbnailsShown >= usable)
    library.thumbnailsShownMs = ms;
  if (library.thumbnailsShownMs && !library.timingLogged) {
    library.timingLogged = true;
    char text[256];
    std::snprintf(text, sizeof text,
                  "Library: %zu lenses read in %.0f ms and shown %.0f ms after the request, "
                  "their thumbnails made in %.0f ms (%zu from the cache on disk, %zu drawn) and "
                  "shown after %.0f ms",
                  snapshot.entries.size(), snapshot.listedAfterMs, *library.listedMs,
                  snapshot.finishedAfterMs, snapshot.thumbnailsFromDisk, snapshot.thumbnailsDrawn,
                  *library.thumbnailsShownMs);
    state.log.info(text);
  }
}

int libraryThumbnailWidthPx() { return static_cast<int>(std::lround(px(kLibraryThumbnailWidth))); }
int libraryThumbnailHeightPx() {
  return static_cast<int>(std::lround(px(kLibraryThumbnailHeight)));
}

}  // namespace

void showLibraryBrowser(ViewerState& state, const std::filesystem::path& folder, bool reload) {
  if (const PanelSpec* panel = findPanel("library")) showPanel(state, *panel);
  openLibrary(state.library, folder, libraryThumbnailWidthPx(), libraryThumbnailHeightPx(),
              state.frameNumber, reload);
}

void drawLibraryPanel(ViewerState& state, const PanelPlace& place) {
  LibraryBrowserState& library = state.library;
  // Shown from the View menu or its tab before anything asked to read a folder: the bundled one.
  if (!library.catalogue) {
    openLibrary(library, bundledLibraryFolder(), libraryThumbnailWidthPx(),
                libraryThumbnailHeightPx(), state.frameNumber - 1);
  }
  uploadLibraryThumbnails(library);
  if (beginPanel("Library", place)) {
    const ShownLibrary shown = shownLibraryEntries(library);
    const LibraryCatalogue::Snapshot& snapshot = *shown.snapshot;
    drawLibraryFilters(state, snapshot);
    // The filters above may have changed this frame: list what they keep now.
    const std::vector<std::size_t> kept = filterLibrary(snapshot.entries, library.filter);
    ImGui::Separator();

    ImGui::BeginChild("library-cards", ImVec2(0, 0), false);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float cardWidth = px(kLibraryThumbnailWidth) + px(12);
    const float cardHeight =
        px(kLibraryThumbnailHeight) + px(16) + 5 * ImGui::GetTextLineHeightWithSpacing();
    const float available = ImGui::GetContentRegionAvail().x;
    const int columns = std::max(
        1, static_cast<int>((available + style.ItemSpacing.x) / (cardWidth + style.ItemSpacing.x)));
    std::size_t usable = 0, thumbnailsShown = 0;
    for (const LibraryEntry& entry : snapshot.entries) {
      if (!entry.usable()) continue;
      ++usable;
      thumbnailsShown += library.thumbnails.count(entry.contentHash);
    }
    std::optional<std::filesystem::path> toOpen;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      if (k % columns != 0) ImGui::SameLine();
      const LibraryEntry& entry = snapshot.entries[kept[k]];
      if (drawLibraryCard(state, entry, cardWidth, cardHeight)) toOpen = entry.path;
    }
    if (kept.empty() && snapshot.listed && !snapshot.entries.empty())
      ImGui::TextDisabled("No lens matches the search and filters.");
    ImGui::EndChild();
    library.shownCount = kept.size();
    library.thumbnailsShown = thumbnailsShown;
    noteLibraryTiming(state, snapshot, usable);
    if (toOpen) {
      // Exactly as File > Open and the Library menu: the viewer reads it, focuses it for the
      // scene and makes it one undo step.
      state.fileRequests.push_back({FileRequest::Kind::OpenLens, toOpen->string()});
    }
  }
  ImGui::End();
}

}  // namespace lenslab::app
