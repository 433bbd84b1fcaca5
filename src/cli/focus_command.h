#pragma once
// `lenslab focus LENS (--object-distance MM | --film-distance MM) [--json]`: real-ray focusing.

#include <CLI/CLI.hpp>

#include "cli/subcommand.h"

namespace lenslab::cli {

void addFocusCommand(CLI::App& app, SubcommandRunner& run);

}  // namespace lenslab::cli
