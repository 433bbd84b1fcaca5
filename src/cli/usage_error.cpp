#include "cli/usage_error.h"

#include <cstdio>

#include "common/diagnostics.h"

namespace lenslab::cli {

void printUsageError(const std::string& command, const std::string& message) {
  // An option's value is quoted in the message: a 10-million-digit one is shortened.
  std::fprintf(stderr, "%s: %s\nRun '%s --help' for its options.\n", command.c_str(),
               abbreviateMessage(message).c_str(), command.c_str());
}

}  // namespace lenslab::cli
