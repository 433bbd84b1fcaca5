#include "app/library/library_catalogue.h"

#include "app/library/library_thumbnail.h"

#include <chrono>

namespace lenslab::app {

LibraryCatalogue::LibraryCatalogue(Options options)
    : options_(std::move(options)),
      snapshot_(std::make_shared<const Snapshot>()),
      worker_([this] { run(); }) {}

LibraryCatalogue::~LibraryCatalogue() {
  stopping_ = true;
  worker_.join();
}

std::shared_ptr<const LibraryCatalogue::Snapshot> LibraryCatalogue::snapshot(
    std::uint64_t* revision) const {
  std::lock_guard lock(mutex_);
  if (revision) *revision = revision_;
  return snapshot_;
}

std::vector<LibraryCatalogue::Thumbnail> LibraryCatalogue::takeThumbnails() {
  std::lock_guard lock(mutex_);
  return std::exchange(finished_, {});
}

void LibraryCatalogue::publish(const Snapshot& next) {
  {
    std::lock_guard lock(mutex_);
    snapshot_ = std::make_shared<const Snapshot>(next);
    ++revision_;
  }
  if (options_.published) options_.published();
}

void LibraryCatalogue::run() {
  const auto started = std::chrono::steady_clock::now();
  const auto msSinceStart = [&] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
        .count();
  };
  Snapshot state;
  const std::vector<std::filesystem::path> files = listLibraryFiles(options_.folder);
  state.files = files.size();
  publish(state);
  // The lenses as built, for their thumbnails after the list is complete: the list comes first,
  // as it is what a user reads and filters.
  std::vector<std::shared_ptr<const optics::LensSystem>> systems;
  for (const std::filesystem::path& path : files) {
    if (stopping_) return;
    std::shared_ptr<const optics::LensSystem> system;
    state.entries.push_back(readLibraryEntry(path, &system));
    systems.push_back(std::move(system));
    publish(state);
  }
  state.listed = true;
  state.listedAfterMs = msSinceStart();
  publish(state);

  std::unique_ptr<SlideFont> font;  // the rasteriser's; built when a thumbnail is first drawn
  const int width = options_.thumbnailWidthPx, height = options_.thumbnailHeightPx;
  for (std::size_t i = 0; i < state.entries.size() && width > 0 && height > 0; ++i) {
    if (stopping_) return;
    const LibraryEntry& entry = state.entries[i];
    if (!systems[i] || options_.known.count(entry.contentHash)) continue;
    Thumbnail thumbnail{entry.contentHash, {}};
    const std::filesystem::path cached =
        options_.cacheDirectory.empty()
            ? std::filesystem::path()
            : thumbnailCachePath(options_.cacheDirectory, entry.contentHash, width, height);
    if (auto image = cached.empty() ? std::nullopt : readCachedThumbnail(cached, width, height)) {
      thumbnail.image = std::move(*image);
      ++state.thumbnailsFromDisk;
    } else {
      if (!font) font = std::make_unique<SlideFont>();
      thumbnail.image =
          drawLibraryThumbnail(*systems[i], entry.fansHalfDiagonalMm, width, height, *font);
      ++state.thumbnailsDrawn;
      // A cache that cannot be written costs the next start the drawing, nothing else.
      if (!cached.empty()) writeCachedThumbnail(cached, thumbnail.image);
    }
    options_.known.insert(entry.contentHash);
    {
      std::lock_guard lock(mutex_);
      finished_.push_back(std::move(thumbnail));
    }
    publish(state);
  }
  state.finished = true;
  state.finishedAfterMs = msSinceStart();
  publish(state);
}

}  // namespace lenslab::app
