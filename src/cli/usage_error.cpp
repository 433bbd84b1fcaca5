#include "cli/usage_error.h"

#include <cstdio>

namespace lenslab::cli {

void printUsageError(const std::string& command, const std::string& message) {
  std::fprintf(stderr, "%s: %s\nRun '%s --help' for its options.\n", command.c_str(),
               message.c_str(), command.c_str());
}

}  // namespace lenslab::cli
