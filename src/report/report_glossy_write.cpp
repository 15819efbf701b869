// The glossy section of report.md, its report.csv rows and glossy_error_vs_lmax.png
// (report_glossy.h).
#include <cmath>
#include <map>

#include "core/text.h"
#include "raster/plot.h"
#include "core/markdown_table.h"
#include "report/report_glossy.h"

namespace prt {
namespace {

std::string Percent(double x) { return Formatted("%.3g%%", 100.0 * x); }

/// The material as --material writes it, quoted for the CSV (it holds a comma).
std::string MaterialField(int exponent, double ks) { return Formatted("\"phong:%d,%g\"", exponent, ks); }

}  // namespace

std::string GlossyMarkdown(const GlossyStudy& d) {
  std::string s = Formatted("\n## Glossy materials: Phong lobes of KS %g\n\n", d.ks);
  s += Formatted("The same scene seen from the pictures' camera (eye %.4g,%.4g,%.4g), unshadowed and shadowed; ", d.eye.x,
                 d.eye.y, d.eye.z) +
       Formatted("%d fibonacci directions and %d lobe rays per vertex; ground truth from prt reference with the same "
                 "material and eye (%d directions per vertex). ",
                 d.samples, d.lobe_samples, d.reference_samples) +
       "`total` compares the radiance as rendered, albedo (L.T) + L.G, with the reference; `lobe` compares the lobe's "
       "part alone, L.G, with the reference's lobe part (the glossy reference minus the diffuse one: the reference "
       "draws the lobe's samples from a stream of their own, so the difference holds nothing else), relative to the "
       "lobe part's RMS. Unshadowed, only the lobe filters the light, so the lobe error is what the bands do to the "
       "lobe: the rule of thumb lmax ~ sqrt(N) is about that. Shadowed, visibility multiplies the light with sharp "
       "edges (a small sun's shadows) that no lobe smooths, and the truncated light's error seen through them sets a "
       "floor that more bands lower only slowly, as for diffuse shadows.\n\n";

  s += Formatted("### Bands a lobe needs\n\n`needed`: the smallest lmax of the sweep whose lobe error is at most %.0f%% "
                 "(`> L`: not reached by lmax L). `90%% energy`: the smallest lmax whose bands keep 90%% of the lobe's "
                 "energy (LobeBandShare, material/lobe.h; below it `prt render` warns). `lobe / radiance`: the lobe "
                 "part's share of the shadowed radiance (RMS). The references' own error is their two halves' "
                 "estimate, relative to their RMS radiance.\n\n",
                 100.0 * kLobeTarget);
  s += MarkdownHeader({"N", "sqrt(N)", "90% energy", "unshadowed: needed", "needed / sqrt(N)",
                       "lowest lobe error (lmax)", "shadowed: needed", "lowest lobe error (lmax)", "lobe / radiance",
                       "reference seconds (unshadowed)", "reference seconds (shadowed)",
                       "reference own error (unshadowed)", "reference own error (shadowed)"});
  const int top = d.vector_rows.empty() ? 0 : d.vector_rows.back().lmax;
  const auto needed = [top](const GlossyNeed& n) {
    return n.needed_lmax >= 0 ? std::to_string(n.needed_lmax) : "> " + std::to_string(top);
  };
  std::string ratios;
  for (const auto& e : d.exponents) {
    const double root = std::sqrt(double(e.exponent));
    const GlossyNeed &u = e.unshadowed, &h = e.shadowed;
    const std::string ratio = u.needed_lmax >= 0 ? Formatted("%.2f", u.needed_lmax / root) : "-";
    if (u.needed_lmax >= 0) ratios += (ratios.empty() ? "" : ", ") + ratio + Formatted(" at N = %d", e.exponent);
    s += MarkdownRow({std::to_string(e.exponent), Formatted("%.3g", root), std::to_string(e.share_lmax), needed(u), ratio,
                      Percent(u.best_lobe_error) + Formatted(" (%d)", u.best_lmax), needed(h),
                      Percent(h.best_lobe_error) + Formatted(" (%d)", h.best_lmax), Percent(h.lobe_share),
                      Formatted("%.2f", u.reference_seconds), Formatted("%.2f", h.reference_seconds),
                      Percent(u.reference_rms_error), Percent(h.reference_rms_error)});
  }
  s += "\nUnshadowed lmax needed / sqrt(N): " +
       (ratios.empty() ? std::string("no exponent reached the target within the sweep") : ratios) +
       ". A ratio near 1 bears the rule of thumb out; above 1, the light (a small bright sun reflected in a sharp "
       "lobe) needs more bands than the lobe's width alone suggests. A sharp lobe under a truncated sun can come out "
       "worse than no lobe at all (error above 100%): the ringing, blurred sun lights vertices the true highlight "
       "misses.\n\n";

  s += "### Vector path: error and precompute time against lmax\n\n" +
       MarkdownHeader({"mode", "N", "lmax", "precompute seconds", "total error", "lobe error", "lobe energy in bands"});
  for (const auto& r : d.vector_rows)
    s += MarkdownRow({TransportModeName(r.mode), std::to_string(r.exponent), std::to_string(r.lmax),
                      Formatted("%.3g", r.seconds), Percent(r.total.relative), Percent(r.lobe.relative),
                      Percent(r.band_share)});

  s += "\n### Fixed-camera vector against transfer matrices (shadowed)\n\nThe vector G integrates the lobe against the "
       "full visibility and cosine and truncates only the light to lmax, so it is exact for the band-limited light; "
       "the matrices truncate the product V L cos to lmax before the lobe is applied, so the lobe sees a blurred, "
       "ringing incident light, and the two differ until the bands hold the lobe. Both share the diffuse transfer, "
       "so their difference is all in the lobe. `matrices vs vector`: the RMS difference of the rendered radiance "
       "relative to the vector path's RMS radiance (frame 0, same eye); `lobe parts`: the same for the lobe's part "
       "alone. Matrix seconds are one run per lmax (the matrices do not depend on the lobe).\n\n" +
       MarkdownHeader({"N", "lmax", "vector total error", "matrix total error", "vector lobe error", "matrix lobe error",
                       "matrices vs vector", "lobe parts", "matrix seconds", "matrix MiB"});
  std::map<std::pair<int, int>, const GlossyVectorRow*> vec;
  for (const auto& r : d.vector_rows)
    if (r.mode == TransportMode::kShadowed) vec[{r.exponent, r.lmax}] = &r;
  for (const auto& r : d.matrix_rows) {
    const GlossyVectorRow* v = vec.at({r.exponent, r.lmax});
    s += MarkdownRow({std::to_string(r.exponent), std::to_string(r.lmax), Percent(v->total.relative),
                      Percent(r.total.relative), Percent(v->lobe.relative), Percent(r.lobe.relative),
                      Percent(r.vs_vector.relative), Percent(r.lobe_vs_vector.relative), Formatted("%.3g", r.seconds),
                      Formatted("%.3g", double(r.bytes) / 1048576.0)});
  }
  s += "\nglossy_error_vs_lmax.png plots the lobe errors against lmax: per exponent (colour), unshadowed vector (solid, "
       "squares), shadowed vector (dashed, circles) and shadowed matrices (light solid, triangles).\n";
  if (d.cpca) s += CpcaMarkdown(*d.cpca);
  return s;
}

std::string GlossyCsvRows(const GlossyStudy& d) {
  std::string s;
  // mode,sampler,samples,directions,lmax,seconds,sampling x3,total x3,psnr,material,path,lobe_relative,
  // vs_vector_relative,matrix_bytes
  for (const auto& r : d.vector_rows) {
    const bool rays = r.mode != TransportMode::kUnshadowed;  // unshadowed: closed form and quadrature, no rays
    s += Formatted("%s,%s,%d,%d,%d,%.6g,,,,%.6g,%.6g,%.6g,,", TransportModeName(r.mode), rays ? "fibonacci" : "closed-form",
                   rays ? d.samples : 0, rays ? d.samples : 0, r.lmax, r.seconds, r.total.rms, r.total.max,
                   r.total.relative) +
         MaterialField(r.exponent, d.ks) + Formatted(",glossy-vector,%.6g,,\n", r.lobe.relative);
  }
  for (const auto& r : d.matrix_rows)
    s += Formatted("shadowed,fibonacci,%d,%d,%d,%.6g,,,,%.6g,%.6g,%.6g,,", d.samples, d.samples, r.lmax, r.seconds,
                   r.total.rms, r.total.max, r.total.relative) +
         MaterialField(r.exponent, d.ks) +
         Formatted(",glossy-matrices,%.6g,%.6g,%llu\n", r.lobe.relative, r.vs_vector.relative,
                   static_cast<unsigned long long>(r.bytes));
  if (d.cpca) s += CpcaCsvRows(*d.cpca, d.samples, MaterialField(d.cpca->exponent, d.ks));
  return s;
}

Image8 GlossyPlot(const GlossyStudy& d) {
  std::vector<PlotSeries> series;
  for (std::size_t i = 0; i < d.exponents.size(); ++i) {
    const int n = d.exponents[i].exponent;
    PlotSeries u, v, m;
    u.label = Formatted("N %d unshadowed", n);
    v.label = Formatted("N %d shadowed", n);
    m.label = Formatted("N %d matrices", n);
    u.color = v.color = PlotColor(int(i));
    m.color = 0.5f * u.color + glm::vec3(0.5f);
    v.dashed = true;
    // The exponent by colour, the path by marker as well as by line.
    u.marker = PlotMarker::kSquare, v.marker = PlotMarker::kCircle, m.marker = PlotMarker::kTriangle;
    for (const auto& r : d.vector_rows)
      if (r.exponent == n) {
        PlotSeries& p = r.mode == TransportMode::kUnshadowed ? u : v;
        p.x.push_back(r.lmax), p.y.push_back(r.lobe.relative);
      }
    for (const auto& r : d.matrix_rows)
      if (r.exponent == n) m.x.push_back(r.lmax), m.y.push_back(r.lobe.relative);
    series.push_back(u);
    series.push_back(v);
    series.push_back(m);
  }
  PlotOptions o;
  o.width = 1000, o.height = 680;
  o.title = Formatted("Phong lobes (KS %g): lobe error (relative RMS) vs lmax", d.ks);
  o.x_label = "lmax";
  o.y_label = "lobe error";
  return DrawLogLogPlot(series, o);
}

}  // namespace prt
