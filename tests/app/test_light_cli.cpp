// `prt light` from outside. --rotate: the printed light turned, checked against properties that
// hold for any correct rotation, whatever the implementation: about +Z each (m, -m) pair turns
// by cos/sin(m a); band 1 turns as the vector it is; every band keeps its energy, at lmax 200 too
// (a drifting rotation inflates it). --window auto: the printed light is nowhere negative, by a
// scan of directions of its own.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "precompute_io/light_txt.h"
#include "sh/coeffs.h"
#include "tests/sh/sh_test_util.h"
#include "tests/test_process.h"

using namespace prt;
using namespace prt::test;

namespace {

// light.txt prints 9 significant digits: relative rounding 5e-9 a coefficient.
constexpr double kPrintedTolerance = 2e-8;

/// The printed light, read as light.txt is (a square count of finite `R G B` lines).
ShRgb Coefficients(const std::string& text) { return ParseLightTxt(text, "stdout"); }

ShRgb Light(const std::string& arguments) {
  const RunResult r = RunPrt("light --quiet " + arguments);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  return Coefficients(r.out);
}

/// Sum over the band's coefficients of squares, per channel.
glm::dvec3 BandEnergy(const ShRgb& c, int l) {
  glm::dvec3 e(0.0);
  for (int k = l * l; k < (l + 1) * (l + 1); ++k) e += c[k] * c[k];
  return e;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("prt light --rotate about +Z turns each (m, -m) pair by cos/sin(m a)") {
    const int lmax = 6;
    const double degrees = 37.0, a = degrees * kPi / 180.0;
    const auto plain = Light("--lmax 6");
    const auto turned = Light("--lmax 6 --rotate 0,0,2:37");
    REQUIRE(plain.size() == std::size_t(CoeffCount(lmax)));
    REQUIRE(turned.size() == plain.size());
    const double scale = glm::length(plain[0]);
    for (int l = 0; l <= lmax; ++l) {
      CHECK(glm::length(turned[ShIndex(l, 0)] - plain[ShIndex(l, 0)]) < kPrintedTolerance * scale);
      for (int m = 1; m <= l; ++m) {
        const glm::dvec3 c = plain[ShIndex(l, m)], s = plain[ShIndex(l, -m)];
        CHECK(glm::length(turned[ShIndex(l, m)] - (std::cos(m * a) * c - std::sin(m * a) * s)) < kPrintedTolerance * scale);
        CHECK(glm::length(turned[ShIndex(l, -m)] - (std::sin(m * a) * c + std::cos(m * a) * s)) < kPrintedTolerance * scale);
      }
    }
  }

  TEST_CASE("prt light --lmax 200 --rotate: band 1 turns as a vector, every band keeps its energy") {
    const int lmax = 200;
    const std::string bands = " --lmax " + std::to_string(lmax);
    const auto plain = Light(bands);
    const auto turned = Light(bands + " --rotate 1,2,3:40");
    REQUIRE(plain.size() == std::size_t(CoeffCount(lmax)));
    REQUIRE(turned.size() == plain.size());
    // Band 1 is (-y, z, -x) up to one constant: turning the light by R turns that vector by R.
    const glm::dvec3 k = glm::normalize(glm::dvec3(1, 2, 3));
    const double a = 40.0 * kPi / 180.0;
    for (int ch = 0; ch < 3; ++ch) {
      const glm::dvec3 v(-plain[3][ch], -plain[1][ch], plain[2][ch]);
      const glm::dvec3 r = v * std::cos(a) + glm::cross(k, v) * std::sin(a) + k * glm::dot(k, v) * (1 - std::cos(a));
      const glm::dvec3 got(-turned[3][ch], -turned[1][ch], turned[2][ch]);
      CHECK(glm::length(got - r) < kPrintedTolerance * glm::length(v) + 1e-12);
    }
    double worst = 0.0;
    for (int l = 0; l <= lmax; ++l) {
      const glm::dvec3 before = BandEnergy(plain, l), after = BandEnergy(turned, l);
      for (int ch = 0; ch < 3; ++ch)
        if (before[ch] > 0) worst = std::max(worst, std::abs(after[ch] / before[ch] - 1.0));
    }
    MESSAGE("worst relative change of a band's energy to lmax " << lmax << ": " << worst);
    CHECK(worst < 1e-6);  // printed digits only; a drifting rotation changes it by orders of magnitude
  }

  TEST_CASE("prt light --rotate and --lmax refuse what they cannot do, in one line") {
    for (const std::string bad : {"--rotate 0,0,0:30", "--rotate 1,2,3", "--rotate 1,2:30", "--rotate 1,2,3:ninety",
                                  "--rotate 1,2,3,4:5", "--rotate 1,nan,3:5", "--lmax 201", "--lmax 100 --window auto"}) {
      const RunResult r = RunPrt("light " + bad);
      INFO(bad << ": " << r.err);
      CHECK(r.exit_code == 2);
      CHECK(r.out.empty());
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
  }

  TEST_CASE("prt light --window auto: a sun of 1e5 x the mean prints a light that is nowhere negative") {
    const std::string env = "--env sky:sun=300,radius=0.25 --lmax 8";
    const RunResult plain = RunPrt("light " + env);
    const RunResult windowed = RunPrt("light " + env + " --window auto");
    REQUIRE(plain.exit_code == 0);
    REQUIRE(windowed.exit_code == 0);
    // The summary names the window, the lowest radiance without and with it, and its cost.
    CHECK(windowed.err.find("without a window") != std::string::npos);
    CHECK(windowed.err.find("with one") != std::string::npos);
    CHECK(windowed.err.find("of the irradiance") != std::string::npos);
    // 40,000 directions on a latitude-longitude grid, nodes offset from the poles.
    std::vector<glm::dvec3> grid;
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 200; ++j) {
        const double z = 1.0 - 2.0 * (i + 0.5) / 200, phi = 2.0 * kPi * (j + 0.25) / 200;
        const double s = std::sqrt(1.0 - z * z);
        grid.push_back({s * std::cos(phi), s * std::sin(phi), z});
      }
    auto lowest = [&grid](const ShRgb& c) { return test::LowestOver(c, grid); };
    const auto before = Coefficients(plain.out), after = Coefficients(windowed.out);
    REQUIRE(after.size() == std::size_t(CoeffCount(8)));
    CHECK(lowest(before) < 0);   // it rings unwindowed
    CHECK(lowest(after) >= 0);   // and not with auto
    CHECK(glm::length(after[0] - before[0]) < kPrintedTolerance * glm::length(before[0]));  // mean kept
  }
}
