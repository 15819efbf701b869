// The threads tier of src/env (tests/README.md, "Tiers"): a cube map's texel averages, gathered a
// row of texels per chunk, are the same bits on one thread and on more threads than cores;
// ThreadSanitizer watches the many-thread run.
#include <doctest/doctest.h>

#include <cmath>

#include "env/cubemap.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("env") {
  TEST_CASE("threads: a cube map's texel averages are the same bits on 1 and many threads") {
    const auto radiance = [](const glm::dvec3& d) {
      return glm::dvec3(1.0 + d.x, std::exp(3.0 * d.y), 0.5 + d.z * d.z);
    };
    const auto [one, many] = test::OneAndMany([&] { return CubemapFaceAverages(radiance, 16, 4, CubeLayout::kStandard); });
    for (int f = 0; f < 6; ++f) CHECK(one[f].pixels == many[f].pixels);
  }
}

}  // namespace prt
