#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "raster/exposure.h"

namespace {

using prt::ToneCurve;

// An unrounded EV within a few ulps of a rounding tie (x.x5) may round either way, so two EVs
// that differ exactly by an integer in exact arithmetic can differ by one step after rounding.
constexpr double kRoundingSlack = prt::kAutoEvStep + 1e-9;
// Rounding to kAutoEvStep moves the exposure by at most half a step: a factor 2^(step / 2).
constexpr double kHalfStepLog2 = 0.5 * prt::kAutoEvStep + 1e-9;

constexpr ToneCurve kCurves[] = {ToneCurve::kSrgb, ToneCurve::kReinhard, ToneCurve::kAces};

// A 40 x 30 frame: a covered 20 x 16 block of varied colours (luminance from about 0.02 to 2)
// with half-covered edge pixels, on a background of `background` radiance.
prt::RasterImage Frame(float scale, float background = 0.f) {
  prt::RasterImage f;
  f.image = prt::ImageF(40, 30);
  f.coverage.assign(40 * 30, 0.f);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool inside = x >= 10 && x < 30 && y >= 7 && y < 23;
      const bool edge = (x == 9 || x == 30) && y >= 7 && y < 23;
      const std::size_t i = static_cast<std::size_t>(y) * 40 + x;
      if (inside) {
        const float t = static_cast<float>((x * 7 + y * 13) % 17) / 16.f;
        f.image.pixels[i] = scale * glm::vec3(0.02f + 2.f * t * t, 0.03f + 1.5f * t, 0.05f + t * t * t);
        f.coverage[i] = 1.f;
      } else {
        f.image.pixels[i] = glm::vec3(background);
        f.coverage[i] = edge ? 0.5f : 0.f;
      }
    }
  return f;
}

}  // namespace

TEST_SUITE("raster") {
  TEST_CASE("InverseToneCurve finds the exposed value of a display value") {
    // The inverse is bisected down to adjacent floats: a few float ulps.
    constexpr double kInverseTolerance = 1e-6;
    CHECK(prt::InverseToneCurve(ToneCurve::kSrgb, 0.18) == 0.18);
    CHECK(prt::InverseToneCurve(ToneCurve::kReinhard, 0.18) == doctest::Approx(0.18 / 0.82).epsilon(kInverseTolerance));
    for (ToneCurve curve : kCurves)
      for (double display : {0.01, 0.18, 0.5, 0.95})
        CHECK(double(prt::ApplyToneCurve(curve, float(prt::InverseToneCurve(curve, display)))) ==
              doctest::Approx(display).epsilon(kInverseTolerance));
  }

  TEST_CASE("AutoExposureEv moves by -k when the image is scaled by 2^k") {
    for (ToneCurve curve : kCurves) {
      CAPTURE(prt::ToneCurveName(curve));
      const double ev = prt::AutoExposureEv(Frame(1.f), curve);
      CHECK(std::abs(ev) < prt::kMaxAutoEv);
      // A multiple of the step, exactly as "%.1f" prints and parses it back.
      CHECK(ev == std::round(ev * 10.0) / 10.0);
      for (int k : {-6, -1, 3, 9}) {
        CAPTURE(k);
        CHECK(std::abs(prt::AutoExposureEv(Frame(std::ldexp(1.f, k)), curve) - (ev - k)) <= kRoundingSlack);
      }
      CHECK(prt::AutoExposureEv(Frame(1.f), curve) == ev);  // deterministic
    }
  }

  TEST_CASE("AutoExposureEv measures the mesh only") {
    for (ToneCurve curve : kCurves) {
      const double ev = prt::AutoExposureEv(Frame(1.f), curve);
      // A sun-bright background, also in the half-covered edge pixels, changes nothing.
      CHECK(prt::AutoExposureEv(Frame(1.f, 1e4f), curve) == ev);
      // Nor do NaN, infinite, negative and black covered pixels.
      prt::RasterImage f = Frame(1.f);
      f.image.at(12, 8) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
      f.image.at(13, 8) = glm::vec3(std::numeric_limits<float>::infinity());
      f.image.at(14, 8) = glm::vec3(-1.f, 0.5f, 0.5f);
      f.image.at(15, 8) = glm::vec3(0.f);
      prt::RasterImage g = Frame(1.f);
      for (int x = 12; x < 16; ++x) g.coverage[8 * 40 + x] = 0.f;
      CHECK(prt::AutoExposureEv(f, curve) == prt::AutoExposureEv(g, curve));
      // Nothing covered: 0 EV.
      prt::RasterImage empty = Frame(1.f, 3.f);
      std::fill(empty.coverage.begin(), empty.coverage.end(), 0.f);
      CHECK(prt::AutoExposureEv(empty, curve) == 0.0);
      CHECK(prt::AutoExposureEv(prt::RasterImage{}, curve) == 0.0);
    }
  }

  TEST_CASE("AutoExposureEv maps a furnace to the key display value, clamped to +-20 EV") {
    for (ToneCurve curve : kCurves)
      for (float c : {1e-3f, 0.18f, 1.f, 40.f}) {
        CAPTURE(prt::ToneCurveName(curve));
        CAPTURE(c);
        prt::RasterImage f = Frame(1.f, 5.f);
        for (std::size_t i = 0; i < f.coverage.size(); ++i)
          if (f.coverage[i] > 0.f) f.image.pixels[i] = glm::vec3(c);
        const double ev = prt::AutoExposureEv(f, curve);
        const double grey = prt::InverseToneCurve(curve, prt::kKeyDisplay);
        CHECK(std::abs(std::log2(c * std::exp2(ev) / grey)) <= kHalfStepLog2);
      }
    prt::RasterImage f = Frame(1e-12f);
    CHECK(prt::AutoExposureEv(f, ToneCurve::kSrgb) == prt::kMaxAutoEv);
    f = Frame(1e12f);
    CHECK(prt::AutoExposureEv(f, ToneCurve::kAces) == -prt::kMaxAutoEv);
  }

  TEST_CASE("AutoExposureEv keeps the highlights below white") {
    // 96% of the mesh in deep shadow (0.01), 4% lit (1.0): the key alone would expose the
    // shadow to grey and clip the lit part; the highlight percentile holds it under white.
    prt::RasterImage f;
    f.image = prt::ImageF(50, 10);
    f.coverage.assign(500, 1.f);
    for (std::size_t i = 0; i < 500; ++i) f.image.pixels[i] = glm::vec3(i % 25 == 0 ? 1.f : 0.01f);
    for (ToneCurve curve : {ToneCurve::kSrgb, ToneCurve::kAces}) {
      const double ev = prt::AutoExposureEv(f, curve);
      const double display = prt::ApplyToneCurve(curve, static_cast<float>(std::exp2(ev)));
      CHECK(display <= prt::kHighlightDisplay * std::exp2(kHalfStepLog2));
      CHECK(display < 1.0);
    }
  }
}
