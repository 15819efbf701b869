// The sample rule (precompute/sample_rule.h): its shape, its floor at the default lmax, and that
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
        const int minimum = MinimumSamples(l, s), fallback = DefaultSamples(l, s);
        CHECK((minimum & (minimum - 1)) == 0);
        CHECK((fallback & (fallback - 1)) == 0);
        CHECK(minimum >= CoeffCount(l));  // never fewer directions than coefficients
        CHECK(fallback >= minimum);
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

  TEST_CASE("sample rule: 1024 at lmax 2, the count prt has always used, and 4096 at lmax 15") {
    for (Sampler s : {Sampler::kFibonacci, Sampler::kStratified}) CHECK(DefaultSamples(2, s) == 1024);
    CHECK(DefaultSamples(2, Sampler::kUniform) == 2048);  // the noisy baseline: 8 x 256
    // lmax 15: 1024 fibonacci directions leave visible blotches, 4096 none (sample_rule.h).
    CHECK(DefaultSamples(15, Sampler::kFibonacci) == 4096);
    // The noisier samplers need more: the rule's order follows the measured convergence.
    CHECK(MinimumSamples(15, Sampler::kUniform) > MinimumSamples(15, Sampler::kStratified));
    CHECK(MinimumSamples(15, Sampler::kStratified) > MinimumSamples(15, Sampler::kFibonacci));
    // The transport's own default is the rule's at its default lmax and sampler.
    const TransportOptions t;
    CHECK(t.samples == DefaultSamples(t.lmax, t.sampler));
  }
}

}  // namespace prt
