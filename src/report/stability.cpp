#include "report/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "bases/list.h"
#include "basis/study.h"
#include "core/constants.h"
#include "core/markdown_table.h"
#include "core/parallel.h"
#include "core/rng.h"
#include "core/text.h"
#include "env/procedural.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "precompute/error_metrics.h"
#include "precompute/light.h"
#include "precompute/samplers.h"
#include "precompute/transport.h"
#include "report/stability_inputs.h"
#include "sh/axis_rotation.h"
#include "sh/basis.h"
#include "sh/dering.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"
#include "sh/window.h"
#include "sh/zonal.h"

namespace prt {
namespace {

StabilityCase Case(std::string name, std::string checks, double figure, double limit, bool at_least = false,
                   std::string note = "") {
  StabilityCase c{std::move(name), std::move(checks), figure, limit, at_least, false, std::move(note)};
  c.pass = std::isfinite(figure) && (at_least ? figure >= limit : figure <= limit);
  return c;
}

/// max |<Y_i, Y_j> - delta_ij| on the Gauss rule exact for bands 0..lmax, for i among 24
/// indices (the first, the last, and 22 spread between) against every j: the full Gram matrix
/// at lmax 64 would cost 10^11 operations.
double Orthonormality(int lmax) {
  const SphereQuadrature q = GaussSphere(lmax + 1);
  const int n = CoeffCount(lmax);
  std::vector<int> rows;
  for (int r = 0; r < 24; ++r) rows.push_back(static_cast<int>((long long)(n - 1) * r / 23));
  std::vector<double> gram(rows.size() * std::size_t(n), 0.0), y(n);
  for (std::size_t i = 0; i < q.directions.size(); ++i) {
    EvalBasis(lmax, q.directions[i], y.data());
    for (std::size_t a = 0; a < rows.size(); ++a) {
      const double wa = q.weights[i] * y[rows[a]];
      double* g = gram.data() + a * n;
      for (int b = 0; b < n; ++b) g[b] += wa * y[b];
    }
  }
  double worst = 0;
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (int b = 0; b < n; ++b) worst = std::max(worst, std::abs(gram[a * n + b] - (rows[a] == b)));
  return worst;
}

/// The bands whose orthogonality is checked: all to lmax 64; above, every 7th and the last (a
/// band costs (2l+1)^3 to check, all 201 of lmax 200 would take seconds).
std::vector<int> CheckedBands(int lmax) {
  const int step = lmax > 64 ? 7 : 1;
  std::vector<int> bands;
  for (int l = 0; l <= lmax; l += step) bands.push_back(l);
  if (bands.back() != lmax) bands.push_back(lmax);
  return bands;
}

/// max over random d of |Y(R d) - D(R) Y(d)|, and max |D D^T - I| over CheckedBands.
void Rotation(int lmax, double& equivariance, double& orthogonality) {
  Pcg32 rng(7, 1);
  const glm::dmat3 R = RandomRotation(rng);
  const ShRotation rot(R, lmax);
  const int n = CoeffCount(lmax);
  std::vector<double> y(n), yr(n), dy(n);
  equivariance = 0;
  for (int t = 0; t < 16; ++t) {
    const glm::dvec3 d = SampleSphere(Sampler::kUniform, 1, rng)[0];
    EvalBasis(lmax, d, y.data());
    EvalBasis(lmax, glm::normalize(R * d), yr.data());
    rot.Apply(y.data(), dy.data());
    for (int k = 0; k < n; ++k) equivariance = std::max(equivariance, std::abs(yr[k] - dy[k]));
  }
  orthogonality = 0;
  for (int l : CheckedBands(lmax)) {
    const auto& D = rot.Band(l);
    const int w = 2 * l + 1;
    for (int i = 0; i < w; ++i)
      for (int j = 0; j < w; ++j) {
        double s = 0;
        for (int k = 0; k < w; ++k) s += D[i * w + k] * D[j * w + k];
        orthogonality = std::max(orthogonality, std::abs(s - (i == j)));
      }
  }
}

/// 1 if every Y_k, k < CoeffCount(200), is finite at the poles and at z = 1 - 1e-15, else 0;
/// `largest` receives max |Y_k| found.
double BasisFinite(double& largest) {
  const double z = 1.0 - 1e-15, s = std::sqrt((1.0 - z) * (1.0 + z));
  const glm::dvec3 dirs[4] = {{0, 0, 1}, {0, 0, -1}, {s, 0, z}, {0, -s, -z}};
  std::vector<double> y(CoeffCount(kMaxBasisLmax));
  largest = 0;
  for (const auto& d : dirs) {
    EvalBasis(kMaxBasisLmax, d, y.data());
    for (double v : y) {
      if (!std::isfinite(v)) return 0.0;
      largest = std::max(largest, std::abs(v));
    }
  }
  return 1.0;
}

/// Lowest reconstructed radiance (any channel) at 200,000 spherical Fibonacci directions: a
/// check that shares nothing with the grid-and-compass search of sh/dering.h.
double LowestAtFibonacci(const ShRgb& c) {
  const int lmax = LmaxOfCount(c.size());
  Pcg32 rng(11, 3);
  const std::vector<glm::dvec3> dirs = SampleSphere(Sampler::kFibonacci, 200000, rng);
  std::vector<double> lows(dirs.size());
  ParallelFor(dirs.size(), 4096, [&](std::size_t begin, std::size_t end) {
    std::vector<double> y(c.size());
    for (std::size_t i = begin; i < end; ++i) {
      EvalBasis(lmax, dirs[i], y.data());
      glm::dvec3 v(0.0);
      for (std::size_t k = 0; k < c.size(); ++k) v += y[k] * c[k];
      lows[i] = std::min({v.x, v.y, v.z});
    }
  });
  return *std::min_element(lows.begin(), lows.end());
}

/// `--window auto` on one sun at one lmax: the figure is the lowest radiance after it, over
/// the peak, by both the chooser's own search and the independent Fibonacci check.
StabilityCase AutoWindowCase(const std::string& name, const SkyParams& p, int lmax) {
  const auto env = MakeSky(p);
  ShRgb c = ProjectLight(*env, lmax);
  const double mean = c[0].y / std::sqrt(4.0 * kPi);
  const double sun = env->Radiance(SunDirection(p)).y;
  const AutoWindow a = ChooseAutoWindow(c);
  ApplyWeights(a.weights, c);
  const double lowest = std::min(a.min_after, LowestAtFibonacci(c));
  return Case(name,
              "--window auto on sky:sun=" + Formatted("%g", p.sun) + ",radius=" + Formatted("%g", p.radius) + " (sun/mean " +
                  Formatted("%.2g", sun / mean) + ") at lmax " + std::to_string(lmax) +
                  ": lowest radiance after it / peak, own search and 200,000 Fibonacci directions (>= 0)",
              lowest / a.peak, 0.0, true,
              "before " + Formatted("%.3g", a.min_before / a.peak) + " of the peak; strength " + Formatted("%.4g", a.t) +
                  ", w_1 " + Formatted("%.4f", a.weights.size() > 1 ? a.weights[1] : 1.0) + ", irradiance cost " +
                  Formatted("%.3g", 100.0 * a.irradiance_cost) + "%");
}

void HdrSun(std::vector<StabilityCase>& out) {
  SkyParams p;
  p.sun = 30, p.radius = 0.5;
  const auto env = MakeSky(p);
  const ShRgb full = ProjectLight(*env, 8);
  const double mean = full[0].y / std::sqrt(4.0 * kPi);
  const double peak = env->Radiance(SunDirection(p)).y;
  out.push_back(Case("hdr_sun_peak_over_mean", "sky:sun=30,radius=0.5 is an extreme HDR light (peak/mean of green)",
                     peak / mean, 1e4, true));
  for (Window w : {Window::kNone, Window::kHann, Window::kLanczos}) {
    ShRgb c = full;
    ApplyWindow(w, c);
    const double lo = LowestRadiance(c);
    out.push_back(Case(std::string("ringing_lmax8_") + WindowName(w),
                       std::string("min(reconstruction)/peak of the lmax 8 sun with window ") + WindowName(w) +
                           " (negative = ringing; reported, limit only says no NaN)",
                       lo / peak, 1.0, false, "min " + Formatted("%.4g", lo) + ", peak " + Formatted("%.4g", peak)));
  }
  for (int lmax : {2, 4, 8, 16}) out.push_back(AutoWindowCase("window_auto_lmax" + std::to_string(lmax), p, lmax));
  SkyParams strong = p;
  strong.sun = 300, strong.radius = 0.25;  // sun / mean above 1e5
  const auto strong_env = MakeSky(strong);
  const double strong_ratio = strong_env->Radiance(SunDirection(strong)).y /
                              (ProjectLight(*strong_env, 0)[0].y / std::sqrt(4.0 * kPi));
  out.push_back(Case("sun_1e5_peak_over_mean", "sky:sun=300,radius=0.25: a sun of 1e5 x the mean radiance (green)",
                     strong_ratio, 1e5, true));
  for (int lmax : {8, 64}) out.push_back(AutoWindowCase("window_auto_sun1e5_lmax" + std::to_string(lmax), strong, lmax));
}

void SceneScale(std::vector<StabilityCase>& out) {
  for (float scale : {1e-4f, 1e4f}) {
    Mesh sphere = MakeSphere(24);
    TransformMesh(sphere, scale, glm::vec3(3.0f * scale));
    TransportOptions o;
    o.lmax = 4;
    o.samples = 256;
    o.mode = TransportMode::kUnshadowed;
    const Transport u = ComputeTransport(sphere, o, nullptr);
    o.mode = TransportMode::kShadowed;
    TransportReport r;
    const Transport s = ComputeTransport(sphere, o, &r);
    double diff = 0;
    for (std::size_t i = 0; i < u.coeffs.size(); ++i) diff = std::max(diff, double(std::abs(u.coeffs[i] - s.coeffs[i])));
    out.push_back(Case("convex_scale_" + Formatted("%g", scale), "a lone convex sphere of radius " + Formatted("%g", scale) +
                           " far from the origin: shadowed transport equals unshadowed (max |difference|)",
                       diff, 0.0, false, std::to_string(r.closed_form_vertices) + " of " +
                                             std::to_string(sphere.vertex_count()) + " vertices unoccluded"));
  }
}

void LongRotation(std::vector<StabilityCase>& out) {
  const int lmax = 8, frames = 36000;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, 3));
  const auto env = MakeSky(SkyParams{});
  const ShRgb light = ProjectLight(*env, lmax);
  const double angle = 2.0 * kPi * double(frames - 1) / frames;
  const ShRgb framed = AxisRotation(axis, lmax).Rotate(light, angle);
  const ShRgb direct = ShRotation(AxisAngle(axis, angle), lmax).Apply(light);
  double err = 0, accumulated_err = 0;
  for (std::size_t k = 0; k < light.size(); ++k) err = std::max(err, glm::length(framed[k] - direct[k]));
  // Accumulating the per-frame step in float, as a naive renderer would.
  const ShRotation step(AxisAngle(axis, 2.0 * kPi / frames), lmax);
  const int n = CoeffCount(lmax);
  std::vector<float> c(n);
  std::vector<double> in(n), outv(n);
  for (int k = 0; k < n; ++k) c[k] = float(light[k].y);
  for (int f = 1; f < frames; ++f) {
    for (int k = 0; k < n; ++k) in[k] = c[k];
    step.Apply(in.data(), outv.data());
    for (int k = 0; k < n; ++k) c[k] = float(outv[k]);
  }
  for (int k = 0; k < n; ++k) accumulated_err = std::max(accumulated_err, std::abs(double(c[k]) - direct[k].y));
  out.push_back(Case("rotation_36000_frames", "frame 35999 of 36000 about (1,2,3), lmax 8, rebuilt from its absolute "
                                              "angle, against the directly rotated coefficients (max abs)",
                     err, 1e-12, false, "accumulating float per-frame steps instead: " + Formatted("%.3g", accumulated_err)));
}

void Accumulation(std::vector<StabilityCase>& out) {
  const int n = 1000000;
  Pcg32 rng(3, 5);
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.3, 0.8, -0.5));
  const std::vector<glm::dvec3> dirs = SampleSphere(Sampler::kFibonacci, n, rng);
  float naive_f = 0;
  double naive_d = 0;
  long double exact = 0;
  NeumaierSum comp;
  for (const auto& d : dirs) {
    const double term = (4.0 / n) * std::max(0.0, glm::dot(normal, d)) * 0.28209479177387814;  // (4pi/N)(1/pi) cos Y00
    naive_f += float(term);
    naive_d += term;
    exact += static_cast<long double>(term);
    comp.Add(term);
  }
  const double ref = double(exact);
  const double closed = ClampedCosineBand(0) / kPi * 0.28209479177387814;
  out.push_back(Case("sum_1e6_compensated", "10^6 terms of the unshadowed T_00 estimate: Neumaier sum against a "
                                            "long-double sum of the same terms (abs)",
                     std::abs(comp.Value() - ref), 1e-12, false,
                     "naive double " + Formatted("%.3g", std::abs(naive_d - ref)) + ", naive float " +
                         Formatted("%.3g", std::abs(double(naive_f) - ref)) + "; estimate - closed form " +
                         Formatted("%.3g", std::abs(ref - closed)) + " (sampling error, not summation)"));
}

/// Every case but the wavelet ones: their inputs are fixed.
void FixedCases(std::vector<StabilityCase>& out) {
  for (int lmax : {32, 64, 100, 200}) {
    const std::string at = "_lmax" + std::to_string(lmax);
    if (lmax <= 64)
      out.push_back(Case("orthonormality" + at,
                         "max |<Y_i,Y_j> - delta_ij| on the exact Gauss rule, bands 0.." + std::to_string(lmax),
                         Orthonormality(lmax), 1e-10));
    double eq = 0, orth = 0;
    Rotation(lmax, eq, orth);
    out.push_back(Case("rotation_equivariance" + at, "max |Y(R d) - D(R) Y(d)| over 16 random d, random R", eq, 1e-11));
    out.push_back(Case("rotation_orthogonality" + at,
                       lmax <= 64 ? std::string("max |D_l D_l^T - I| over bands")
                                  : "max |D_l D_l^T - I| over bands 0, 7, 14, ... and the last (a band costs (2l+1)^3)",
                       orth, 1e-12));
  }
  double largest = 0;
  const double finite = BasisFinite(largest);
  out.push_back(Case("basis_finite_lmax200", "every Y_k to lmax 200 finite at both poles and at z = +-(1 - 1e-15) (1 = yes)",
                     finite, 1.0, true, "largest |Y| " + Formatted("%.4g", largest)));
  HdrSun(out);
  SceneScale(out);
  LongRotation(out);
  Accumulation(out);
  ExtremeMeshes(out);
  DeepConcavity(out);
  BadTexels(out);
  GlossySharpLobe(out);
}

}  // namespace

std::vector<StabilityCase> RunStabilityCases(const StabilityOptions& options) {
  std::vector<StabilityCase> out;
  if (options.fixed_cases) FixedCases(out);
  // Each basis's own cases (basis/study.h), in the list's order.
  for (const Basis* basis : Bases())
    if (const BasisStudy* study = basis->Study()) study->StabilityCases(out, options.study_scene);
  return out;
}

std::string StabilityCsv(const std::vector<StabilityCase>& cases) {
  std::string s = "case,figure,limit,comparison,pass,checks,note\n";
  for (const auto& c : cases)
    s += c.name + "," + Formatted("%.6g", c.figure) + "," + Formatted("%.6g", c.limit) + "," + (c.at_least ? ">=" : "<=") + "," +
         (c.pass ? "pass" : "FAIL") + ",\"" + c.checks + "\",\"" + c.note + "\"\n";
  return s;
}

std::string StabilityMarkdown(const std::vector<StabilityCase>& cases) {
  std::string s = "# prt report --stability: stiff and extreme cases\n\n" +
                  MarkdownHeader({"case", "what is checked", "measured", "limit", "result", "note"});
  for (const auto& c : cases)
    s += MarkdownRow({c.name, c.checks, Formatted("%.4g", c.figure), (c.at_least ? ">= " : "<= ") + Formatted("%.3g", c.limit),
                      c.pass ? "pass" : "**FAIL**", c.note});
  return s;
}

}  // namespace prt
