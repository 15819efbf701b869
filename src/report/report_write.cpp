#include "report/report_write.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "core/atomic_file.h"
#include "core/log.h"
#include "io/png_io.h"
#include "raster/plot.h"
#include "core/markdown_table.h"
#include "report/report_noise.h"
#include "report/report_sample_rule.h"
#include "report/report_time_plot.h"

namespace prt {
namespace {

std::string F(const char* fmt, double v) {
  char b[64];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

constexpr double kTarget = 0.01;  // "1% error": relative RMS

/// Where a "time to 1%" cell begins: the run's median time and range, then its work; only the
/// work when the times are not trusted.
std::string When(const SweepRow& r, bool trusted) { return trusted ? TimeWithRange(r.time) + ", " : ""; }

/// The timing columns, last on every line (empty on the glossy and basis rows, whose times are
/// single runs of their own studies).
constexpr const char* kTimingColumns = "seconds_min,seconds_max,timing_samples,timed_lmax,rays,basis_evaluations";
constexpr const char* kNoTiming = ",,,,,,";  // a comma and the six columns, empty

std::string TimingFields(const SweepRow& r) {
  char b[200];
  std::snprintf(b, sizeof b, "%.6g,%.6g,%d,%d,%llu,%llu", r.time.min, r.time.max, r.time.samples, r.timed_lmax,
                static_cast<unsigned long long>(r.rays), static_cast<unsigned long long>(r.basis_evaluations));
  return b;
}

/// Every line of `rows` (each ending in a newline) with `suffix` before its newline.
std::string EachLineEndingWith(const std::string& rows, const std::string& suffix) {
  std::string out;
  for (std::size_t begin = 0, end; begin < rows.size(); begin = end + 1) {
    end = std::min(rows.find('\n', begin), rows.size());
    out += rows.substr(begin, end - begin) + suffix + "\n";
  }
  return out;
}

std::string Csv(const ReportData& d) {
  // With the basis section, three more columns: every row before its rows is an SH one.
  const std::string basis = d.basis_study ? ",sh,," : "";
  std::string s = std::string("mode,sampler,samples,directions,lmax,seconds,sampling_rms,sampling_max,sampling_relative,"
                              "total_rms,total_max,total_relative,psnr_db,material,path,lobe_relative,vs_vector_relative,"
                              "matrix_bytes") +
                  (d.basis_study ? ",basis,budget,bytes_per_vertex" : "") + "," + kTimingColumns + "\n";
  for (const auto& r : d.rows) {
    char b[400];
    std::snprintf(b, sizeof b, "%s,%s,%d,%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,diffuse,diffuse,,,", r.mode.c_str(),
                  r.sampler.c_str(), r.samples, r.directions, r.lmax, r.time.median, r.sampling.rms, r.sampling.max,
                  r.sampling.relative, r.total.rms, r.total.max, r.total.relative, r.psnr);
    s += b + basis + "," + TimingFields(r) + "\n";
  }
  if (d.glossy) s += EachLineEndingWith(GlossyCsvRows(*d.glossy), basis + kNoTiming);
  if (d.basis_study) s += EachLineEndingWith(d.basis_study->CsvRows(), kNoTiming);
  return s;
}

const ModeBaseline* BaselineOf(const ReportData& d, const std::string& mode) {
  for (const auto& b : d.baselines)
    if (b.mode == mode) return &b;
  return nullptr;
}

std::string Markdown(const ReportData& d) {
  const int l2 = std::min(2, d.max_lmax);
  std::string s = "# prt report: error against run time\n\n" + TimingWarning(d);
  s += "Scene: " + d.scene + " (" + std::to_string(d.vertices) + " vertices), environment `" + d.environment +
       "`. Errors are relative RMS over vertices and channels of the outgoing radiance (`sampling`: against the "
       "converged transport at the same lmax; `total`: against the ground truth, SH truncation included). Seconds "
       "are measured transport time of the run at lmax " +
       std::to_string(d.max_lmax) +
       "; lower lmax rows reuse its first (l+1)^2 coefficients, which a run at that lmax computes identically "
       "from the same directions, and so its time and rays (hollow markers in error_vs_time.png). What remains "
       "flat at the smallest counts is fixed cost (the BVH build, " + F("%.3g s", d.bvh_seconds) +
       " of every sampled run, and starting the threads), so there the first points of a curve crowd together at "
       "nearly one time.\n" + TimingMarkdown(d) + "\n";
  s += "## Baselines\n\n" + MarkdownHeader({"mode", "reference directions", "reference seconds",
                                              "reference own RMS error", "converged directions", "converged seconds",
                                              "converged vs half-size run"});
  for (const auto& b : d.baselines)
    s += MarkdownRow({b.mode, std::to_string(b.reference_samples), F("%.2f", b.reference_seconds),
                      F("%.3g%%", 100.0 * b.reference_rms_error / std::max(b.reference_rms_radiance, 1e-300)),
                      b.converged_samples ? std::to_string(b.converged_samples) : std::string("closed form"),
                      F("%.2f", b.converged_seconds), F("%.3g%%", 100.0 * b.converged_self_error)});

  // Slopes and time to 1%, per mode and sampler; against seconds only when the times hold.
  const bool trusted = TimesTrusted(d);
  std::map<std::pair<std::string, std::string>, std::vector<const SweepRow*>> groups;
  for (const auto& r : d.rows)
    if (r.lmax == l2 && r.sampler != "closed-form") groups[{r.mode, r.sampler}].push_back(&r);
  s += "\n## Convergence at lmax " + std::to_string(l2) +
       "\n\nSlopes: least-squares fit of log(sampling error) against log(seconds) and log(directions), over rows "
       "whose error is at least 3x the converged result's own noise. Time to 1%: the first measured run whose "
       "relative error is at most 1%, its median time with the range of its samples (only its directions when the "
       "times are untrusted).\n\n" +
       MarkdownHeader({"mode", "sampler", "slope vs seconds", "slope vs directions", "time to 1% sampling error",
                       "time to 1% total error (any lmax)"});
  for (const auto& [key, rows] : groups) {
    const ModeBaseline* b = BaselineOf(d, key.first);
    const double floor = b ? 3.0 * b->converged_self_error : 0.0;
    std::vector<double> t, n, e;
    std::string to_sampling = "not reached";
    for (const SweepRow* r : rows) {
      if (r->sampling.relative >= floor) t.push_back(r->time.median), n.push_back(r->directions), e.push_back(r->sampling.relative);
      if (to_sampling == "not reached" && r->sampling.relative <= kTarget)
        to_sampling = When(*r, trusted) + std::to_string(r->directions) + " dirs";
    }
    std::string to_total = "not reached";
    double best = std::numeric_limits<double>::infinity();
    for (const auto& r : d.rows)
      if (r.mode == key.first && r.sampler == key.second) {
        best = std::min(best, r.total.relative);
        if (r.total.relative <= kTarget && to_total == "not reached")
          to_total = When(r, trusted) + std::to_string(r.directions) + " dirs, lmax " + std::to_string(r.lmax);
      }
    if (to_total == "not reached") to_total += F(" (lowest %.3g%%)", 100.0 * best);
    s += MarkdownRow({key.first, key.second, trusted ? F("%.2f", LogLogSlope(t, e)) : "left out (times untrusted)",
                      F("%.2f", LogLogSlope(n, e)), to_sampling, to_total});
  }

  s += "\n## Truncation: total error against lmax (highest sample count of each sampler)\n\n" +
       MarkdownHeader({"mode", "sampler", "lmax", "total relative", "total max", "PSNR dB"});
  for (std::size_t i = 0; i < d.rows.size(); ++i) {
    const auto& r = d.rows[i];
    const bool last = i + d.max_lmax >= d.rows.size() || d.rows[i + d.max_lmax].sampler != r.sampler ||
                      d.rows[i + d.max_lmax].mode != r.mode;
    if (!last) continue;
    s += MarkdownRow({r.mode, r.sampler, std::to_string(r.lmax), F("%.3g%%", 100 * r.total.relative),
                      F("%.3g", r.total.max), F("%.1f", r.psnr)});
  }
  if (d.max_lmax >= 3 && std::any_of(d.rows.begin(), d.rows.end(), [](const SweepRow& r) { return r.sampler == "closed-form"; }))
    s += "\nUnshadowed, lmax 2 and 3 (and 4 and 5, 6 and 7) have the same error, and that is right: the "
         "unshadowed transfer of a vertex is the clamped cosine max(0, n.s), whose SH coefficients vanish in every "
         "odd band above 1 (Ramamoorthi and Hanrahan, \"An Efficient Representation for Irradiance Environment "
         "Maps\", SIGGRAPH 2001), so bands 3, 5, 7 add nothing to it, whatever the light holds there. Shadows "
         "(visibility) give the transfer odd bands, so the sampled modes change at every lmax.\n";

  s += SampleRuleSection(d);
  s += "\n## Light projection against cubemap resolution\n\nThe environment averaged into cubemaps, each texel "
       "holding the mean over its solid angle of sub-texel samples (as a filtered cubemap stores it), projected to "
       "lmax " + std::to_string(d.max_lmax) +
       " and compared with its exact projection (relative L2 over all coefficients). Texel-centre samples would "
       "instead catch the sky's sun disk (2 degrees in radius by default) on a texel centre at some face sizes and "
       "miss it at others, so the error would jump up and down with the size instead of falling.\n\n" +
       MarkdownHeader({"face size", "sub-texels", "seconds (median, min-max)", "coefficient error"});
  for (const auto& l : d.light)
    s += MarkdownRow({std::to_string(l.face_size), std::to_string(l.supersample) + "^2", TimeWithRange(l.time),
                      F("%.3g", l.coeff_error)});
  if (d.glossy) s += GlossyMarkdown(*d.glossy);
  if (d.basis_study) s += d.basis_study->Markdown(TimesTrusted(d));
  if (d.noise) s += NoiseMarkdown(*d.noise);
  const std::size_t glossy_rows =
      d.glossy ? d.glossy->vector_rows.size() + d.glossy->matrix_rows.size() + (d.glossy->cpca ? d.glossy->cpca->rows.size() : 0)
               : 0;
  const std::size_t basis_rows = d.basis_study ? d.basis_study->RowCount() : 0;
  s += "\n## All measurements\n\nSee report.csv (" + std::to_string(d.rows.size() + glossy_rows + basis_rows) +
       " rows; the glossy ones have material phong:N,KS and path glossy-vector, glossy-matrices or glossy-cpca-CxK "
       "(clustered PCA against the full matrices: sampling_relative the matrices' Frobenius error, seconds the "
       "compression, matrix_bytes the compressed bytes)" +
       (d.basis_study ? "; the basis section's have path " + d.basis_study->CsvPaths() +
                            " and the columns basis, budget and bytes_per_vertex"
                      : std::string()) +
       ") and error_vs_time.png" + (d.glossy ? ", glossy_error_vs_lmax.png" : "") +
       (d.basis_study ? ", basis_error.png" : "") + ".\n";
  return s;
}

}  // namespace

void WriteReport(OutputFolder& folder, const ReportData& d) {
  WriteFileAtomic(folder.Output("report.csv"), Csv(d));
  WriteFileAtomic(folder.Output("report.md"), Markdown(d));
  WritePng(folder.Output("error_vs_time.png"), ErrorVsTimePlot(d));
  if (d.glossy) WritePng(folder.Output("glossy_error_vs_lmax.png"), GlossyPlot(*d.glossy));
  if (d.basis_study) WritePng(folder.Output("basis_error.png"), d.basis_study->Plot(TimesTrusted(d)));
  Summary("wrote " + folder.dir() + "/report.csv, report.md and error_vs_time.png" +
          (d.glossy ? std::string(" and glossy_error_vs_lmax.png") : std::string()) +
          (d.basis_study ? std::string(" and basis_error.png") : std::string()));
}

}  // namespace prt
