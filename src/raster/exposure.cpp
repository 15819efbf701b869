#include "raster/exposure.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/color.h"

namespace prt {
namespace {

// A pixel's luminance when it can be measured (finite, no negative channel, not black), else 0.
double Measurable(const glm::vec3& c) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c[i]) || c[i] < 0.f) return 0.0;
  const double y = Luminance(glm::dvec3(c));  // Rec. 709 [1]
  return y > 0.0 && std::isfinite(y) ? y : 0.0;
}

}  // namespace

double InverseToneCurve(ToneCurve curve, double display) {
  if (curve == ToneCurve::kSrgb) return display;
  // The curves rise monotonically from 0: bracket the value, then halve down to adjacent floats.
  const float target = static_cast<float>(display);
  float lo = 0.f, hi = 1.f;
  while (ApplyToneCurve(curve, hi) < target && hi < 1e30f) lo = hi, hi *= 2.f;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const float mid = 0.5f * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    (ApplyToneCurve(curve, mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (double(lo) + double(hi));
}

double AutoExposureEv(const RasterImage& frame, ToneCurve curve) {
  // Measure the fully covered pixels; a mesh smaller than a pixel, every pixel it touches.
  const std::vector<glm::vec3>& pixels = frame.image.pixels;
  const std::size_t n = std::min(pixels.size(), frame.coverage.size());
  std::vector<double> luminance;
  for (const float full_only : {1.f, 0.f}) {
    for (std::size_t i = 0; i < n; ++i) {
      const bool covered = full_only > 0.f ? frame.coverage[i] >= 1.f : frame.coverage[i] > 0.f;
      const double y = covered ? Measurable(pixels[i]) : 0.0;
      if (y > 0.0) luminance.push_back(y);
    }
    if (!luminance.empty()) break;
  }
  if (luminance.empty()) return 0.0;

  // Key: the log-average (geometric mean), summed in pixel order so the result is deterministic.
  double log_sum = 0.0;
  for (const double y : luminance) log_sum += std::log2(y);
  const double log_key = log_sum / static_cast<double>(luminance.size());
  // Highlights: the nearest-rank percentile.
  const std::size_t rank = static_cast<std::size_t>(
      std::ceil(kHighlightPercentile * static_cast<double>(luminance.size())));
  const auto nth = luminance.begin() + static_cast<std::ptrdiff_t>(std::clamp<std::size_t>(rank, 1, luminance.size()) - 1);
  std::nth_element(luminance.begin(), nth, luminance.end());

  const double key_ev = std::log2(InverseToneCurve(curve, kKeyDisplay)) - log_key;
  const double highlight_ev = std::log2(InverseToneCurve(curve, kHighlightDisplay) / *nth);
  const double ev = std::clamp(std::min(key_ev, highlight_ev), -kMaxAutoEv, kMaxAutoEv);
  // n / steps is the double nearest to the decimal n / 10, the same value that parsing the EV
  // printed with one decimal gives back; + 0.0 turns -0 into 0.
  const double steps = std::round(1.0 / kAutoEvStep);
  return std::round(ev * steps) / steps + 0.0;
}

std::string AutoExposureLimitNote(double ev) {
  if (ev <= -kMaxAutoEv) return "; the limit: the scene is brighter than -20 EV can show, expect white";
  if (ev >= kMaxAutoEv) return "; the limit: the scene is darker than +20 EV can show, expect black";
  return "";
}

}  // namespace prt
