#include "report/report_sample_rule.h"

#include <map>

#include "core/text.h"
#include "precompute/sample_rule.h"
#include "core/markdown_table.h"

namespace prt {
namespace {

/// Sampling errors of one (mode, sampler) at one lmax, by requested sample count.
struct Column {
  std::vector<int> samples;
  std::vector<double> error;
};

std::string Percent(double v) { return Formatted("%.2g%%", 100.0 * v); }

}  // namespace

int SmallestBelow(const std::vector<int>& samples, const std::vector<double>& error, double limit) {
  for (std::size_t i = 0; i < samples.size() && i < error.size(); ++i)
    if (error[i] < limit) return samples[i];
  return 0;
}

std::string SampleRuleSection(const ReportData& d) {
  std::string s =
      "\n## Directions needed for the bands: the sample rule\n\n"
      "Without `--samples`, prt casts DefaultSamples(lmax, sampler) directions per vertex, and warns when "
      "`--samples` is below MinimumSamples(lmax, sampler) (src/precompute/sample_rule.h): the fewest directions "
      "whose sampling error stays below the SH truncation error of that lmax. How to read the tables: one row per "
      "lmax; `truncation` is the converged transport's total error at that lmax (what more bands would remove); "
      "each sample-count column is the sampling error of that many directions, marked `*` where it is below the "
      "truncation error; `measured need` is the smallest such count (`<= N` when the sweep's smallest count is already below); `rule min` and `rule default` are the "
      "rule's values. The rule is borne out where `measured need` is at most `rule min`; a need above it, or "
      "`> N` (not reached by the sweep), means the rule asks too few directions for this scene.\n";
  std::map<std::pair<std::string, std::string>, std::map<int, Column>> groups;
  for (const SweepRow& r : d.rows) {
    if (r.sampler == "closed-form") continue;
    Column& c = groups[{r.mode, r.sampler}][r.lmax];
    c.samples.push_back(r.samples);
    c.error.push_back(r.sampling.relative);
  }
  for (const auto& [key, by_lmax] : groups) {
    const ModeBaseline* base = nullptr;
    for (const auto& b : d.baselines)
      if (b.mode == key.first) base = &b;
    if (!base || by_lmax.empty()) continue;
    const Sampler sampler = SamplerFromName(key.second);
    const std::vector<int>& counts = by_lmax.begin()->second.samples;
    std::vector<std::string> head = {"lmax", "truncation"};
    for (int n : counts) head.push_back(std::to_string(n));
    head.insert(head.end(), {"measured need", "rule min", "rule default"});
    s += "\n" + key.first + ", " + key.second + " (rule: " + SampleRuleText(sampler) + ")\n\n" + MarkdownHeader(head);
    for (const auto& [lmax, column] : by_lmax) {
      if (lmax >= static_cast<int>(base->truncation.size())) continue;
      const double truncation = base->truncation[lmax];
      std::vector<std::string> row = {std::to_string(lmax), Percent(truncation)};
      for (double e : column.error) row.push_back(Percent(e) + (e < truncation ? "*" : ""));
      const int need = SmallestBelow(column.samples, column.error, truncation);
      // The sweep's smallest count already below: the need is at most that, not exactly it.
      const std::string need_text = !need                           ? "> " + std::to_string(column.samples.back())
                                    : need == column.samples.front() ? "<= " + std::to_string(need)
                                                                     : std::to_string(need);
      row.insert(row.end(), {need_text, std::to_string(MinimumSamples(lmax, sampler)),
                             std::to_string(DefaultSamples(lmax, sampler))});
      s += MarkdownRow(row);
    }
  }
  return s;
}

}  // namespace prt
