#include "sh/dering.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/text.h"
#include "sh/basis.h"
#include "sh/nonnegative_kernel.h"
#include "sh/quadrature.h"
#include "sh/window.h"
#include "sh/zonal.h"

namespace prt {
namespace {

constexpr double kStrictness = 1e-6;  // share of a constant kernel mixed into k (header)
constexpr double kMarginT = 1e-6;     // margin added to the least t found
constexpr int kStarts = 16;           // grid points a compass search starts from

/// Unwindowed (a) and kernel-windowed (b) reconstruction at one direction, per channel.
struct Pair {
  glm::dvec3 a, b;
};

class Field {
 public:
  Field(const ShRgb& c, const std::vector<double>& w) : c_(c), w_(w), lmax_(LmaxOfCount(c.size())) {}

  Pair At(const glm::dvec3& d, std::vector<double>& y) const {
    y.resize(c_.size());
    EvalBasis(lmax_, d, y.data());
    Pair p{glm::dvec3(0.0), glm::dvec3(0.0)};
    for (int l = 0; l <= lmax_; ++l) {
      glm::dvec3 band(0.0);
      for (int k = l * l; k < (l + 1) * (l + 1); ++k) band += y[k] * c_[k];
      p.a += band;
      p.b += w_[l] * band;
    }
    return p;
  }
  int lmax() const { return lmax_; }

 private:
  const ShRgb& c_;
  const std::vector<double>& w_;
  int lmax_;
};

double LowestChannel(const glm::dvec3& v) { return std::min({v.x, v.y, v.z}); }

/// f_t per channel, lowest channel.
double Blend(const Pair& p, double t) { return LowestChannel((1.0 - t) * p.a + t * p.b); }

/// The least t making this direction non-negative in every channel (0 if it already is).
double NeededT(const Pair& p) {
  double need = 0.0;
  for (int ch = 0; ch < 3; ++ch) {
    const double a = p.a[ch], b = p.b[ch];
    if (a >= 0) continue;
    need = std::max(need, b > a ? -a / (b - a) : 1.0);
  }
  return need;
}

/// Local maximum of `score` on the sphere from `d` by a compass search: eight tangent
/// directions at the current step, the best taken if it improves, else the step halves.
template <class Score>
double Climb(const Score& score, glm::dvec3 d, double step) {
  double best = score(d);
  for (int evals = 0; step > 1e-9 && evals < 600; evals += 8) {
    const glm::dvec3 helper = std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(d, helper)), v = glm::cross(d, u);
    glm::dvec3 best_d = d;
    double best_here = best;
    for (int k = 0; k < 8; ++k) {
      const double ang = kPi / 4.0 * k;
      const glm::dvec3 c = glm::normalize(d + step * (std::cos(ang) * u + std::sin(ang) * v));
      const double s = score(c);
      if (s > best_here) best_here = s, best_d = c;
    }
    if (best_here > best) {
      best = best_here;
      d = best_d;
    } else {
      step *= 0.5;
    }
  }
  return best;
}

/// The field on a Gauss grid, and the grid's spacing.
struct Sampled {
  std::vector<glm::dvec3> dirs;
  std::vector<Pair> values;
  double spacing = 0;
};

Sampled Sample(const Field& field) {
  const int rings = (3 * field.lmax() + 1) / 2 + 12;
  Sampled s;
  s.dirs = GaussSphere(rings).directions;
  s.spacing = kPi / rings;
  s.values.resize(s.dirs.size());
  ParallelFor(s.dirs.size(), 256, [&](std::size_t begin, std::size_t end) {
    std::vector<double> y;
    for (std::size_t i = begin; i < end; ++i) s.values[i] = field.At(s.dirs[i], y);
  });
  return s;
}

/// max over the sphere of score(Pair): the grid's best, refined from the kStarts best points.
template <class Score>
double Maximum(const Field& field, const Sampled& s, const Score& score) {
  std::vector<double> scores(s.values.size());
  for (std::size_t i = 0; i < scores.size(); ++i) scores[i] = score(s.values[i]);
  std::vector<std::size_t> order(s.dirs.size());
  std::iota(order.begin(), order.end(), 0);
  const std::size_t starts = std::min<std::size_t>(kStarts, order.size());
  std::partial_sort(order.begin(), order.begin() + starts, order.end(), [&](std::size_t i, std::size_t j) {
    return scores[i] > scores[j] || (scores[i] == scores[j] && i < j);
  });
  std::vector<double> found(starts);
  ParallelFor(starts, 1, [&](std::size_t begin, std::size_t end) {
    std::vector<double> y;
    for (std::size_t i = begin; i < end; ++i)
      found[i] = Climb([&](const glm::dvec3& d) { return score(field.At(d, y)); }, s.dirs[order[i]], s.spacing);
  });
  return *std::max_element(found.begin(), found.end());
}

/// Relative RMS irradiance error added by `w` (header).
double IrradianceCost(const ShRgb& c, const std::vector<double>& w) {
  double added = 0.0, total = 0.0;
  for (int l = 0; l < static_cast<int>(w.size()); ++l) {
    const double a2 = ClampedCosineBand(l) * ClampedCosineBand(l);
    double energy = 0.0;
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) energy += glm::dot(c[k], c[k]);
    added += a2 * (1.0 - w[l]) * (1.0 - w[l]) * energy;
    total += a2 * energy;
  }
  return total > 0 ? std::sqrt(added / total) : 0.0;
}

}  // namespace

AutoWindow ChooseAutoWindow(const ShRgb& coeffs) {
  const int lmax = LmaxOfCount(coeffs.size());
  if (lmax > kMaxAutoWindowLmax)
    throw Error(Formatted("--window auto: works to lmax %d, not %d", kMaxAutoWindowLmax, lmax));
  std::vector<double> kernel = NonNegativeKernelWeights(lmax);
  for (int l = 1; l <= lmax; ++l) kernel[l] *= 1.0 - kStrictness;
  const Field field(coeffs, kernel);
  const Sampled grid = Sample(field);

  AutoWindow w;
  w.min_before = -Maximum(field, grid, [](const Pair& p) { return -LowestChannel(p.a); });
  w.peak = Maximum(field, grid, [](const Pair& p) { return std::max({p.a.x, p.a.y, p.a.z}); });
  const double needed = Maximum(field, grid, [](const Pair& p) { return NeededT(p); });
  w.t = needed > 0 ? std::min(1.0, needed + kMarginT) : 0.0;
  for (int attempt = 0;; ++attempt) {
    const double t = w.t;
    w.min_after = w.t == 0 ? w.min_before : -Maximum(field, grid, [t](const Pair& p) { return -Blend(p, t); });
    if (w.min_after >= 0 || w.t >= 1.0 || attempt == 30) break;
    w.t = 0.5 * (w.t + 1.0);  // a dip the grid missed: spend more of the kernel
  }
  w.weights.resize(lmax + 1);
  for (int l = 0; l <= lmax; ++l) w.weights[l] = (1.0 - w.t) + w.t * kernel[l];
  w.irradiance_cost = IrradianceCost(coeffs, w.weights);
  return w;
}

double LowestRadiance(const ShRgb& coeffs) {
  const std::vector<double> none(LmaxOfCount(coeffs.size()) + 1, 1.0);
  const Field field(coeffs, none);
  return -Maximum(field, Sample(field), [](const Pair& p) { return -LowestChannel(p.a); });
}

std::string AutoWindow::Describe() const {
  const std::size_t last = weights.size() - 1;
  const double scale = peak > 0 ? peak : 1.0;
  std::string s = Formatted("lowest radiance %.3g (%.3g%% of the peak %.3g) without a window", min_before,
                            100.0 * min_before / scale, peak);
  if (t == 0) return s + ": already non-negative, no window";
  return s + Formatted(", %.3g with one: strength %.4g toward the sharpest non-negative kernel (w_1 %.4f, "
                       "w_%zu %.3g), costing %.3g%% of the irradiance (relative RMS)",
                       min_after, t, weights.size() > 1 ? weights[1] : 1.0, last, weights[last],
                       100.0 * irradiance_cost);
}

}  // namespace prt
