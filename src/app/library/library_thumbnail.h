#pragma once
// The library browser's thumbnails: a lens's cross-section with its ray fans, drawn as the slide
// export draws it (slide_layout.h, slide_raster.h) but small and without labels, in the panel's
// colours; and their cache on disk, in the user's cache folder, keyed by the lens file's content
// hash, so that a library opened again shows its pictures at once. No GL: made off the UI thread
// (library_catalogue.h), uploaded by the panel.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/drawing/slide_raster.h"
#include "optics/lens_system.h"

namespace lenslab::app {

// Bumped whenever the pictures change (colours, fans, layout), so that old cached files are not
// shown: it is part of the cache's file names.
inline constexpr int kThumbnailStyleVersion = 1;

// The lens's cross-section at `widthPx` x `heightPx`: its outline, stop and film, and fans at the
// axis, 0.7 and the full field of `filmHalfDiagonalMm`, from infinity.
SlideImage drawLibraryThumbnail(const optics::LensSystem& system, double filmHalfDiagonalMm,
                                int widthPx, int heightPx, const SlideFont& font);

// $XDG_CACHE_HOME/lenslab/thumbnails, else ~/.cache/lenslab/thumbnails; empty when neither is
// known (no cache on disk then).
std::filesystem::path thumbnailCacheDirectory();

// The cached picture's file: "<hash>-<w>x<h>-v<style>.png".
std::filesystem::path thumbnailCachePath(const std::filesystem::path& directory,
                                         std::uint64_t contentHash, int widthPx, int heightPx);

// The cached picture, when the file is there and of that size; nullopt otherwise (a damaged file
// is drawn again and rewritten).
std::optional<SlideImage> readCachedThumbnail(const std::filesystem::path& path, int widthPx,
                                              int heightPx);
// Writes it atomically (creating the folder); "" or the error.
std::string writeCachedThumbnail(const std::filesystem::path& path, const SlideImage& image);

}  // namespace lenslab::app
