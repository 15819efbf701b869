#include <doctest/doctest.h>

#include <cmath>

#include "core/error.h"
#include "raster/image_diff.h"

namespace {

prt::Image8 Gradient(int w, int h) {
  prt::Image8 image(w, h);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i * 7 % 251);
  return image;
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("Identical images: all zero, infinite PSNR") {
    const prt::Image8 a = Gradient(5, 4);
    const prt::DiffMetrics m = prt::CompareImages(a, a);
    CHECK(m.max_abs == 0);
    CHECK(m.mean_abs == 0.0);
    CHECK(m.differing_pixels == 0);
    CHECK(m.pixels_over_one == 0);
    CHECK(std::isinf(m.psnr));
    CHECK(prt::FormatDiffMetrics(m) == "max_abs=0 mean_abs=0 rmse=0 psnr=inf differing_pixels=0");
    const prt::Image8 d = prt::AmplifiedDifference(a, a);
    for (auto v : d.rgb) CHECK(v == 0);
  }

  TEST_CASE("Slightly different images: exact metrics and a visible difference image") {
    const prt::Image8 a = Gradient(5, 4);
    prt::Image8 b = a;
    b.rgb[7] = static_cast<std::uint8_t>(b.rgb[7] + 3);   // pixel 2
    b.rgb[30] = static_cast<std::uint8_t>(b.rgb[30] - 1);  // pixel 10
    const prt::DiffMetrics m = prt::CompareImages(a, b);
    CHECK(m.max_abs == 3);
    CHECK(m.differing_pixels == 2);
    CHECK(m.pixels_over_one == 1);  // pixel 2 (3 levels); pixel 10 is 1 level off
    CHECK(m.mean_abs == doctest::Approx(4.0 / 60.0));
    CHECK(m.rmse == doctest::Approx(std::sqrt(10.0 / 60.0)));
    CHECK(m.psnr == doctest::Approx(20.0 * std::log10(255.0 / std::sqrt(10.0 / 60.0))));
    const prt::Image8 d = prt::AmplifiedDifference(a, b);
    CHECK(d.rgb[7] == 255);
    CHECK(d.rgb[30] == 64 + 191 / 3);
    CHECK(d.rgb[0] == 0);
  }

  TEST_CASE("A difference in any one channel counts the same: red, green and blue alike") {
    // CompareImages judges every golden image: a channel it skipped would let any bug in that
    // channel through every golden test.
    const prt::Image8 a = Gradient(5, 4);
    for (int channel = 0; channel < 3; ++channel) {
      prt::Image8 b = a;
      const std::size_t at = 3 * 13 + channel;  // pixel 13
      b.rgb[at] = static_cast<std::uint8_t>(b.rgb[at] ^ 0x10);  // a change of 16
      const prt::DiffMetrics m = prt::CompareImages(a, b);
      CAPTURE(channel);
      CHECK(m.max_abs == 16);
      CHECK(m.differing_pixels == 1);
      CHECK(m.pixels_over_one == 1);
      CHECK(m.mean_abs == doctest::Approx(16.0 / 60.0));
      CHECK(m.rmse == doctest::Approx(std::sqrt(256.0 / 60.0)));
      const prt::Image8 d = prt::AmplifiedDifference(a, b);
      CHECK(d.rgb[at] > 0);
      for (std::size_t i = 0; i < d.rgb.size(); ++i)
        if (i != at) CHECK(d.rgb[i] == 0);
    }
  }

  TEST_CASE("Images of different sizes are an error") {
    CHECK_THROWS_WITH_AS(prt::CompareImages(Gradient(5, 4), Gradient(4, 5)),
                         doctest::Contains("differ in size"), prt::Error);
  }
}
