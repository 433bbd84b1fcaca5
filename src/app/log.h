#pragma once
// The log that the Log panel shows: warnings and errors with their file:line, never a modal.

#include <string>
#include <vector>

namespace lenslab::app {

enum class LogLevel { Info, Warning, Error };

struct LogEntry {
  LogLevel level;
  std::string text;
};

class Log {
 public:
  void info(std::string text) { add(LogLevel::Info, std::move(text)); }
  void warning(std::string text) { add(LogLevel::Warning, std::move(text)); }
  void error(std::string text) { add(LogLevel::Error, std::move(text)); }
  void add(LogLevel level, std::string text);

  const std::vector<LogEntry>& entries() const { return entries_; }
  void clear() { entries_.clear(); }
  // Bumped on every add, so the panel can scroll to new entries.
  unsigned long long revision() const { return revision_; }

 private:
  static constexpr std::size_t kMaxEntries = 5000;
  std::vector<LogEntry> entries_;
  unsigned long long revision_ = 0;
};

}  // namespace lenslab::app
