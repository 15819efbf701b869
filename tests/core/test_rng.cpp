#include <doctest/doctest.h>

#include <cmath>

#include "core/rng.h"

TEST_SUITE("core") {
  TEST_CASE("Pcg32 streams are reproducible and distinct") {
    prt::Pcg32 a(42, 7), b(42, 7), c(42, 8);
    bool differ = false;
    for (int i = 0; i < 100; ++i) {
      const auto x = a.NextU32();
      CHECK(x == b.NextU32());
      differ |= (x != c.NextU32());
    }
    CHECK(differ);
  }

  TEST_CASE("Pcg32 doubles are uniform, 0 <= u < 1") {
    // Mean of n uniforms has standard deviation 1/sqrt(12 n); 6 sigma cannot fail by chance.
    const int n = 200000;
    prt::Pcg32 rng(1, 2);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double u = rng.NextDouble();
      REQUIRE(u >= 0.0);
      REQUIRE(u < 1.0);
      sum += u;
    }
    const double kSixSigma = 6.0 / std::sqrt(12.0 * n);
    CHECK(std::abs(sum / n - 0.5) < kSixSigma);
  }
}
