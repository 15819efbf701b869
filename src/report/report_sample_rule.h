#pragma once
/// \file
/// The section of report.md that shows the evidence for the sample rule
/// (precompute/sample_rule.h): per transport mode, sampler and lmax of the sweep, the sampling
/// error at each measured direction count beside the SH truncation error at that lmax, the
/// smallest measured count whose sampling error is below it, and what the rule gives. A run of
/// `prt report --max-lmax 16` reproduces the rule's own measurement.

#include <string>

#include "report/report_sweep.h"

namespace prt {

/// The markdown section (heading, how to read it, one table per mode and sampler).
std::string SampleRuleSection(const ReportData& data);

/// The smallest of `samples` (ascending) whose `error` is below `limit`; 0 if none is.
int SmallestBelow(const std::vector<int>& samples, const std::vector<double>& error, double limit);

}  // namespace prt
