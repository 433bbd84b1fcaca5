#pragma once
// `lenslab analyze LENS [--json] [--film-distance MM] [--object-distance MM|inf]
// [--film-diagonal MM] [--stop-diameter MM] [--points N] [--fields F,F,..] [--wavelength NM]
// [--only KEY,KEY]`: analyses of a lens at one film distance. The analyses and their JSON keys
// are registered in cli/analyze/analysis_reports.cpp; each names its fields by
// field_angle_deg and image_height_mm (optics/analysis/field_point.h).

#include <CLI/CLI.hpp>

#include "cli/subcommand.h"

namespace lenslab::cli {

void addAnalyzeCommand(CLI::App& app, SubcommandRunner& run);

}  // namespace lenslab::cli
