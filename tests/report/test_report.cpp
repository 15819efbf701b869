// prt report's parts in-process: the stability suite's wavelet cases on the scene asked for,
// --lmax auto, the plot. (The commands: test_report_cli.cpp; the README's stability command with
// every case's figure: tests/app/test_readme_stability.cpp.)
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "env/procedural.h"
#include "raster/plot.h"
#include "report/report_auto_lmax.h"
#include "report/stability.h"
#include "tests/test_support.h"

namespace {

/// Count of pixels that are not pure white.
std::size_t Inked(const prt::Image8& im) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < im.rgb.size(); i += 3) n += (im.rgb[i] != 255 || im.rgb[i + 1] != 255 || im.rgb[i + 2] != 255);
  return n;
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("stability: the bases' cases (the wavelets') run on the scene StabilityOptions asks for") {
    // A knot of 16 x 3 over a 2 x 2 ground: 48 + 3^2 = 57 vertices, named with its ground in each
    // wavelet case's checks; the cases with fixed inputs left out. The wavelet cases' figures on
    // a scene this coarse are not the measured ones, so only that they are numbers is checked.
    const auto cases = prt::RunStabilityCases(prt::StabilityOptions{{16, 3, 2}, false});
    CHECK(cases.size() == 2);
    int wavelet = 0;
    for (const auto& c : cases) {
      if (c.name.rfind("wavelet_sun_", 0) != 0) continue;
      CAPTURE(c.checks);
      CHECK(c.checks.find("on a 2 x 2 ground under sky (2-degree sun), 57 vertices,") != std::string::npos);
      CHECK(std::isfinite(c.figure));
      ++wavelet;
    }
    CHECK(wavelet == 2);
  }

  TEST_CASE("--lmax auto: the smallest band count whose irradiance error is within the tolerance") {
    const auto furnace = prt::MakeFurnace(1.0);
    CHECK(prt::ChooseLmax(*furnace, 1e-6, 64).lmax == 0);  // constant light: band 0 is all of it
    const auto sky = prt::MakeSky(prt::SkyParams{});
    const prt::AutoLmax loose = prt::ChooseLmax(*sky, 0.1, 64), tight = prt::ChooseLmax(*sky, 0.01, 64);
    CHECK(loose.error <= 0.1);
    CHECK(tight.error <= 0.01);
    CHECK(tight.lmax > loose.lmax);
    CHECK(prt::ChooseLmax(*sky, 0.01, tight.lmax - 1).error > 0.01);  // one band fewer is not enough
  }

  TEST_CASE("plot: axes, lines and legend are drawn, points that log axes cannot show are skipped") {
    // Series a is y = 1e-4 / x: a straight falling line on log-log axes. Series b has one point
    // a log axis can show (x = 0 and y < 0 are skipped): no line, only its legend entry.
    prt::PlotSeries a, b;
    a.label = "a", a.x = {1e-3, 1e-2, 1e-1}, a.y = {1e-1, 1e-2, 1e-3}, a.color = prt::PlotColor(0);
    b.label = "b", b.x = {0.0, 1e-2, 1.0}, b.y = {1.0, -1.0, 1e-2}, b.color = prt::PlotColor(1), b.dashed = true;
    prt::PlotOptions o;
    o.title = "t", o.x_label = "x", o.y_label = "y";
    const prt::Image8 im = prt::DrawLogLogPlot({a, b}, o);
    REQUIRE(im.width == o.width);
    REQUIRE(im.height == o.height);
    const auto pixels_of = [](const prt::Image8& image, const glm::vec3& colour) {
      std::vector<std::pair<int, int>> at;
      const glm::ivec3 c = glm::ivec3(glm::round(colour * 255.0f));
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
          if (prt::test::PixelAt(image, x, y) == c) at.emplace_back(x, y);
      return at;
    };
    const auto line_a = pixels_of(im, a.color), line_b = pixels_of(im, b.color);
    CAPTURE(line_a.size());
    CAPTURE(line_b.size());
    REQUIRE(line_a.size() > 200);
    CHECK(line_b.size() > 0);               // b's legend entry
    CHECK(line_b.size() < line_a.size() / 2);  // but no line of its own
    // a's pixels (its legend swatch, a short horizontal line, aside) fall on one straight line
    // going down to the right: pixel y grows linearly with pixel x.
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, n = 0;
    for (const auto& [x, y] : line_a) {
      if (x > im.width * 3 / 4) continue;  // the legend is on the right
      sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y, sxy += double(x) * y, ++n;
    }
    const double correlation = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
    CHECK(correlation > 0.99);
    CHECK(Inked(im) > 2000);
    const prt::Image8 empty = prt::DrawLogLogPlot({}, o);
    CHECK(Inked(empty) > 0);  // axes even without data
    CHECK(pixels_of(empty, a.color).empty());
  }

}
