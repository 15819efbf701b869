#include "precompute/sample_rule.h"

#include <algorithm>

#include "sh/coeffs.h"

namespace prt {
namespace {

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
  return std::max(kDefaultFloor, kSeenOverHidden * DefaultHiddenSamples(lmax, sampler));
}

int DefaultHiddenSamples(int lmax, Sampler sampler) {
  return std::max(kHiddenFloor, kHiddenMargin * MinimumSamples(lmax, sampler));
}

std::string SampleRuleText(Sampler sampler) {
  return std::string(SamplerName(sampler)) + " needs " + std::to_string(SamplesPerCoefficient(sampler)) +
         " (L+1)^2 rounded up to a power of two; the default is " + std::to_string(kHiddenMargin) +
         " times that, at least " + std::to_string(kHiddenFloor) + ", for the vertices the camera does not see, and " +
         std::to_string(kSeenOverHidden) + " times theirs, at least " + std::to_string(kDefaultFloor) +
         ", for those it sees";
}

std::string SampleRuleTextEveryVertex(Sampler sampler) {
  return std::string(SamplerName(sampler)) + " needs " + std::to_string(SamplesPerCoefficient(sampler)) +
         " (L+1)^2 rounded up to a power of two; every vertex takes " + std::to_string(kSeenOverHidden * kHiddenMargin) +
         " times that, at least " + std::to_string(kDefaultFloor) + ", as the vertices a camera sees do";
}

}  // namespace prt
