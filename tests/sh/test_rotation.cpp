#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "core/constants.h"
#include "core/rng.h"
#include "sh/basis.h"
#include "sh/quadrature.h"
#include "sh/rotation.h"
#include "sh/rotation_course.h"
#include "sh/wigner_d.h"
#include "tests/sh/sh_test_util.h"
#include "tests/test_support.h"
#include "core/error.h"

using namespace prt;

namespace {

// The bound for orthogonality and Y(R d) = D Y(d) at lmax <= 10: rounding of a few products.
constexpr double kRotationTolerance = 1e-13;
// Rotate-then-project against project-then-rotate: exact quadrature on both sides, rounding
// over a few thousand terms.
constexpr double kCommuteTolerance = 1e-12;

using test::RandomDirection;

glm::dmat3 RandomRotation(Pcg32& rng) {
  return AxisAngle(RandomDirection(rng), 2.0 * kPi * rng.NextDouble());
}

/// max |D_l D_l^T - I| over bands l = 0, step, 2 step, ... and the last (the check costs
/// (2l+1)^3 a band: all 201 bands of lmax 200 would take seconds).
double BandOrthogonalityError(const ShRotation& rot, int step = 1) {
  std::vector<int> bands;
  for (int l = 0; l <= rot.lmax(); l += step) bands.push_back(l);
  if (bands.back() != rot.lmax()) bands.push_back(rot.lmax());
  double worst = 0.0;
  for (int l : bands) {
    const int n = 2 * l + 1;
    const auto& d = rot.Band(l);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        double dot = 0.0;
        for (int k = 0; k < n; ++k) dot += d[i * n + k] * d[j * n + k];
        worst = std::max(worst, std::abs(dot - (i == j ? 1.0 : 0.0)));
      }
  }
  return worst;
}

/// max over k of |Y_k(R d) - (D Y(d))_k|.
double ApplyError(const ShRotation& rot, const glm::dmat3& R, const glm::dvec3& d) {
  const int lmax = rot.lmax();
  const auto y = EvalBasis(lmax, d);
  const auto yr = EvalBasis(lmax, R * d);
  std::vector<double> dy(y.size());
  rot.Apply(y.data(), dy.data());
  double worst = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) worst = std::max(worst, std::abs(dy[k] - yr[k]));
  return worst;
}

}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("band matrices are orthogonal and satisfy Y(R d) = D(R) Y(d), lmax <= 10") {
    Pcg32 rng(5, 0);
    for (int trial = 0; trial < 20; ++trial) {
      const glm::dmat3 R = RandomRotation(rng);
      const ShRotation rot(R, 10);
      CHECK(BandOrthogonalityError(rot) < kRotationTolerance);
      for (int i = 0; i < 10; ++i) CHECK(ApplyError(rot, R, RandomDirection(rng)) < kRotationTolerance);
    }
  }

  TEST_CASE("identity, 180 degrees and 1e-9 rad are exact") {
    Pcg32 rng(6, 0);
    const glm::dvec3 axis = RandomDirection(rng);
    for (double angle : {0.0, kPi, 1e-9}) {
      const glm::dmat3 R = AxisAngle(axis, angle);
      const ShRotation rot(R, 10);
      CHECK(BandOrthogonalityError(rot) < kRotationTolerance);
      for (int i = 0; i < 10; ++i) CHECK(ApplyError(rot, R, RandomDirection(rng)) < kRotationTolerance);
    }
    // The identity gives the identity matrix exactly.
    const ShRotation id(glm::dmat3(1.0), 6);
    for (int l = 0; l <= 6; ++l)
      for (int i = 0; i < 2 * l + 1; ++i)
        for (int j = 0; j < 2 * l + 1; ++j)
          CHECK(id.Band(l)[i * (2 * l + 1) + j] == doctest::Approx(i == j ? 1.0 : 0.0).epsilon(1e-15));
  }

  TEST_CASE("rotation about +Z: matrices equal the cos/sin(m a) closed form") {
    Pcg32 rng(8, 0);
    ShRgb c(CoeffCount(8));
    for (auto& v : c) v = {rng.NextDouble() - 0.5, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5};
    const double a = 0.7;
    const ShRgb fast = RotateAboutZ(c, a);
    const ShRgb full = ShRotation(AxisAngle({0, 0, 1}, a), 8).Apply(c);
    for (std::size_t k = 0; k < c.size(); ++k)
      for (int ch = 0; ch < 3; ++ch) CHECK(std::abs(fast[k][ch] - full[k][ch]) < kRotationTolerance);
  }

  TEST_CASE("rotate-then-project equals project-then-rotate") {
    // f(d) = a band-limited-free smooth function; its rotated version g(d) = f(R^T d).
    const int lmax = 6;
    Pcg32 rng(9, 0);
    const glm::dmat3 R = RandomRotation(rng);
    auto f = [](const glm::dvec3& d) { return std::exp(d.x + 0.5 * d.y * d.z) + d.z * d.z * d.x; };
    const SphereQuadrature q = GaussSphere(40);
    std::vector<double> cf(CoeffCount(lmax), 0.0), cg(CoeffCount(lmax), 0.0), y(CoeffCount(lmax));
    for (std::size_t s = 0; s < q.directions.size(); ++s) {
      const glm::dvec3 d = q.directions[s];
      EvalBasis(lmax, d, y.data());
      const double fv = f(d), gv = f(glm::transpose(R) * d);
      for (int k = 0; k < CoeffCount(lmax); ++k) {
        cf[k] += q.weights[s] * fv * y[k];
        cg[k] += q.weights[s] * gv * y[k];
      }
    }
    std::vector<double> rotated(cf.size());
    ShRotation(R, lmax).Apply(cf.data(), rotated.data());
    for (std::size_t k = 0; k < cf.size(); ++k) CHECK(std::abs(rotated[k] - cg[k]) < kCommuteTolerance);
  }

  TEST_CASE("lmax 64, 100 and 200: orthogonal to 1e-12 and Y(R d) = D Y(d) to 1e-11") {
    // What the rotation promises at every order it accepts. Random rotations and three
    // near-degenerate ones (beta = 1e-9 and pi - 1e-9, where the Euler angles alpha and gamma are
    // ill-determined alone, and an exact half turn about x).
    constexpr double kOrthogonalityLimit = 1e-12;
    constexpr double kEquivarianceLimit = 1e-11;
    Pcg32 rng(10, 0);
    std::vector<glm::dmat3> rotations = {RandomRotation(rng), AxisAngle(RandomDirection(rng), 1e-9) * RandomRotation(rng),
                                         AxisAngle({0.6, 0.8, 0.0}, 1e-9), AxisAngle({1, 0, 0}, kPi - 1e-9),
                                         AxisAngle({1, 0, 0}, kPi)};
    // Scaled under a sanitizer (tests/README.md): lmax 200 alone, with one random rotation and
    // the near half turn (the orders below take the same code).
    for (int lmax : {64, 100, 200}) {
      if (test::kSanitized && lmax != 200) continue;
      for (std::size_t r = 0; r < rotations.size(); ++r) {
        if (lmax != 200 && r > 1) continue;  // the degenerate cases once, at the highest order
        if (test::kSanitized && r != 0 && r != 3) continue;
        const ShRotation rot(rotations[r], lmax);
        const double ortho = BandOrthogonalityError(rot, lmax > 64 ? 7 : 1);
        double apply = 0.0;
        for (int t = 0; t < 3; ++t) apply = std::max(apply, ApplyError(rot, rotations[r], RandomDirection(rng)));
        MESSAGE("lmax " << lmax << ", rotation " << r << ": orthogonality error " << ortho
                        << ", Y(Rd) - D Y(d) " << apply);
        CHECK(ortho < kOrthogonalityLimit);
        CHECK(apply < kEquivarianceLimit);
      }
    }
  }

  TEST_CASE("orders beyond the basis are refused, not returned as garbage") {
    CHECK_THROWS_AS(ShRotation(glm::dmat3(1.0), kMaxBasisLmax + 1), Error);
    CHECK_THROWS_AS(ShRotation(glm::dmat3(1.0), -1), Error);
  }

  TEST_CASE("Wigner d by the recurrence in l equals Wigner's explicit sum") {
    // The explicit sum cancels for large l; to l = 14 in long double it is good to ~1e-15.
    constexpr double kExplicitTolerance = 1e-13;
    const int lmax = 14;
    std::vector<double> run(lmax + 1);
    double worst = 0.0;
    for (double beta : {0.0, 1e-7, 0.3, kPi / 2, 2.5, kPi - 1e-7, kPi}) {
      for (int m = -lmax; m <= lmax; ++m)
        for (int k = -lmax; k <= lmax; ++k) {
          WignerDRun(m, k, beta, lmax, run.data());
          for (int l = std::max(std::abs(m), std::abs(k)); l <= lmax; ++l)
            worst = std::max(worst, std::abs(run[l] - WignerDExplicit(l, m, k, beta)));
        }
    }
    MESSAGE("worst |recurrence - explicit| to l = " << lmax << ": " << worst);
    CHECK(worst < kExplicitTolerance);
    // One hand value: d^1_{10}(beta) = -sin(beta) / sqrt(2).
    WignerDRun(1, 0, 0.4, 1, run.data());
    CHECK(run[1] == doctest::Approx(-std::sin(0.4) / std::sqrt(2.0)).epsilon(1e-15));
  }

  TEST_CASE("the course's projection method equals the exact matrices for bands 1 and 2") {
    Pcg32 rng(12, 0);
    for (int trial = 0; trial < 10; ++trial) {
      const glm::dmat3 R = RandomRotation(rng);
      const ShRotation rot(R, 2);
      for (int l = 1; l <= 2; ++l) {
        const auto course = CourseBandMatrix(R, l);
        for (std::size_t i = 0; i < course.size(); ++i)
          CHECK(std::abs(course[i] - rot.Band(l)[i]) < kRotationTolerance);
      }
    }
  }
}
