#pragma once
// What a fuzz target asserts beyond "no crash, no sanitizer report": a promise the code under
// test makes in its header. A broken one aborts with the message, so libFuzzer saves the input
// as a crash and the replay test (replay_main.cpp) fails on it, in both builds alike.

#include <cstdio>
#include <cstdlib>

#include "common/diagnostics.h"

namespace lenslab::fuzz {

inline void check(bool holds, const char* promise) {
  if (holds) return;
  std::fprintf(stderr, "fuzz check failed: %s\n", promise);
  std::abort();
}

// Every reader's diagnostics: an error is what a failed read says, and a success has none; each
// is located in a file and formats to one bounded line (Diagnostics abbreviates them).
inline void checkDiagnostics(const Diagnostics& diagnostics, bool succeeded) {
  check(succeeded != diagnostics.hasErrors(), "a read fails exactly when it reports an error");
  for (const Diagnostic& diagnostic : diagnostics.all()) {
    check(!diagnostic.location.file.empty(), "a diagnostic names its file");
    check(diagnostic.location.line >= 0 && diagnostic.location.column >= 0,
          "a diagnostic's line and column are not negative");
    check(!diagnostic.message.empty(), "a diagnostic says what is wrong");
    check(diagnostic.format().size() <= kMaxMessageChars + 2048,
          "a diagnostic stays a bounded line");
  }
}

}  // namespace lenslab::fuzz
