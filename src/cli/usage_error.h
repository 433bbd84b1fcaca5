#pragma once
// How every usage error reads: one line naming the command and the problem, then where to find
// the command's options. The whole --help text used to follow, burying the one line that matters.

#include <string>

namespace lenslab::cli {

// command is what the user typed to name it: "lenslab" or "lenslab render".
// Prints "COMMAND: MESSAGE" and "Run 'COMMAND --help' for its options." to stderr.
void printUsageError(const std::string& command, const std::string& message);

}  // namespace lenslab::cli
