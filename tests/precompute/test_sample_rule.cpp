// The sample rule (precompute/sample_rule.h): its shape, its counts at the usual lmax, and that
// the transport's own default agrees with it. The rule's constants are measured, so this file
// checks the properties any version of them must keep, not the constants themselves.
#include <doctest/doctest.h>

#include "precompute/sample_rule.h"
#include "precompute/transport.h"
#include "sh/coeffs.h"

namespace prt {

TEST_SUITE("precompute") {
  TEST_CASE("sample rule: monotonic in lmax, powers of two, the default at least the minimum") {
    for (Sampler s : {Sampler::kFibonacci, Sampler::kStratified, Sampler::kUniform}) {
      CAPTURE(SamplerName(s));
      for (int l = 0; l <= kMaxLmax; ++l) {
        CAPTURE(l);
        const int minimum = MinimumSamples(l, s), fallback = DefaultSamples(l, s), hidden = DefaultHiddenSamples(l, s);
        CHECK((minimum & (minimum - 1)) == 0);
        CHECK((fallback & (fallback - 1)) == 0);
        CHECK((hidden & (hidden - 1)) == 0);
        CHECK(minimum >= CoeffCount(l));  // never fewer directions than coefficients
        CHECK(hidden >= minimum);
        CHECK(fallback >= 2 * hidden);   // the vertices a frame shows take more
        if (l > 0) {
          CHECK(minimum >= MinimumSamples(l - 1, s));
          CHECK(fallback >= DefaultSamples(l - 1, s));
        }
      }
      // Proportional to the coefficient count: four times the coefficients (lmax 7 -> 15) asks
      // four times the directions, as the header's measurement found.
      CHECK(MinimumSamples(15, s) == 4 * MinimumSamples(7, s));
      CHECK(DefaultSamples(kMaxLmax, s) > DefaultSamples(2, s));  // the high bands ask more
    }
  }

  TEST_CASE("sample rule: 8192 directions for the vertices the camera sees, 1024 (the count before) for the others") {
    // Measured on the demo and the course's mary (sample_rule.h): 8192 keeps frame 0 within
    // 2 levels of the converged frame where 1024 left blotches of up to 8 levels.
    for (int lmax : {0, 2, 4, 7}) {
      CHECK(DefaultSamples(lmax, Sampler::kFibonacci) == 8192);
      CHECK(DefaultHiddenSamples(lmax, Sampler::kFibonacci) == 1024);
    }
    CHECK(DefaultHiddenSamples(2, Sampler::kStratified) == 1024);
    CHECK(DefaultHiddenSamples(2, Sampler::kUniform) == 2048);  // the noisy baseline: 8 x 256
    // Higher bands: the hidden count follows the minimum, the seen one stays twice it at least.
    CHECK(DefaultHiddenSamples(15, Sampler::kFibonacci) == 4096);
    CHECK(DefaultSamples(15, Sampler::kFibonacci) == 8192);
    CHECK(DefaultSamples(16, Sampler::kFibonacci) == 2 * DefaultHiddenSamples(16, Sampler::kFibonacci));
    // The noisier samplers need more: the rule's order follows the measured convergence.
    CHECK(MinimumSamples(15, Sampler::kUniform) > MinimumSamples(15, Sampler::kStratified));
    CHECK(MinimumSamples(15, Sampler::kStratified) > MinimumSamples(15, Sampler::kFibonacci));
    // The transport's own default, for callers without a camera, is the hidden count at its
    // default lmax and sampler: every vertex alike.
    const TransportOptions t;
    CHECK(t.samples == DefaultHiddenSamples(t.lmax, t.sampler));
    CHECK(t.hidden_samples == 0);
  }
}

}  // namespace prt
