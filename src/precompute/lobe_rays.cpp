#include "precompute/lobe_rays.h"

#include <cmath>

#include "core/constants.h"
#include "core/frame.h"
#include "core/rng.h"

namespace prt {
namespace {

constexpr double kInvGolden = 0.61803398874989484820;

double Frac(double x) { return x - std::floor(x); }


}  // namespace

void DrawLobeRays(const Lobe& lobe, const glm::dvec3& r, int m, std::uint64_t seed, std::size_t vertex, LobeRays& out) {
  out.dirs.resize(m);
  out.weights.resize(m);
  Pcg32 rng(MixSeed(seed, kLobeStream), vertex);
  const double s1 = rng.NextDouble(), s2 = rng.NextDouble();
  glm::dvec3 e1, e2;
  TangentFrame(r, e1, e2);
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
