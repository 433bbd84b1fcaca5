#include "app/log.h"

#include <cstdio>

namespace lenslab::app {

void Log::add(LogLevel level, std::string text) {
  // Errors and warnings also go to stderr, so scripted runs and tests see them.
  if (level != LogLevel::Info) {
    std::fprintf(stderr, "lenslab: %s: %s\n", level == LogLevel::Error ? "error" : "warning",
                 text.c_str());
  }
  if (entries_.size() >= kMaxEntries) entries_.erase(entries_.begin());
  entries_.push_back({level, std::move(text)});
  ++revision_;
}

}  // namespace lenslab::app
