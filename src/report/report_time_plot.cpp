#include "report/report_time_plot.h"

#include <map>
#include <utility>
#include <vector>

#include "core/text.h"
#include "raster/plot.h"

namespace prt {
namespace {

PlotMarker SamplerMarker(const std::string& sampler) {
  if (sampler == "uniform") return PlotMarker::kSquare;
  if (sampler == "stratified") return PlotMarker::kCircle;
  return PlotMarker::kTriangle;
}

/// One panel: the rows of `mode`.
Image8 ModePanel(const ReportData& d, const std::string& mode, bool seconds) {
  int samples = 0;
  for (const SweepRow& r : d.rows)
    if (r.mode == mode) samples = r.time.samples;
  PlotOptions o;
  o.width = 1100, o.height = 720;
  o.title = mode + ": total error vs " + (seconds ? "precompute time" : "rays traced (times untrusted)");
  o.x_label = seconds ? "seconds (median; bars: min-max)" : "rays traced per run";
  o.y_label = "relative RMS error";
  o.notes = {"square uniform, circle", "stratified, triangle fibonacci",
             Formatted("hollow: lmax < %d, its", d.max_lmax), Formatted("time and rays the lmax %d", d.max_lmax),
             "run's (same directions)"};
  if (seconds) o.notes.push_back(Formatted("bars: %d samples each", samples));
  return DrawLogLogPlot(ErrorVsTimeSeries(d, mode, seconds), o);
}

}  // namespace

std::vector<PlotSeries> ErrorVsTimeSeries(const ReportData& d, const std::string& mode, bool seconds) {
  std::vector<PlotSeries> series;
  std::map<std::pair<std::string, int>, std::size_t> index;
  for (const SweepRow& r : d.rows) {
    if (r.mode != mode || r.sampler == "closed-form") continue;
    const auto key = std::make_pair(r.sampler, r.lmax);
    if (!index.count(key)) {
      index[key] = series.size();
      PlotSeries p;
      p.label = r.sampler + " lmax " + std::to_string(r.lmax);
      p.color = PlotColor(r.lmax - 1);
      p.marker = SamplerMarker(r.sampler);
      p.dashed = r.sampler == "stratified";
      p.hollow = r.lmax < r.timed_lmax;
      series.push_back(p);
    }
    PlotSeries& p = series[index[key]];
    p.x.push_back(seconds ? r.time.median : double(r.rays));
    if (seconds) p.x_min.push_back(r.time.min), p.x_max.push_back(r.time.max);
    p.y.push_back(r.total.relative);
  }
  return series;
}

Image8 ErrorVsTimePlot(const ReportData& d) {
  std::vector<std::string> modes;
  for (const SweepRow& r : d.rows)
    if (r.sampler != "closed-form" && (modes.empty() || modes.back() != r.mode)) modes.push_back(r.mode);
  const bool seconds = TimesTrusted(d);
  std::vector<Image8> panels;
  for (const std::string& m : modes) panels.push_back(ModePanel(d, m, seconds));
  if (panels.empty()) panels.push_back(DrawLogLogPlot({}, PlotOptions{}));
  return StackVertically(panels);
}

std::string TimeWithRange(const TimingStats& t) {
  return Formatted("%.3g s (%.3g-%.3g)", t.median, t.min, t.max);
}

std::string TimingMarkdown(const ReportData& d) {
  const auto [spread, whose] = LargestSpread(d);
  int rounds = 0;
  for (const SweepRow& r : d.rows) rounds = std::max(rounds, r.time.samples);
  std::string s = "\n## Timing\n\n";
  s += Formatted("All %d configurations (the sampled transports, the closed form and the light projections) were "
                 "timed together in round robin: one untimed run each, then %d rounds of one sample each (at least "
                 "%d, more while a spread exceeded %.0f%%), a run under %.0f ms repeated within its sample "
                 "(round_robin_timing.h), so a burst of other work slows a round of all of them rather than a few. ",
                 d.timed_configurations, rounds, d.timing.min_rounds, 100.0 * d.timing.spread_limit,
                 1000.0 * d.timing.min_sample_seconds) +
       "A time is the median of its samples, with their range (min-max) in parentheses here, in report.csv "
       "(`seconds`, `seconds_min`, `seconds_max`) and as bars in error_vs_time.png. Work is counted beside the "
       "seconds: rays traced and directions whose basis was evaluated per run (report.csv `rays`, "
       "`basis_evaluations`), which no other work on the machine changes.\n\n";
  s += Formatted("- Largest spread (interquartile range / median: the middle half of the samples, which one slow "
                 "sample does not move): %.0f%%", 100.0 * spread) +
       (whose.empty() ? std::string() : " (" + whose + ")") +
       Formatted("; above %.0f%% the times are called noisy.\n", 100.0 * kTrustedSpread);
  if (d.order_violations.empty()) {
    s += "- Work order: time grows with work. No run with at least twice the rays of another of its mode and "
         "sampler (or the texels of another light projection) was faster beyond their ranges.\n";
  } else {
    s += Formatted("- Work order: **%zu pairs out of order**, e.g.", d.order_violations.size());
    for (std::size_t i = 0; i < std::min<std::size_t>(3, d.order_violations.size()); ++i) {
      const OrderViolation& v = d.order_violations[i];
      s += Formatted(" %s %s at most %.3g s against %s at least %.3g s;", v.group.c_str(), v.more.c_str(), v.more_max,
                     v.less.c_str(), v.less_min);
    }
    s.back() = '.';
    s += "\n";
  }
  s += TimesTrusted(d) ? "- The slopes against seconds below are fitted to the medians; error_vs_time.png plots "
                         "seconds.\n"
                       : "- So the slopes against seconds and the times to 1% are left out below, and "
                         "error_vs_time.png plots the error against rays traced instead of seconds.\n";
  return s;
}

std::string TimingWarning(const ReportData& d) {
  if (TimesTrusted(d)) return "";
  return "**The times of this run are not trustworthy** (see Timing: the spread or the work order). The machine "
         "was probably busy; the errors and the work counts hold, the seconds do not. Rerun on an idle machine "
         "for times.\n\n";
}

}  // namespace prt
