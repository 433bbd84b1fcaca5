#pragma once
// `lenslab analyze LENS [--json] [--film-distance MM | --object-distance MM|inf]
// [--film-diagonal MM] [--stop-diameter MM] [--points N]`: analyses of a lens at one film distance.
// Today: relative illumination (optics/relative_illumination.h), with the names `total`, `cos4`,
// `vignetting` and `clipped_by` that the viewer's panels use, plus `rear_disk_total`: total as the
// course scenes' rear-disk sampling integrates it. Later analyses add their own keys.

#include <CLI/CLI.hpp>

#include "cli/subcommand.h"

namespace lenslab::cli {

void addAnalyzeCommand(CLI::App& app, SubcommandRunner& run);

}  // namespace lenslab::cli
