#pragma once
// `lenslab convert IN OUT`: reads a lens in any format lenslab reads (.lens, .dat, .zmx, .seq, a
// patent's table in .txt) and writes it as lenslab's .lens or pbrt's .dat, as OUT's extension
// says. Exits 1 when IN cannot be read, or when OUT cannot hold the lens (a .dat cannot hold a
// conic, aspheric terms or a catalogue glass: the message names the first surface that does not
// fit, and nothing is written).

#include <CLI/CLI.hpp>

#include "cli/subcommand.h"

namespace lenslab::cli {

void addConvertCommand(CLI::App& app, SubcommandRunner& run);

}  // namespace lenslab::cli
