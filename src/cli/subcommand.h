#pragma once
// How a headless subcommand plugs into the command line: its add...Command() registers the CLI11
// subcommand and, when the user names it, stores the work to run in `run`. cli.cpp then calls it
// and returns its exit code (0 ok, 1 failed, e.g. a bad input file; CLI11 usage errors exit 2).

#include <functional>

namespace lenslab::cli {

using SubcommandRunner = std::function<int()>;

}  // namespace lenslab::cli
