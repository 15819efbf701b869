#include "raster/image_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "core/error.h"

namespace prt {
namespace {

std::string SizeText(const Image8& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void CheckComparable(const Image8& a, const Image8& b) {
  for (const Image8* image : {&a, &b})
    if (image->width < 0 || image->height < 0 ||
        image->rgb.size() != 3 * static_cast<std::size_t>(image->width) * image->height)
      throw Error("image " + SizeText(*image) + ": holds " + std::to_string(image->rgb.size()) +
                  " bytes (expected 3 * width * height)");
  if (a.width != b.width || a.height != b.height)
    throw Error("images differ in size: " + SizeText(a) + " and " + SizeText(b) +
                " (expected equal sizes)");
}

}  // namespace

DiffMetrics CompareImages(const Image8& a, const Image8& b) {
  CheckComparable(a, b);
  DiffMetrics m;
  std::uint64_t sum_abs = 0, sum_sq = 0;  // exact: at most 255^2 * 3 * 2^31 < 2^64
  for (std::size_t p = 0; p < a.rgb.size(); p += 3) {
    int worst = 0;
    for (std::size_t c = p; c < p + 3; ++c) {
      const int d = std::abs(int(a.rgb[c]) - int(b.rgb[c]));
      worst = std::max(worst, d);
      sum_abs += static_cast<std::uint64_t>(d);
      sum_sq += static_cast<std::uint64_t>(d * d);
    }
    m.max_abs = std::max(m.max_abs, worst);
    m.differing_pixels += worst != 0;
    m.pixels_over_one += worst > 1;
  }
  const double n = std::max<double>(1.0, static_cast<double>(a.rgb.size()));
  m.mean_abs = static_cast<double>(sum_abs) / n;
  m.rmse = std::sqrt(static_cast<double>(sum_sq) / n);
  m.psnr = m.rmse > 0.0 ? 20.0 * std::log10(255.0 / m.rmse)
                        : std::numeric_limits<double>::infinity();
  return m;
}

Image8 AmplifiedDifference(const Image8& a, const Image8& b) {
  const DiffMetrics m = CompareImages(a, b);
  Image8 out(a.width, a.height);
  for (std::size_t c = 0; c < a.rgb.size(); ++c) {
    const int d = std::abs(int(a.rgb[c]) - int(b.rgb[c]));
    out.rgb[c] = static_cast<std::uint8_t>(d == 0 ? 0 : 64 + 191 * d / m.max_abs);
  }
  return out;
}

std::string FormatDiffMetrics(const DiffMetrics& m) {
  char psnr[32];
  if (std::isinf(m.psnr))
    std::snprintf(psnr, sizeof psnr, "inf");
  else
    std::snprintf(psnr, sizeof psnr, "%.4f", m.psnr);
  char line[256];
  std::snprintf(line, sizeof line, "max_abs=%d mean_abs=%.6g rmse=%.6g psnr=%s differing_pixels=%zu",
                m.max_abs, m.mean_abs, m.rmse, psnr, m.differing_pixels);
  return line;
}

}  // namespace prt
