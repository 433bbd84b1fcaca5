#pragma once
// `lenslab glass NAME [--maker M] [--wavelength NM ...] [--json]`: one catalogue glass, its
// formula and range, n_d and V_d, and its index at the wavelengths asked for.
// `lenslab glass --list [--maker M] [--json]`: the catalogues' glasses (name, maker, n_d, V_d).

#include <CLI/CLI.hpp>

#include "cli/subcommand.h"

namespace lenslab::cli {

void addGlassCommand(CLI::App& app, SubcommandRunner& run);

}  // namespace lenslab::cli
