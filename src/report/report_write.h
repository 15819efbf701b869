#pragma once
/// \file
/// Writing the report of report_sweep.h: DIR/report.csv (one row per measurement),
/// DIR/report.md (tables, fitted log-log slopes of error against seconds and against samples
/// per sampler, the time each sampler needs to reach 1% error, the light-projection table) and
/// DIR/error_vs_time.png (raster/plot.h). The slope is the least-squares fit of log error
/// against log seconds; only rows whose error is at least 3x the converged result's own noise
/// enter it, so the fit measures the sampler and not the noise floor.

#include <string>

#include "core/output_folder.h"
#include "report/report_sweep.h"

namespace prt {

/// Writes the three files into `folder`, each atomically.
void WriteReport(OutputFolder& folder, const ReportData& data);

}  // namespace prt
