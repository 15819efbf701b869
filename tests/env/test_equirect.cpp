#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "env/equirect.h"
#include "tests/env/env_test_util.h"

using namespace prt;

namespace {
constexpr double kFourPi = 4.0 * kPi;
// Exact row solid angles: their sum is 4 pi up to rounding.
constexpr double kSolidAngleSumTolerance = 1e-12;
}  // namespace

TEST_SUITE("env") {
  TEST_CASE("equirect texel solid angles sum to 4 pi for any size") {
    for (auto [w, h] : {std::pair{2, 1}, {8, 4}, {7, 3}, {1024, 512}, {4096, 2048}}) {
      double sum = 0.0;
      for (int row = 0; row < h; ++row) sum += w * EquirectEnvironment::TexelSolidAngle(row, w, h);
      CHECK(std::abs(sum - kFourPi) < kSolidAngleSumTolerance);
    }
  }

  TEST_CASE("equirect rows look where Radiance() reads") {
    // A smooth function sampled at texel centres is returned exactly at those centres.
    auto f = [](const glm::dvec3& d) { return glm::dvec3(d.x + 2, d.y + 2, d.z + 2); };
    const auto env = test::EquirectFrom(f, 64, 32);
    std::vector<Texel> texels;
    for (std::size_t r = 0; r < env->RowCount(); r += 5) {
      env->Row(r, texels);
      for (std::size_t c = 0; c < texels.size(); c += 7) {
        const glm::dvec3 expected = f(texels[c].dir), got = env->Radiance(texels[c].dir);
        // Stored as float: agreement to float precision.
        CHECK(glm::length(expected - got) < 1e-5);
      }
    }
  }

  TEST_CASE("equirect orientation: the centre column looks along -Z, row 0 straight up") {
    std::vector<Texel> texels;
    const auto env = test::EquirectFrom([](const glm::dvec3&) { return glm::dvec3(1.0); }, 64, 32);
    env->Row(16, texels);  // just below the horizon
    CHECK(texels[32].dir.z < -0.99);
    CHECK(texels[48].dir.x > 0.99);  // a quarter turn to the right is +X
    env->Row(0, texels);
    CHECK(texels[0].dir.y > 0.99);
  }
}
