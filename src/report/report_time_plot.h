#pragma once
/// \file
/// error_vs_time.png and the timing paragraph of report.md: how `prt report` shows its times
/// (report_sweep.h, round_robin_timing.h).
///
/// The plot has one panel per sampled transport mode (shadowed, and interreflection when the
/// sweep ran it), total error against run time: colour tells the lmax apart, the marker's shape
/// the sampler (square uniform, circle stratified, triangle fibonacci; stratified also dashed),
/// each point carries its timing range (min - max of its samples) as a horizontal bar, and the
/// points of lmax below the sweep's max_lmax, whose time is that run's (the same directions give
/// the same first coefficients), are hollow. When the times are not trusted (TimesTrusted) the
/// x axis is the work instead, rays traced per run, and the panel's title says so.

#include <string>
#include <vector>

#include "core/image.h"
#include "raster/plot.h"
#include "report/report_sweep.h"

namespace prt {

/// The series of the panel of `mode`: one per (sampler, lmax) in the order first met, x the
/// median seconds with their range, or (`seconds` false) the rays traced; y the total error.
std::vector<PlotSeries> ErrorVsTimeSeries(const ReportData& data, const std::string& mode, bool seconds);

/// error_vs_time.png.
Image8 ErrorVsTimePlot(const ReportData& data);

/// report.md's "Timing" section: how the times were taken, the largest spread, the work-order
/// check and, when they fail, a warning that the slopes against seconds are left out.
std::string TimingMarkdown(const ReportData& data);

/// The warning report.md opens with when the times are not trusted; empty when they are.
std::string TimingWarning(const ReportData& data);

/// "0.124 s (0.12-0.13)": a median with its range.
std::string TimeWithRange(const TimingStats& t);

}  // namespace prt
