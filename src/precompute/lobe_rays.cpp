#include "precompute/lobe_rays.h"

#include <cmath>

#include "core/rng.h"

namespace prt {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInvGolden = 0.61803398874989484820;
/// Stream of the per-vertex lattice shifts (distinct from the direction pool's streams).
constexpr std::uint64_t kLobeStream = 0x6c6f6265;  // "lobe"

double Frac(double x) { return x - std::floor(x); }

/// A right-handed frame (e1, e2) across the unit vector r (Duff et al. 2017).
void Frame(const glm::dvec3& r, glm::dvec3& e1, glm::dvec3& e2) {
  const double sign = std::copysign(1.0, r.z);
  const double a = -1.0 / (sign + r.z), b = r.x * r.y * a;
  e1 = {1.0 + sign * r.x * r.x * a, sign * b, -sign * r.x};
  e2 = {b, sign + r.y * r.y * a, -r.y};
}

}  // namespace

void DrawLobeRays(const Lobe& lobe, const glm::dvec3& r, int m, std::uint64_t seed, std::size_t vertex, LobeRays& out) {
  out.dirs.resize(m);
  out.weights.resize(m);
  Pcg32 rng(MixSeed(seed, kLobeStream), vertex);
  const double s1 = rng.NextDouble(), s2 = rng.NextDouble();
  glm::dvec3 e1, e2;
  Frame(r, e1, e2);
  for (int i = 0; i < m; ++i) {
    double weight = 0.0;
    const double mu = lobe.SampleMu(Frac((i + 0.5) / m + s1), weight);
    const double phi = 2.0 * kPi * Frac(i * kInvGolden + s2);
    const double sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    out.dirs[i] = mu * r + sine * (std::cos(phi) * e1 + std::sin(phi) * e2);
    out.weights[i] = weight / m;
  }
}

}  // namespace prt
