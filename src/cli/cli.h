#pragma once

namespace lenslab::cli {

// Parses the command line and runs the viewer or a headless subcommand; returns the exit code.
// Usage errors exit 2 after printing one line and the command's --help hint (usage_error.h).
int run(int argc, char** argv);

}  // namespace lenslab::cli
