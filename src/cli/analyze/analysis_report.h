#pragma once
// The analyses `lenslab analyze` can run, registered once. Each is a key of the JSON output (and
// of `--only`), a line of help, and a function from the lens and setup to its JSON value and its
// part of the readable summary. Adding an analysis is one file (its report) and one line in
// analysis_reports.cpp; option parsing, `--only`, the JSON document and the exit status follow
// from the registry.

#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cli/json_numbers.h"
#include "common/formatted.h"
#include "common/units.h"
#include "optics/analysis/field_point.h"
#include "optics/lens_system.h"

namespace lenslab::cli {

// Everything an analysis is asked for: the lens at its film distance, stop and wavelength, and
// the fields and object (optics/analysis/field_point.h).
struct AnalyzeContext {
  std::string lensPath;
  std::shared_ptr<const optics::LensSystem> lens;
  optics::AnalysisSetup setup;
  int points = 64;  // samples along a curve from the axis to the film corner
};

struct ReportPart {
  // The key's value; nullopt leaves the key out (the chromatic keys of a lens without V_d).
  std::optional<nlohmann::json> json;
  std::string text;  // its part of the readable summary, lines ending in '\n'
};

// Thrown by a report that cannot run at all (no light on the axis, an afocal lens): `analyze`
// prints the message, sets the key to null with the message under "unavailable", and exits 1.
class AnalysisUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct AnalysisReport {
  const char* key;   // the JSON key and the `--only` name
  const char* what;  // one line for --help
  ReportPart (*run)(const AnalyzeContext& context);
};

// Every analysis, in the order the JSON and the summary list them.
std::span<const AnalysisReport> analysisReports();
const AnalysisReport* findAnalysisReport(std::string_view key);

}  // namespace lenslab::cli
