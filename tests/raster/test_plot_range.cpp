// The axes of raster/plot.h: tight around the data (within the nearest ticks m 10^e outside it),
// not widened to whole decades, which left most of the report's time axis empty.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <stb_easy_font.h>

#include "core/image.h"
#include "raster/annotate.h"
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

  TEST_CASE("plot: points on the ends of both ranges are drawn whole inside the axes") {
    // Values on ticks make the range end exactly at them (the basis chart's 1 % point sat on the
    // x axis, half of its marker below it). Every pixel of the series must lie inside the box the
    // axis lines draw, clear of the lines themselves.
    PlotSeries s;
    s.label = "ends";
    s.x = {1e-2, 1.0, 3e-1};
    s.y = {1e-2, 1.0, 2e-2};
    s.color = glm::vec3(1.0f, 0.0f, 0.0f);
    s.marker = PlotMarker::kSquare;
    PlotOptions o;
    o.width = 600, o.height = 400;
    const Image8 im = DrawLogLogPlot({s}, o);
    // The axis lines: the leftmost column and the lowest row black for over half the image.
    const auto black = [&im](int x, int y) {
      const std::size_t i = 3 * (std::size_t(y) * im.width + x);
      return im.rgb[i] == 0 && im.rgb[i + 1] == 0 && im.rgb[i + 2] == 0;
    };
    int axis_x = -1, axis_y = -1, axis_end = -1;
    for (int x = 0; x < im.width && axis_x < 0; ++x) {
      int run = 0;
      for (int y = 0; y < im.height; ++y) run += black(x, y);
      if (run > im.height / 2) axis_x = x;
    }
    for (int y = im.height - 1; y >= 0 && axis_y < 0; --y) {
      int run = 0;
      for (int x = 0; x < im.width; ++x) run += black(x, y);
      if (run > im.width / 2) axis_y = y;
    }
    REQUIRE(axis_x > 0);
    REQUIRE(axis_y > 0);
    for (int x = axis_x; x < im.width && black(x, axis_y); ++x) axis_end = x;
    int red = 0;
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x <= axis_end; ++x) {  // the legend, right of the axes, left out
        const std::size_t i = 3 * (std::size_t(y) * im.width + x);
        if (im.rgb[i] != 255 || im.rgb[i + 1] != 0 || im.rgb[i + 2] != 0) continue;
        ++red;
        CAPTURE(x);
        CAPTURE(y);
        CHECK(x > axis_x + 1);
        CHECK(y < axis_y - 1);
      }
    CHECK(red > 3 * 40);  // three markers and the lines between them
  }

  TEST_CASE("plot: each tick label names the tick it stands under, and the ends of lmax 1..8 read 1 and 8") {
    // The glossy plot's x axis: lmax 1, 2, 3, 4, 6, 8 (the quick study's).
    const LogRange lmax = LogAxisRange({1, 2, 3, 4, 6, 8});
    CHECK(lmax.lo == 1.0);
    CHECK(lmax.hi == 8.0);
    const auto labels = LogAxisLabels(lmax, 0.05);
    REQUIRE(!labels.empty());
    CHECK(labels.front().second == "1");
    CHECK(labels.back().second == "8");
    for (const auto& [value, text] : labels) {
      CAPTURE(text);
      CHECK(value >= lmax.lo);
      CHECK(value <= lmax.hi);
      CHECK(std::stod(text) == doctest::Approx(value));  // "2e-3" parses too
    }
    // Seconds over two decades: powers of ten only, plus the ends.
    for (const auto& [value, text] : LogAxisLabels(LogAxisRange({4.3e-3, 0.9}), 0.05)) {
      CAPTURE(text);
      CHECK(std::stod(text) == doctest::Approx(value));
    }
  }

  TEST_CASE("text: every printable character is drawn whole, as stb_easy_font lays it out") {
    // The ink of DrawText(c) against the area of every quad stb_easy_font gives for c with a
    // buffer far larger than any character needs: a buffer cut short drops the last strokes
    // (a lone "8" once lost its lower left one and read as a 9).
    for (int ch = 33; ch < 127; ++ch) {
      char text[2] = {static_cast<char>(ch), '\0'};
      std::vector<unsigned char> quads(64 * 1024);
      unsigned char rgba[4] = {0, 0, 0, 255};
      const int n = stb_easy_font_print(0, 0, text, rgba, quads.data(), static_cast<int>(quads.size()));
      Image8 expected(16, 16), drawn(16, 16);
      std::fill(expected.rgb.begin(), expected.rgb.end(), std::uint8_t{255});
      std::fill(drawn.rgb.begin(), drawn.rgb.end(), std::uint8_t{255});
      for (int q = 0; q < n; ++q) {
        const float* v = reinterpret_cast<const float*>(quads.data() + q * 64);
        for (int y = int(v[1]); y < int(v[9]); ++y)
          for (int x = int(v[0]); x < int(v[8]); ++x)
            for (int c = 0; c < 3; ++c) expected.rgb[3 * (y * 16 + x) + c] = 0;
      }
      DrawText(drawn, 0, 0, text, glm::vec3(0.f));
      CAPTURE(text);
      CHECK(drawn.rgb == expected.rgb);
    }
  }
}

}  // namespace prt
