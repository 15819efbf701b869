// The axes of raster/plot.h: tight around the data (within the nearest ticks m 10^e outside it),
// not widened to whole decades, which left most of the report's time axis empty.
#include <doctest/doctest.h>

#include <vector>

#include "raster/plot.h"

namespace prt {

TEST_SUITE("raster") {
  TEST_CASE("plot: a log axis holds every point and begins and ends less than a factor 2 outside them") {
    // The nearest tick m 10^e below v is above v/2 (v = 1.99 10^e is the worst case: tick 10^e).
    constexpr double kTightFactor = 2.0;
    const std::vector<std::vector<double>> cases = {
        {4.3e-3, 5.5e-3, 8e-3, 1.25e-2, 2.1e-2},  // the quick report's seconds
        {0.105, 0.27},                           // its errors
        {1.99e-5, 3e-2},
        {1e-3, 1e-1},                            // on ticks already
        {9.9, 10.1},
        {7e-3},                                  // one point
    };
    for (const auto& values : cases) {
      CAPTURE(values.front());
      const LogRange r = LogAxisRange(values);
      double lo = values.front(), hi = values.front();
      for (double v : values) lo = std::min(lo, v), hi = std::max(hi, v);
      CHECK(r.lo <= lo);
      CHECK(r.hi >= hi);
      CHECK(r.hi > r.lo);
      CHECK(lo / r.lo < kTightFactor);  // whole decades gave up to 10 (4.3e-3 -> 1e-3)
      CHECK(r.hi / hi <= kTightFactor);
    }
    const LogRange seconds = LogAxisRange(cases[0]);
    CHECK(seconds.lo == doctest::Approx(4e-3));
    CHECK(seconds.hi == doctest::Approx(3e-2));
    // Values a log axis cannot show are left out; none at all gives one decade.
    const LogRange skipped = LogAxisRange({0.0, -1.0, 2e-2, 5e-2});
    CHECK(skipped.lo == doctest::Approx(2e-2));
    CHECK(skipped.hi == doctest::Approx(5e-2));
    const LogRange none = LogAxisRange({});
    CHECK(none.lo == 1.0);
    CHECK(none.hi == 10.0);
  }
}

}  // namespace prt
