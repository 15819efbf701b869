#include <doctest/doctest.h>

#include <cmath>

#include "core/constants.h"
#include "core/parallel.h"
#include "core/rng.h"
#include "env/procedural.h"
#include "precompute/light.h"
#include "sh/basis.h"
#include "tests/env/env_test_util.h"
#include "tests/test_support.h"

using namespace prt;

namespace {

// The furnace's bound: exact to 1e-12 in double.
constexpr double kFurnaceTolerance = 1e-12;
// The bound for a band-limited function on a 64^2-per-face cubemap.
constexpr double kBandLimited64Tolerance = 2e-4;

/// A band-limited test function: fixed random coefficients up to band 4, plus a constant that
/// keeps it positive.
ShRgb TestCoefficients() {
  Pcg32 rng(21, 0);
  ShRgb c(CoeffCount(4));
  for (auto& v : c) v = {rng.NextDouble() - 0.5, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5};
  c[0] += glm::dvec3(4.0);
  return c;
}

glm::dvec3 Evaluate(const ShRgb& c, const glm::dvec3& d) {
  const auto y = EvalBasis(4, d);
  glm::dvec3 v(0.0);
  for (std::size_t k = 0; k < c.size(); ++k) v += y[k] * c[k];
  return v;
}

double MaxError(const ShRgb& a, const ShRgb& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(a[k][ch] - b[k][ch]));
  return worst;
}

}  // namespace

TEST_SUITE("precompute") {
  TEST_CASE("furnace: constant c gives L00 = 2 sqrt(pi) c and nothing else") {
    const double c = 2.5;
    for (int lmax : {2, 8, 64}) {
      const ShRgb L = ProjectLight(*MakeFurnace(c), lmax);
      CHECK(std::abs(L[0].x - 2 * std::sqrt(kPi) * c) < kFurnaceTolerance);
      for (std::size_t k = 1; k < L.size(); ++k) CHECK(std::abs(L[k].y) < kFurnaceTolerance);
    }
  }

  TEST_CASE("a constant cubemap: L00 exact, cubic harmonics vanish as 1/N^2") {
    // Exact texel solid angles make band 0 exact. The midpoint rule is not exact for the
    // bands where the cube's symmetry group has an invariant (l = 4, 6, 8, ...): their
    // error is O(h^2), so it must fall by about 4 per halving of the texel size.
    const double c = 2.5;
    double previous = 0.0;
    for (int size : {16, 32, 64}) {
      const auto cube = test::CubemapFrom([&](const glm::dvec3&) { return glm::dvec3(c); }, size);
      const ShRgb L = ProjectLight(*cube, 8);
      CHECK(std::abs(L[0].z - 2 * std::sqrt(kPi) * c) < kFurnaceTolerance);
      double worst = 0.0;
      for (std::size_t k = 1; k < 16; ++k) CHECK(std::abs(L[k].z) < kFurnaceTolerance);  // bands 1-3
      for (std::size_t k = 16; k < L.size(); ++k) worst = std::max(worst, std::abs(L[k].z));
      if (previous > 0) CHECK(previous / worst == doctest::Approx(4.0).epsilon(0.1));
      previous = worst;
    }
  }

  TEST_CASE("each basis function on a cubemap projects back to itself, error falling as 1/N^2") {
    // Fill the cubemap with Y_k (unit coefficient) for every k of bands 0..4 and project;
    // the worst coefficient error over all k is the figure of merit.
    auto worst_error = [](int size) {
      double worst = 0.0;
      for (int k = 0; k < CoeffCount(4); ++k) {
        auto f = [k](const glm::dvec3& d) { return glm::dvec3(EvalBasis(4, d)[k]); };
        const ShRgb L = ProjectLight(*test::CubemapFrom(f, size), 4);
        for (int j = 0; j < CoeffCount(4); ++j) worst = std::max(worst, std::abs(L[j].x - (j == k ? 1.0 : 0.0)));
      }
      return worst;
    };
    const double e32 = worst_error(32), e64 = worst_error(64), e128 = worst_error(128);
    MESSAGE("basis projection error: 32^2 " << e32 << ", 64^2 " << e64 << ", 128^2 " << e128);
    CHECK(e64 < kBandLimited64Tolerance);
    // Midpoint quadrature: halving the texel size divides the error by about 4.
    CHECK(e32 / e64 == doctest::Approx(4.0).epsilon(0.25));
    CHECK(e64 / e128 == doctest::Approx(4.0).epsilon(0.25));
  }

  TEST_CASE("a band-limited equirect projects back to its coefficients") {
    const ShRgb truth = TestCoefficients();
    auto f = [&](const glm::dvec3& d) { return Evaluate(truth, d); };
    const double e128 = MaxError(ProjectLight(*test::EquirectFrom(f, 256, 128), 4), truth);
    const double e256 = MaxError(ProjectLight(*test::EquirectFrom(f, 512, 256), 4), truth);
    MESSAGE("equirect projection error: 256x128 " << e128 << ", 512x256 " << e256);
    CHECK(e128 < kBandLimited64Tolerance);
    CHECK(e128 / e256 == doctest::Approx(4.0).epsilon(0.25));
  }

}
