#include "precompute/sample_rule.h"

#include <algorithm>

#include "sh/coeffs.h"

namespace prt {
namespace {

/// The default never goes below the count prt has always used at its default lmax of 2.
constexpr int kDefaultFloor = 1024;
/// Safety factor of the default over the minimum (sample_rule.h says why 8).
constexpr int kDefaultMargin = 8;

int PowerOfTwoAtLeast(long long n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

}  // namespace

int SamplesPerCoefficient(Sampler sampler) {
  switch (sampler) {
    case Sampler::kFibonacci: return 2;
    case Sampler::kStratified: return 4;
    case Sampler::kUniform: return 19;
  }
  return 19;
}

int MinimumSamples(int lmax, Sampler sampler) {
  const int l = std::clamp(lmax, 0, kMaxLmax);
  return PowerOfTwoAtLeast(static_cast<long long>(SamplesPerCoefficient(sampler)) * CoeffCount(l));
}

int DefaultSamples(int lmax, Sampler sampler) {
  return std::max(kDefaultFloor, kDefaultMargin * MinimumSamples(lmax, sampler));
}

std::string SampleRuleText(Sampler sampler) {
  return std::string(SamplerName(sampler)) + " needs " + std::to_string(SamplesPerCoefficient(sampler)) +
         " (L+1)^2 rounded up to a power of two, the default is 8 times that, at least 1024";
}

}  // namespace prt
