#include "precompute/samplers.h"

#include <cmath>

#include "core/constants.h"
#include "core/name_table.h"

namespace prt {
namespace {

constexpr auto kSamplers = MakeNameTable<Sampler>({
    {Sampler::kFibonacci, "fibonacci"},
    {Sampler::kStratified, "stratified"},
    {Sampler::kUniform, "uniform"},
});
static_assert(kSamplers.Distinct());

}  // namespace

Sampler SamplerFromName(const std::string& name) { return kSamplers.Parse(name, "sampler"); }

const char* SamplerName(Sampler s) { return kSamplers.Name(s); }

std::vector<std::string> SamplerNames() { return kSamplers.Names(); }

glm::dmat3 RandomRotation(Pcg32& rng) {
  // A uniform unit quaternion from three uniforms (Shoemake, Graphics Gems III).
  const double u1 = rng.NextDouble(), u2 = 2 * kPi * rng.NextDouble(), u3 = 2 * kPi * rng.NextDouble();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double w = a * std::sin(u2), x = a * std::cos(u2), y = b * std::sin(u3), z = b * std::cos(u3);
  glm::dmat3 R;  // column-major
  R[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  R[1] = {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  R[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
  return R;
}

std::vector<glm::dvec3> SampleSphere(Sampler sampler, int n, Pcg32& rng) {
  std::vector<glm::dvec3> dirs;
  auto from_z_phi = [](double z, double phi) {
    const double s = std::sqrt(std::max(0.0, (1.0 - z) * (1.0 + z)));
    return glm::dvec3(s * std::cos(phi), s * std::sin(phi), z);
  };
  switch (sampler) {
    case Sampler::kFibonacci: {
      const glm::dmat3 R = RandomRotation(rng);
      const double inv_golden = 0.61803398874989484820;  // 1 / golden ratio
      for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / n;
        const double f = i * inv_golden;
        dirs.push_back(R * from_z_phi(z, 2 * kPi * (f - std::floor(f))));
      }
      break;
    }
    case Sampler::kStratified: {
      const int side = std::max(1, static_cast<int>(std::floor(std::sqrt(double(n)))));
      for (int t = 0; t < side; ++t)
        for (int p = 0; p < side; ++p) {
          const double alpha = (t + rng.NextDouble()) / side, beta = (p + rng.NextDouble()) / side;
          dirs.push_back(from_z_phi(2.0 * alpha - 1.0, 2 * kPi * beta));
        }
      break;
    }
    case Sampler::kUniform:
      for (int i = 0; i < n; ++i) {
        const double z = 2.0 * rng.NextDouble() - 1.0;
        dirs.push_back(from_z_phi(z, 2 * kPi * rng.NextDouble()));
      }
      break;
  }
  return dirs;
}

}  // namespace prt
