#pragma once
// The report functions that analysis_reports.cpp registers, one source file each.

#include "cli/analyze/analysis_report.h"

namespace lenslab::cli {

ReportPart relativeIlluminationReport(const AnalyzeContext& context);
ReportPart mtfReport(const AnalyzeContext& context);

}  // namespace lenslab::cli
