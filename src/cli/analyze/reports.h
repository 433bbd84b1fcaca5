#pragma once
// The report functions that analysis_reports.cpp registers, one source file each.

#include "cli/analyze/analysis_report.h"

namespace lenslab::cli {

ReportPart relativeIlluminationReport(const AnalyzeContext& context);
ReportPart rayFanReport(const AnalyzeContext& context);
ReportPart spotReport(const AnalyzeContext& context);

}  // namespace lenslab::cli
