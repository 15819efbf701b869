#include "precompute/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace prt {
namespace {

template <class V, class R>
VertexError Compare(const std::vector<V>& x, const std::vector<R>& ref) {
  if (x.size() != ref.size())
    throw Error("vertex error: " + std::to_string(x.size()) + " values against a reference of " +
                std::to_string(ref.size()) + " (expected the same vertex count)");
  VertexError e;
  double d2 = 0, r2 = 0;
  for (std::size_t v = 0; v < x.size(); ++v)
    for (int c = 0; c < 3; ++c) {
      const double d = double(x[v][c]) - double(ref[v][c]);
      d2 += d * d;
      r2 += double(ref[v][c]) * double(ref[v][c]);
      e.max = std::max(e.max, std::abs(d));
    }
  const double n = x.empty() ? 1.0 : 3.0 * double(x.size());
  e.rms = std::sqrt(d2 / n);
  e.relative = r2 > 0 ? std::sqrt(d2 / r2) : 0.0;
  return e;
}

}  // namespace

VertexError CompareVertices(const std::vector<glm::vec3>& x, const std::vector<glm::dvec3>& ref) {
  return Compare(x, ref);
}
VertexError CompareVertices(const std::vector<glm::dvec3>& x, const std::vector<glm::dvec3>& ref) {
  return Compare(x, ref);
}
VertexError CompareVertices(const std::vector<glm::vec3>& x, const std::vector<glm::vec3>& ref) {
  return Compare(x, ref);
}

void NeumaierSum::Add(double x) {
  const double t = sum_ + x;
  if (std::abs(sum_) >= std::abs(x))
    compensation_ += (sum_ - t) + x;
  else
    compensation_ += (x - t) + sum_;
  sum_ = t;
}

double LogLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0)) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    ++n;
  }
  const double den = n * sxx - sx * sx;
  if (n < 2 || den == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / den;
}

}  // namespace prt
