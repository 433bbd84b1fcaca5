#pragma once
// The report functions that analysis_reports.cpp registers, one source file each.

#include "cli/analyze/analysis_report.h"

namespace lenslab::cli {

ReportPart relativeIlluminationReport(const AnalyzeContext& context);
ReportPart mtfReport(const AnalyzeContext& context);
ReportPart distortionReport(const AnalyzeContext& context);
ReportPart distortionGridReport(const AnalyzeContext& context);
ReportPart fieldCurvatureReport(const AnalyzeContext& context);
// colour slice (seidel_report.cpp, chromatic_report.cpp)
ReportPart seidelReport(const AnalyzeContext& context);
ReportPart chromaticFocalShiftReport(const AnalyzeContext& context);
ReportPart chromaticFocalShiftCurveReport(const AnalyzeContext& context);
ReportPart lateralColorReport(const AnalyzeContext& context);
ReportPart rayFanReport(const AnalyzeContext& context);
ReportPart spotReport(const AnalyzeContext& context);

}  // namespace lenslab::cli
