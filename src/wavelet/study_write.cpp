// The wavelet study's section of report.md, its report.csv rows and basis_error.png
// (wavelet/study.h).
#include <algorithm>
#include <cstring>

#include "core/markdown_table.h"
#include "core/text.h"
#include "raster/plot.h"
#include "wavelet/study.h"

namespace prt {
namespace {

std::string Percent(double x) { return Formatted("%.3g%%", 100.0 * x); }

std::string Setting(const BasisRow& r) {
  return r.wavelet ? Formatted("%d terms", r.budget) : Formatted("lmax %d", r.lmax);
}

/// "SH shadowed", "wavelets interreflection": the legend's room is about 26 characters.
std::string SeriesLabel(TransportMode mode, bool wavelet) {
  return std::string(wavelet ? "wavelets " : "SH ") + TransportModeName(mode);
}

/// A row's cost beside its memory: its seconds when the report's times are trusted, else its
/// directions a vertex (its work, which no busy machine changes).
std::string Cost(const BasisRow& r, bool times_trusted) {
  return times_trusted ? Formatted(" (%.0f bytes a vertex, %.3g s)", r.bytes_per_vertex, r.seconds)
                       : Formatted(" (%.0f bytes a vertex, %d directions a vertex)", r.bytes_per_vertex, r.directions);
}

/// The cheapest wavelet row of `mode` (fewest bytes) as good as SH's best, in words.
std::string EqualError(const WaveletStudy& d, TransportMode mode, bool times_trusted) {
  const BasisRow* best_sh = nullptr;
  for (const auto& r : d.rows)
    if (r.mode == mode && !r.wavelet && (!best_sh || r.total.relative < best_sh->total.relative)) best_sh = &r;
  if (!best_sh) return "";
  const BasisRow* match = nullptr;
  for (const auto& r : d.rows)
    if (r.mode == mode && r.wavelet && r.total.relative <= best_sh->total.relative &&
        (!match || r.bytes_per_vertex < match->bytes_per_vertex))
      match = &r;
  std::string s = std::string(TransportModeName(mode)) + ": SH's lowest error, " + Percent(best_sh->total.relative) +
                  " at " + Setting(*best_sh) + Cost(*best_sh, times_trusted);
  if (match)
    s += ", is reached by wavelets at " + Setting(*match) + Cost(*match, times_trusted) + ": " +
         Percent(match->total.relative) + ".";
  else
    s += "; no wavelet budget of the study reaches it.";
  return s;
}

}  // namespace

std::string WaveletMarkdown(const WaveletStudy& d, bool times_trusted) {
  const WaveletStudyConfig& c = d.config;
  std::string s = "\n## Basis: spherical harmonics against Haar wavelets\n\n";
  s += "Scene: " + d.scene + " (" + std::to_string(d.vertices) + " vertices), environment `" + d.environment +
       "`, seen whole (no camera: every vertex counts). Error: relative RMS over vertices and channels of the outgoing "
       "radiance against prt reference (the table below it gives its directions, seconds and own error). " +
       Formatted("SH: fibonacci, %d directions per vertex at every lmax; memory (lmax+1)^2 floats per channel (one "
                 "channel shadowed, three with interreflection, whose bounces are coloured). ",
                 c.sh_samples) +
       Formatted("Wavelets: Haar on a cube of 6 x %d^2 texels, %d jittered rays a texel, each vertex keeping its N "
                 "most important coefficients (N the budget, the six faces' means among them; %s-weighted; zeros "
                 "never kept, so a vertex may keep fewer); memory as the transport stores them (the means as "
                 "floats, each other coefficient a 16-bit index and a 16-bit value, a step and an offset per "
                 "vertex: wavelet/transport.h)",
                 c.face_size, c.split * c.split, SelectionName(c.selection)) +
       Formatted("; with interreflection the bounced light in SH at lmax %d from %d directions, its 3 x %d floats "
                 "counted in the bytes. ",
                 c.bounce_lmax, c.sh_samples, CoeffCount(c.bounce_lmax)) +
       "Directions a vertex: SH's directions per vertex (the half below a vertex's horizon cost no ray); the "
       "wavelets' rays traced per vertex on average, " + std::to_string(c.split * c.split) + " a texel over the "
       "texels above its horizon (about half of the cube's " + std::to_string(6 * c.face_size * c.face_size) +
       "). Seconds: the whole transport (BVH build, rays, transform and selection, bounce "
       "pass), the fastest of repeats lasting 0.05 s together" +
       (times_trusted ? std::string(". ")
                      : std::string(", **not trusted** (the timing section above says why): the comparison below "
                                    "and basis_error.png's right panel use the directions instead. ")) +
       "The light is the unturned environment with every coefficient kept. basis_error.png plots the error against "
       "bytes per vertex (left) and against " + (times_trusted ? "seconds" : "directions a vertex") + " (right).\n\n";
  s += MarkdownHeader({"mode", "reference directions", "reference seconds", "reference own error"});
  for (const auto& r : d.references)
    s += MarkdownRow({TransportModeName(r.mode), std::to_string(r.samples), Formatted("%.2f", r.seconds),
                      Percent(r.own_error)});
  s += "\n" + MarkdownHeader({"mode", "basis", "lmax / budget", "coefficients kept per vertex", "bytes per vertex",
                              "directions a vertex", times_trusted ? "precompute seconds" : "precompute seconds (not trusted)",
                              "relative RMS error", "max error", "transport energy kept"});
  for (const auto& r : d.rows) {
    const std::string kept = r.wavelet ? Formatted("%.0f", r.kept) : std::to_string(CoeffCount(r.lmax));
    s += MarkdownRow({TransportModeName(r.mode), r.wavelet ? "wavelet" : "SH", Setting(r), kept,
                      Formatted("%.0f", r.bytes_per_vertex), std::to_string(r.directions), Formatted("%.3g", r.seconds),
                      Percent(r.total.relative), Formatted("%.3g", r.total.max),
                      r.wavelet ? Percent(r.kept_energy) : std::string("-")});
  }
  s += "\n";
  for (TransportMode mode : c.modes) {
    const std::string line = EqualError(d, mode, times_trusted);
    if (!line.empty()) s += line + "\n\n";
  }
  s += "SH keeps the low frequencies of every vertex's transport, so a small sun's shadow edge, which no low band "
       "holds, stays blurred at any affordable lmax; the wavelets keep each vertex's own largest coefficients, so "
       "the fine ones where its shadow edge lies.\n";
  return s;
}

std::string WaveletCsvRows(const WaveletStudy& d) {
  std::string s;
  // mode,sampler,samples,directions,lmax,seconds,sampling x3,total x3,psnr,material,path,lobe_relative,
  // vs_vector_relative,matrix_bytes,basis,budget,bytes_per_vertex
  const WaveletStudyConfig& c = d.config;
  for (const auto& r : d.rows) {
    const int samples = r.wavelet ? 6 * c.face_size * c.face_size * c.split * c.split : c.sh_samples;
    s += Formatted("%s,%s,%d,%d,%d,%.6g,,,,%.6g,%.6g,%.6g,,diffuse,%s,,,,%s,", TransportModeName(r.mode),
                   r.wavelet ? "cube-jittered" : "fibonacci", samples, r.directions, r.lmax, r.seconds, r.total.rms,
                   r.total.max, r.total.relative, r.wavelet ? "basis-wavelet" : "basis-sh", r.wavelet ? "wavelet" : "sh") +
         (r.wavelet ? std::to_string(r.budget) : std::string()) + Formatted(",%.6g\n", r.bytes_per_vertex);
  }
  return s;
}

Image8 WaveletPlot(const WaveletStudy& d, bool times_trusted) {
  std::vector<PlotSeries> by_bytes, by_seconds;
  for (std::size_t m = 0; m < d.config.modes.size(); ++m) {
    const TransportMode mode = d.config.modes[m];
    for (bool wavelet : {false, true}) {
      PlotSeries b;
      b.label = SeriesLabel(mode, wavelet);
      b.color = PlotColor(wavelet ? 1 : 0);
      b.dashed = m > 0;
      PlotSeries t = b;
      for (const auto& r : d.rows)
        if (r.mode == mode && r.wavelet == wavelet) {
          b.x.push_back(r.bytes_per_vertex), b.y.push_back(r.total.relative);
          t.x.push_back(times_trusted ? r.seconds : double(r.directions)), t.y.push_back(r.total.relative);
        }
      if (b.x.empty()) continue;
      by_bytes.push_back(b);
      by_seconds.push_back(t);
    }
  }
  PlotOptions o;
  o.width = 1000, o.height = 680;
  o.title = "error vs transport memory";
  o.x_label = "bytes per vertex";
  o.y_label = "relative RMS error";
  const Image8 left = DrawLogLogPlot(by_bytes, o);
  o.title = times_trusted ? "error vs precompute time" : "error vs work (times not trusted)";
  o.x_label = times_trusted ? "seconds" : "directions per vertex";
  const Image8 right = DrawLogLogPlot(by_seconds, o);
  // The two panels side by side, on one image.
  Image8 both(left.width + right.width, std::max(left.height, right.height));
  std::fill(both.rgb.begin(), both.rgb.end(), std::uint8_t(255));
  for (int y = 0; y < both.height; ++y) {
    std::uint8_t* row = both.rgb.data() + std::size_t(y) * both.width * 3;
    if (y < left.height) std::memcpy(row, left.rgb.data() + std::size_t(y) * left.width * 3, std::size_t(left.width) * 3);
    if (y < right.height)
      std::memcpy(row + std::size_t(left.width) * 3, right.rgb.data() + std::size_t(y) * right.width * 3,
                  std::size_t(right.width) * 3);
  }
  return both;
}

}  // namespace prt
