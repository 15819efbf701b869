// The threads tier of src/sh (tests/README.md, "Tiers"): the search for a light's lowest value,
// which --window auto runs over directions and starting points in chunks, gives the same window
// and the same lowest value on one thread and on more threads than cores; ThreadSanitizer watches
// the many-thread runs.
#include <doctest/doctest.h>

#include "sh/basis.h"
#include "sh/coeffs.h"
#include "sh/dering.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("sh") {
  TEST_CASE("threads: the auto window and the lowest radiance are the same on 1 and many threads") {
    // A sun-like light that rings below zero at lmax 8: a sharp lobe toward +Y over a constant.
    ShRgb light(CoeffCount(8));
    for (int l = 0; l <= 8; ++l)
      for (int m = -l; m <= l; ++m)
        light[std::size_t(ShIndex(l, m))] = glm::dvec3(m == 0 ? (l == 0 ? 4.0 : 2.0) : 0.1 * m, 1.0, 0.5);
    const auto [window_one, window_many] = test::OneAndMany([&] { return ChooseAutoWindow(light); });
    CHECK(window_one.t == window_many.t);
    CHECK(window_one.min_after == window_many.min_after);
    CHECK(window_one.weights == window_many.weights);
    const auto [low_one, low_many] = test::OneAndMany([&] { return LowestRadiance(light); });
    CHECK(low_one == low_many);
    CHECK(low_one < 0.0);  // the light rings: the search had a minimum to find
  }
}

}  // namespace prt
