#pragma once
// The library browser's state in the viewer (Lens > Library > Browse library..., the Library
// panel: panels/library_panel.cpp): the folder it shows, its catalogue (read off the UI thread),
// the thumbnails uploaded so far (the cache in memory, by the file's content hash), the search
// and filters, and how long it took to show everything, measured from the request.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "app/library/library_catalogue.h"
#include "app/library/library_filter.h"
#include "app/platform/preview_texture.h"

namespace lenslab::app {

// The thumbnail's size in the panel, in UI units (times the UI scale in pixels): wide, as a lens
// and its film are.
inline constexpr float kLibraryThumbnailWidth = 248.0f, kLibraryThumbnailHeight = 112.0f;

struct LibraryBrowserState {
  using Clock = std::chrono::steady_clock;
  std::filesystem::path folder;  // the one shown; empty until the browser first opens
  std::unique_ptr<LibraryCatalogue> catalogue;
  // Uploaded thumbnails by content hash: a lens whose file is unchanged keeps its picture when
  // the folder is read again.
  std::map<std::uint64_t, std::unique_ptr<PreviewTexture>> thumbnails;
  LibraryFilter filter;
  // The filter's fields while typed in (the filter takes them each frame).
  char searchText[128] = {};
  bool eflRange = false, yearRange = false;
  double eflFromMm = 10.0, eflToMm = 300.0;
  int yearFrom = 1840, yearTo = 2026;
  std::string selectedPath;  // the lens last clicked or opened
  // Opening: when it was asked for, and the first frames that showed the panel, every entry
  // and every thumbnail (ms from the request); nullopt until reached. Logged once complete.
  std::optional<Clock::time_point> requestedAt;
  std::optional<double> panelShownMs, listedMs, thumbnailsShownMs;
  // The frame of the request, and how many frames later the panel was first drawn (1: the next).
  std::uint64_t requestedInFrame = 0;
  std::optional<std::uint64_t> panelShownAfterFrames;
  bool timingLogged = false;
  // What the panel showed last frame, for dump-ui and scripts.
  std::size_t shownCount = 0, thumbnailsShown = 0;
};

// Starts reading `folder` (replacing the catalogue of another folder, or `rescan`: the same one
// again); the thumbnails already uploaded are kept and not made again. The timing starts now.
void openLibrary(LibraryBrowserState& library, const std::filesystem::path& folder,
                 int thumbnailWidthPx, int thumbnailHeightPx, std::uint64_t frameNumber,
                 bool rescan = false);

// The bundled library: the lenses/ folder the Library menu lists (resources.h).
std::filesystem::path bundledLibraryFolder();

// The entries the search and filters keep, as the panel lists them: indices into the catalogue's
// newest snapshot, held here (null before the browser first opens).
struct ShownLibrary {
  std::shared_ptr<const LibraryCatalogue::Snapshot> snapshot;
  std::vector<std::size_t> indices;
};
ShownLibrary shownLibraryEntries(const LibraryBrowserState& library);

// The shown entry a script names: its file name, its file name without the extension, or its
// name, without case; nullopt when none is shown.
std::optional<LibraryEntry> findShownLibraryEntry(const LibraryBrowserState& library,
                                                  const std::string& name);

}  // namespace lenslab::app
