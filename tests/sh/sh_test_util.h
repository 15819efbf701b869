#pragma once
// Helpers shared by the SH tests (and the command-line tests of `prt light`).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "sh/basis.h"
#include "sh/coeffs.h"

namespace prt::test {

/// A direction uniform on the sphere, from two draws of `rng`.
inline glm::dvec3 RandomDirection(Pcg32& rng) {
  const double z = 2.0 * rng.NextDouble() - 1.0;
  const double phi = 2.0 * kPi * rng.NextDouble();
  const double s = std::sqrt((1.0 - z) * (1.0 + z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

/// Lowest channel of the reconstruction sum_k c_k Y_k over `directions`: a scan that shares
/// nothing with the searches under test.
inline double LowestOver(const ShRgb& c, const std::vector<glm::dvec3>& directions) {
  const int lmax = LmaxOfCount(c.size());
  std::vector<double> y(c.size());
  double lowest = 1e300;
  for (const auto& d : directions) {
    EvalBasis(lmax, d, y.data());
    glm::dvec3 v(0.0);
    for (std::size_t k = 0; k < c.size(); ++k) v += y[k] * c[k];
    lowest = std::min({lowest, v.x, v.y, v.z});
  }
  return lowest;
}

/// sum_k c_k Y_k(d): the band-limited function the coefficients c stand for.
inline glm::dvec3 EvaluateSh(const ShRgb& c, const glm::dvec3& d) {
  std::vector<double> y(c.size());
  EvalBasis(LmaxOfCount(c.size()), glm::normalize(d), y.data());
  glm::dvec3 sum(0.0);
  for (std::size_t k = 0; k < c.size(); ++k) sum += y[k] * c[k];
  return sum;
}

/// A light of bands 0..lmax with coefficients of its own per channel and no symmetry, its mean
/// well above the rest, as a light has.
inline ShRgb RandomLight(int lmax, std::uint64_t seed) {
  Pcg32 rng(seed, 3);
  ShRgb c(CoeffCount(lmax));
  for (auto& v : c) v = {rng.NextDouble() - 0.5, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5};
  c[0] += glm::dvec3(8.0, 7.0, 6.0);
  return c;
}

}  // namespace prt::test
