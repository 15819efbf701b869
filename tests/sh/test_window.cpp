// The Hann window of `--window hann` (sh/window.h): every band's weight for lmax 0..12 against
// the header's formula w_l = (1 + cos(pi l / (lmax + 1))) / 2 written out here as cos^2(pi l /
// (2 (lmax + 1))) (the same function by the half-angle identity, so a slip in either form shows),
// against values worked out by hand, against the Hann window's symmetry w_l + w_{lmax+1-l} = 1,
// and the weights as ApplyWindow puts them on each band's coefficients.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "core/error.h"
#include "sh/coeffs.h"
#include "sh/window.h"
#include "tests/name_checks.h"

using namespace prt;

namespace {

// The weight is one cosine of a double: rounding of a few ulps of 1.
constexpr double kRounding = 1e-14;
// Highest lmax checked: every band of every lmax up to it (the command line allows 64, the
// formula has nothing that changes with lmax beyond this).
constexpr int kLastLmax = 12;

/// w_l by the half-angle form of the header's formula, computed here and not by the code.
double HannByHand(int l, int lmax) {
  const double c = std::cos(kPi * double(l) / (2.0 * double(lmax + 1)));
  return c * c;
}

}  // namespace

TEST_SUITE("sh") {
  TEST_CASE("--window hann: w_l = (1 + cos(pi l / (lmax + 1))) / 2 for every band of lmax 0..12") {
    CHECK(WindowFromName("hann") == Window::kHann);
    CHECK(std::string(WindowName(Window::kHann)) == "hann");
    for (int lmax = 0; lmax <= kLastLmax; ++lmax)
      for (int l = 0; l <= lmax; ++l) {
        INFO("lmax " << lmax << ", band " << l);
        const double w = WindowWeight(Window::kHann, l, lmax);
        CHECK(std::abs(w - HannByHand(l, lmax)) < kRounding);
        // Band 0 untouched (the mean radiance kept); a window that falls toward 0 at lmax + 1
        // (never reached, so every band keeps some weight), and Hann's own symmetry about half
        // of lmax + 1: cos(pi (lmax + 1 - l) / (lmax + 1)) = -cos(pi l / (lmax + 1)).
        if (l == 0) CHECK(w == 1.0);
        if (l > 0) CHECK(w < WindowWeight(Window::kHann, l - 1, lmax));
        CHECK(w > 0.0);
        if (l > 0) CHECK(std::abs(w + WindowWeight(Window::kHann, lmax + 1 - l, lmax) - 1.0) < kRounding);
      }
  }

  TEST_CASE("--window hann: hand-computed weights at lmax 1, 2, 3 and 5") {
    // lmax 1: cos(pi/2) = 0, so w_1 = 1/2.
    CHECK(std::abs(WindowWeight(Window::kHann, 1, 1) - 0.5) < kRounding);
    // lmax 2: cos(pi/3) = 1/2 and cos(2 pi/3) = -1/2: 3/4 and 1/4.
    CHECK(std::abs(WindowWeight(Window::kHann, 1, 2) - 0.75) < kRounding);
    CHECK(std::abs(WindowWeight(Window::kHann, 2, 2) - 0.25) < kRounding);
    // lmax 3: cos(pi/4) = sqrt(2)/2: (2 + sqrt 2)/4, 1/2, (2 - sqrt 2)/4.
    CHECK(std::abs(WindowWeight(Window::kHann, 1, 3) - 0.85355339059327376) < kRounding);
    CHECK(std::abs(WindowWeight(Window::kHann, 2, 3) - 0.5) < kRounding);
    CHECK(std::abs(WindowWeight(Window::kHann, 3, 3) - 0.14644660940672624) < kRounding);
    // lmax 5: cos(pi/6) = sqrt(3)/2, cos(pi/3) = 1/2: (2 + sqrt 3)/4, 3/4, 1/2, 1/4, (2 - sqrt 3)/4.
    const double expected[] = {1.0, 0.93301270189221932, 0.75, 0.5, 0.25, 0.066987298107780677};
    for (int l = 0; l <= 5; ++l) {
      INFO("band " << l);
      CHECK(std::abs(WindowWeight(Window::kHann, l, 5) - expected[l]) < kRounding);
    }
  }

  TEST_CASE("--window hann: ApplyWindow multiplies all 2l + 1 coefficients of band l by w_l") {
    for (int lmax : {0, 1, 2, 4, 7}) {
      // Coefficient k gets a value of its own per channel, so a weight on the wrong index shows.
      ShRgb c(CoeffCount(lmax));
      for (std::size_t k = 0; k < c.size(); ++k) c[k] = glm::dvec3(1.0 + double(k), -2.0 - double(k), 0.5);
      const ShRgb in = c;
      ApplyWindow(Window::kHann, c);
      for (int l = 0; l <= lmax; ++l)
        for (int m = -l; m <= l; ++m) {
          INFO("lmax " << lmax << ", l " << l << ", m " << m);
          const int k = l * l + l + m;  // band l holds l^2 .. (l + 1)^2 - 1 (sh/coeffs.h)
          const double w = HannByHand(l, lmax);
          for (int ch = 0; ch < 3; ++ch) CHECK(std::abs(c[k][ch] - w * in[k][ch]) < kRounding * std::abs(in[k][ch]) + kRounding);
        }
    }
  }

  TEST_CASE("--window: each name names its own window, and no other name is one") {
    const std::vector<std::pair<Window, std::string>> words = {
        {Window::kNone, "none"}, {Window::kHann, "hann"}, {Window::kLanczos, "lanczos"}};
    CHECK(test::NameProblems<Window>(words, WindowName, test::Refusing<Window>(WindowFromName), WindowNames()) == "");
    // "auto" is the command line's (sh/dering.h), chosen before a Window is asked for.
    CHECK_THROWS_WITH_AS(WindowFromName("auto"), "window 'auto' is not one of none, hann, lanczos", Error);
  }
}
