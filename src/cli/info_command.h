#pragma once
// `lenslab info LENS [--json] [--wavelength NM] [--film-diagonal MM]`: first-order data.

#include <CLI/CLI.hpp>

#include "cli/subcommand.h"

namespace lenslab::cli {

void addInfoCommand(CLI::App& app, SubcommandRunner& run);

}  // namespace lenslab::cli
