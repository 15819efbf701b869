#include "raster/tonemap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/parallel.h"

namespace prt {
namespace {

constexpr int kCells = 4096;

// The 8-bit sRGB code of a display-linear v in [0, 1] is the largest k with threshold[k] <= v,
// where threshold[k] is the inverse sRGB curve at (k - 1/2) / 255. A table over 4096 equal
// cells of [0, 1] gives the code at each cell's start; at most two steps up finish the search.
// Exact (no pow per pixel), and about as fast as a plain lookup.
struct SrgbTable {
  std::array<float, 257> threshold{};             // [256] is a sentinel above 1
  std::array<std::uint8_t, kCells + 1> start{};   // code at v = i / kCells
};

const SrgbTable& Table() {
  static const SrgbTable table = [] {
    SrgbTable t;
    for (int k = 1; k < 256; ++k) {
      const double s = (k - 0.5) / 255.0;
      t.threshold[k] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
    }
    t.threshold[256] = 2.f;
    int k = 0;
    for (int i = 0; i <= kCells; ++i) {
      const float v = static_cast<float>(i) / kCells;
      while (v >= t.threshold[k + 1]) ++k;
      t.start[i] = static_cast<std::uint8_t>(k);
    }
    return t;
  }();
  return table;
}

constexpr float kLargest = 1e15f;  // keeps the rational curves finite for huge or infinite input

}  // namespace

std::optional<ToneCurve> ParseToneCurve(const std::string& name) {
  if (name == "srgb") return ToneCurve::kSrgb;
  if (name == "reinhard") return ToneCurve::kReinhard;
  if (name == "aces") return ToneCurve::kAces;
  return std::nullopt;
}

const char* ToneCurveName(ToneCurve curve) {
  switch (curve) {
    case ToneCurve::kReinhard: return "reinhard";
    case ToneCurve::kAces: return "aces";
    default: return "srgb";
  }
}

float ApplyToneCurve(ToneCurve curve, float x) {
  x = std::min(x, kLargest);
  switch (curve) {
    case ToneCurve::kReinhard: return x / (1.f + x);
    case ToneCurve::kAces: return x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
    default: return x;
  }
}

namespace {

std::uint8_t Encode(const SrgbTable& t, float v) {
  if (!(v > 0.f)) return 0;  // also NaN
  if (v >= 1.f) return 255;
  int k = t.start[static_cast<int>(v * kCells)];
  while (v >= t.threshold[k + 1]) ++k;
  return static_cast<std::uint8_t>(k);
}

// One row, with the curve fixed at compile time. Returns pixels with a negative / NaN channel.
template <ToneCurve kCurve>
void MapRow(const glm::vec3* in, int width, float scale, std::uint8_t* out,
            std::size_t& negative, std::size_t& nan) {
  const SrgbTable& table = Table();
  for (int x = 0; x < width; ++x) {
    bool has_negative = false, has_nan = false;
    for (int i = 0; i < 3; ++i) {
      float v = in[x][i] * scale;
      if (v != v) has_nan = true, v = 0.f;  // NaN
      if (v < 0.f) has_negative = true, v = 0.f;
      out[3 * x + i] = Encode(table, ApplyToneCurve(kCurve, v));
    }
    negative += has_negative;
    nan += has_nan;
  }
}

}  // namespace

std::uint8_t EncodeSrgb8(float v) { return Encode(Table(), v); }

ToneMapped ToneMap(const ImageF& image, const ToneMapOptions& options) {
  ToneMapped out;
  out.image = Image8(image.width, image.height);
  const float scale = std::exp2(options.exposure_ev);
  const std::size_t rows = static_cast<std::size_t>(std::max(0, image.height));
  // Per-row counts, summed afterwards: the same totals for any thread count.
  std::vector<std::size_t> negative(rows, 0), nan(rows, 0);
  ParallelFor(rows, 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y) {
      const glm::vec3* in = &image.pixels[y * image.width];
      std::uint8_t* dst = &out.image.rgb[3 * y * image.width];
      switch (options.curve) {
        case ToneCurve::kSrgb: MapRow<ToneCurve::kSrgb>(in, image.width, scale, dst, negative[y], nan[y]); break;
        case ToneCurve::kReinhard: MapRow<ToneCurve::kReinhard>(in, image.width, scale, dst, negative[y], nan[y]); break;
        case ToneCurve::kAces: MapRow<ToneCurve::kAces>(in, image.width, scale, dst, negative[y], nan[y]); break;
      }
    }
  });
  for (std::size_t y = 0; y < rows; ++y) {
    out.negative_pixels += negative[y];
    out.nan_pixels += nan[y];
  }
  return out;
}

}  // namespace prt
