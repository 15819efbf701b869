#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "raster/tonemap.h"
#include "tests/name_checks.h"

namespace {

// The sRGB encoding straight from its definition, in double.
double SrgbTimes255(double v) {
  v = std::min(std::max(v, 0.0), 1.0);
  return 255.0 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("EncodeSrgb8 rounds the sRGB curve exactly") {
    // Values within this distance (in 8-bit steps) of a rounding threshold may go either way:
    // the table thresholds are floats, the reference is double.
    constexpr double kThresholdSlack = 1e-4;
    int checked = 0;
    for (int i = 0; i <= 200000; ++i) {
      const float v = static_cast<float>(i) / 200000.f * 1.1f - 0.05f;
      const double exact = SrgbTimes255(v);
      if (std::fabs(exact - std::floor(exact) - 0.5) < kThresholdSlack) continue;
      CHECK(int(prt::EncodeSrgb8(v)) == int(std::lround(exact)));
      ++checked;
    }
    CHECK(checked > 190000);
    CHECK(prt::EncodeSrgb8(std::numeric_limits<float>::quiet_NaN()) == 0);
    CHECK(prt::EncodeSrgb8(std::numeric_limits<float>::infinity()) == 255);
  }

  TEST_CASE("EncodeSrgb8 is the count of float thresholds at or below v, at every threshold") {
    // The table's one-comparison search must agree with a full search over the 255 rounding
    // thresholds (computed here from the sRGB definition, rounded to float) for floats just
    // below, at and above each threshold.
    std::vector<float> threshold(256, 0.f);
    for (int k = 1; k < 256; ++k) {
      const double s = (k - 0.5) / 255.0;
      threshold[k] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
    }
    for (int k = 1; k < 256; ++k) {
      float v = threshold[k];
      for (int i = 0; i < 4; ++i) v = std::nextafter(v, 0.f);
      for (int step = 0; step < 9; ++step, v = std::nextafter(v, 2.f)) {
        int expected = 0;
        while (expected < 255 && threshold[expected + 1] <= v) ++expected;
        REQUIRE(int(prt::EncodeSrgb8(v)) == expected);
      }
    }
  }

  TEST_CASE("ToneMap encodes the floats around every threshold as EncodeSrgb8 does, 32 at a time or not") {
    // The rows' encoding has a vector version (AVX2 gathers from the same table, 32 values at
    // a time, the rest one by one); these are the values where a wrong index, comparison or
    // byte order would show. 255 thresholds x 9 floats, in rows of several widths so that the
    // vector loop and its tail both see them.
    std::vector<float> values;
    for (int k = 1; k < 256; ++k) {
      const double s = (k - 0.5) / 255.0;
      float v = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
      for (int i = 0; i < 4; ++i) v = std::nextafter(v, 0.f);
      for (int step = 0; step < 9; ++step, v = std::nextafter(v, 2.f)) values.push_back(v);
    }
    values.push_back(0.f);
    values.push_back(1.f);
    for (int width : {1, 11, 64, 765}) {
      const int height = static_cast<int>((values.size() + 3 * width - 1) / (3 * width));
      prt::ImageF image(width, height);
      float* flat = reinterpret_cast<float*>(image.pixels.data());
      for (std::size_t i = 0; i < 3 * image.pixels.size(); ++i) flat[i] = values[i % values.size()];
      const prt::ToneMapped out = prt::ToneMap(image);
      for (std::size_t i = 0; i < 3 * image.pixels.size(); ++i)
        REQUIRE(int(out.image.rgb[i]) == int(prt::EncodeSrgb8(flat[i])));
    }
  }

  TEST_CASE("ToneMap equals EncodeSrgb8 of each channel through every curve, in rows with and without bad values") {
    // A 1000-pixel-wide image (more than one block of the row loop) of values over [0, 1.2]
    // with every channel different; row 1 also holds a NaN and a negative, row 0 none.
    const int w = 1000;
    prt::ImageF image(w, 2);
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < w; ++x)
        image.at(x, y) = glm::vec3(1.2f * float(x) / float(w), 0.37f * float(x % 7), float((x * 37) % 1000) / 999.f);
    image.at(17, 1).y = std::numeric_limits<float>::quiet_NaN();
    image.at(900, 1).z = -0.25f;
    for (prt::ToneCurve curve : {prt::ToneCurve::kSrgb, prt::ToneCurve::kReinhard, prt::ToneCurve::kAces}) {
      prt::ToneMapOptions options;
      options.curve = curve;
      options.exposure_ev = 0.5f;
      const prt::ToneMapped out = prt::ToneMap(image, options);
      CHECK(out.nan_pixels == 1);
      CHECK(out.negative_pixels == 1);
      const float scale = std::exp2(0.5f);
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < w; ++x)
          for (int c = 0; c < 3; ++c) {
            float v = image.at(x, y)[c] * scale;
            v = v > 0.f ? prt::ApplyToneCurve(curve, v) : 0.f;
            REQUIRE(int(out.image.rgb[3 * (std::size_t(y) * w + x) + c]) == int(prt::EncodeSrgb8(v)));
          }
    }
  }

  TEST_CASE("Negative radiance and NaN are clamped to zero and counted") {
    prt::ImageF image(3, 2);
    image.at(0, 0) = glm::vec3(-0.5f, 0.2f, 0.2f);                        // negative
    image.at(1, 0) = glm::vec3(-1e-6f, -2.f, -3.f);                       // negative, one pixel
    image.at(2, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 1.f, 1.f);  // NaN
    image.at(0, 1) = glm::vec3(0.5f);
    image.at(1, 1) = glm::vec3(-std::numeric_limits<float>::infinity(), 0.f, 0.f);
    image.at(2, 1) = glm::vec3(std::numeric_limits<float>::infinity());
    const prt::ToneMapped out = prt::ToneMap(image);
    CHECK(out.negative_pixels == 3);
    CHECK(out.nan_pixels == 1);
    CHECK(out.image.rgb[0] == 0);                   // -0.5 -> 0, not wrapped to 255 or so
    CHECK(out.image.rgb[3 * 2 + 0] == 0);           // NaN -> 0
    CHECK(out.image.rgb[3 * 2 + 1] == 255);
    CHECK(out.image.rgb[3 * 3 + 0] == 188);         // sRGB(0.5) = 0.7354 -> 187.5 -> 188
    for (int c = 0; c < 3; ++c) CHECK(out.image.rgb[3 * 5 + c] == 255);
  }

  TEST_CASE("Exposure and the tone curves") {
    prt::ImageF image(1, 1);
    image.at(0, 0) = glm::vec3(0.25f, 1.f, 100.f);
    prt::ToneMapOptions options;
    options.exposure_ev = 1.f;  // 0.25 -> 0.5
    CHECK(prt::ToneMap(image, options).image.rgb[0] == 188);
    options.exposure_ev = 0.f;
    options.curve = prt::ToneCurve::kReinhard;  // 1 -> 1/2
    CHECK(prt::ToneMap(image, options).image.rgb[1] == 188);
    CHECK(prt::ApplyToneCurve(prt::ToneCurve::kReinhard, 100.f) == doctest::Approx(100.f / 101.f));
    // Narkowicz's fit: 0 -> 0, 1 -> about 0.8, large -> 2.51 / 2.43 (clamped to white).
    CHECK(prt::ApplyToneCurve(prt::ToneCurve::kAces, 0.f) == 0.f);
    CHECK(prt::ApplyToneCurve(prt::ToneCurve::kAces, 1.f) == doctest::Approx(2.54 / 3.16));
    CHECK(prt::ApplyToneCurve(prt::ToneCurve::kAces, 1e30f) == doctest::Approx(2.51 / 2.43));
    CHECK(prt::ParseToneCurve("aces") == prt::ToneCurve::kAces);
    CHECK_FALSE(prt::ParseToneCurve("filmic").has_value());
    CHECK(std::string(prt::ToneCurveName(prt::ToneCurve::kReinhard)) == "reinhard");
  }

  TEST_CASE("--tonemap: each name names its own curve, and no other name is one") {
    const std::vector<std::pair<prt::ToneCurve, std::string>> words = {
        {prt::ToneCurve::kSrgb, "srgb"}, {prt::ToneCurve::kReinhard, "reinhard"}, {prt::ToneCurve::kAces, "aces"}};
    CHECK(prt::test::NameProblems<prt::ToneCurve>(words, prt::ToneCurveName, prt::ParseToneCurve,
                                                  prt::ToneCurveNames()) == "");
  }
}
