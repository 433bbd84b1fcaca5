#include "app/library/library_browser.h"

#include <algorithm>
#include <cctype>

#include "app/library/library_thumbnail.h"
#include "app/platform/window.h"
#include "app/resources.h"

namespace lenslab::app {

void openLibrary(LibraryBrowserState& library, const std::filesystem::path& folder,
                 int thumbnailWidthPx, int thumbnailHeightPx, std::uint64_t frameNumber,
                 bool rescan) {
  library.requestedAt = LibraryBrowserState::Clock::now();
  library.requestedInFrame = frameNumber;
  library.panelShownAfterFrames.reset();
  library.panelShownMs.reset();
  library.listedMs.reset();
  library.thumbnailsShownMs.reset();
  library.timingLogged = false;
  const bool sameSize = library.catalogue &&
                        library.catalogue->options().thumbnailWidthPx == thumbnailWidthPx &&
                        library.catalogue->options().thumbnailHeightPx == thumbnailHeightPx;
  if (library.catalogue && library.folder == folder && sameSize && !rescan) return;
  if (!sameSize) library.thumbnails.clear();
  library.folder = folder;
  LibraryCatalogue::Options options;
  options.folder = folder;
  options.thumbnailWidthPx = thumbnailWidthPx;
  options.thumbnailHeightPx = thumbnailHeightPx;
  options.cacheDirectory = thumbnailCacheDirectory();
  for (const auto& [hash, texture] : library.thumbnails) options.known.insert(hash);
  options.published = &Window::wakeFromAnyThread;
  library.catalogue.reset();  // stops the old worker first
  library.catalogue = std::make_unique<LibraryCatalogue>(std::move(options));
}

std::filesystem::path bundledLibraryFolder() { return findResourceDirectory("lenses"); }

ShownLibrary shownLibraryEntries(const LibraryBrowserState& library) {
  ShownLibrary shown;
  if (!library.catalogue) return shown;
  shown.snapshot = library.catalogue->snapshot();
  shown.indices = filterLibrary(shown.snapshot->entries, library.filter);
  return shown;
}

namespace {

bool librarySameWords(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

std::optional<LibraryEntry> findShownLibraryEntry(const LibraryBrowserState& library,
                                                  const std::string& name) {
  const ShownLibrary shown = shownLibraryEntries(library);
  for (const std::size_t i : shown.indices) {
    const LibraryEntry& entry = shown.snapshot->entries[i];
    if (librarySameWords(entry.fileName, name) ||
        librarySameWords(entry.path.stem().string(), name) || librarySameWords(entry.name, name))
      return entry;
  }
  return std::nullopt;
}

}  // namespace lenslab::app
