#pragma once
// The library browser's reading, off the UI thread: one worker lists the library folder, reads and
// builds each lens file into its entry (library_entry.h), publishing the entries as they come, and
// then makes each usable lens's thumbnail (library_thumbnail.h): from the cache on disk when it
// has it, else drawn and written there. The panel takes the finished thumbnails each frame and
// uploads them. No GL or ImGui here.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "app/drawing/slide_raster.h"
#include "app/library/library_entry.h"

namespace lenslab::app {

class LibraryCatalogue {
 public:
  struct Options {
    std::filesystem::path folder;
    int thumbnailWidthPx = 0, thumbnailHeightPx = 0;
    std::filesystem::path cacheDirectory;  // empty: no cache on disk
    // Thumbnails the viewer already has (by content hash): not made again.
    std::set<std::uint64_t> known;
    // Called on the worker when something new is published (the viewer wakes its loop with it).
    std::function<void()> published;
  };
  explicit LibraryCatalogue(Options options);
  // Stops the worker after the file or thumbnail it is on.
  ~LibraryCatalogue();
  LibraryCatalogue(const LibraryCatalogue&) = delete;
  LibraryCatalogue& operator=(const LibraryCatalogue&) = delete;

  struct Snapshot {
    std::vector<LibraryEntry> entries;  // read so far, in the files' order
    std::size_t files = 0;              // the folder's lens files
    bool listed = false;                // every file has its entry
    bool finished = false;              // and every usable lens its thumbnail
    std::size_t thumbnailsFromDisk = 0, thumbnailsDrawn = 0;
    // The worker's own time, from its start: to the last entry, and to the last thumbnail.
    double listedAfterMs = 0.0, finishedAfterMs = 0.0;
  };
  // The newest state (never null), and a counter that changes whenever it does.
  std::shared_ptr<const Snapshot> snapshot(std::uint64_t* revision = nullptr) const;

  struct Thumbnail {
    std::uint64_t contentHash = 0;
    SlideImage image;
  };
  // The thumbnails finished since the last call.
  std::vector<Thumbnail> takeThumbnails();

  const Options& options() const { return options_; }

 private:
  void run();
  void publish(const Snapshot& next);

  Options options_;
  mutable std::mutex mutex_;
  std::shared_ptr<const Snapshot> snapshot_;
  std::uint64_t revision_ = 0;
  std::vector<Thumbnail> finished_;
  std::atomic<bool> stopping_{false};
  std::thread worker_;  // last: started once the members it uses exist
};

}  // namespace lenslab::app
