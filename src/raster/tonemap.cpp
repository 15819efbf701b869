#include "raster/tonemap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/parallel.h"
#include "core/simd.h"

namespace prt {
namespace {

constexpr int kCells = 4096;

// The 8-bit sRGB code of a display-linear v in [0, 1] is the largest k with threshold[k] <= v,
// where threshold[k] is the inverse sRGB curve at (k - 1/2) / 255. The table splits [0, 1] into
// 4096 equal cells and keeps, per cell, the code at the cell's start and the next threshold
// above it. Cells (2.4e-4 wide) are narrower than the closest two thresholds (3.0e-4 apart, on
// the curve's linear part), so a cell holds at most one threshold and one comparison finishes
// the search: code = start + (v >= next). v * 4096 is exact in float, so the cell index is
// exactly floor(4096 v). Exact (no pow per pixel), and one 8-byte load per value.
struct Cell {
  float next;          // threshold[start + 1]; 2 (above every v) for the last code
  std::uint32_t start;  // code at v = i / kCells
};

struct SrgbTable {
  std::array<Cell, kCells + 1> cell{};
};

const SrgbTable& Table() {
  static const SrgbTable table = [] {
    std::array<float, 257> threshold{};  // [256] is a sentinel above 1
    for (int k = 1; k < 256; ++k) {
      const double s = (k - 0.5) / 255.0;
      threshold[k] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
    }
    threshold[256] = 2.f;
    SrgbTable t;
    int k = 0;
    for (int i = 0; i <= kCells; ++i) {
      const float v = static_cast<float>(i) / kCells;
      while (v >= threshold[k + 1]) ++k;
      t.cell[i] = {threshold[k + 1], static_cast<std::uint32_t>(k)};
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

// v in [0, 1] -> its 8-bit code (see SrgbTable).
std::uint8_t EncodeUnit(const SrgbTable& t, float v) {
  const Cell& c = t.cell[static_cast<int>(v * kCells)];
  return static_cast<std::uint8_t>(c.start + (v >= c.next ? 1u : 0u));
}

constexpr int kBlock = 768;  // values per block: 256 pixels

// The arithmetic of n <= kBlock values, branch-free so that it vectorises: exposure, NaN and
// negative to 0, the curve, clamp to [0, 1]. Returns true if a value was negative or NaN.
template <ToneCurve kCurve>
inline __attribute__((always_inline)) bool Prepare(const float* in, int n, float scale, float* v) {
  int bad = 0;
  for (int i = 0; i < n; ++i) {
    const float x = in[i] * scale;
    bad |= x >= 0.f ? 0 : 1;
    v[i] = std::min(ApplyToneCurve(kCurve, std::max(0.f, x)), 1.f);  // max(0, NaN) is 0
  }
  return bad != 0;
}

using PrepareFn = bool (*)(const float* in, int n, float scale, float* v);

// One version per instruction set, chosen once by CpuVectorLevel() (core/simd.h): the AVX2 one
// at avx2 and above (-ffp-contract=off: the same bits as the baseline's).
template <ToneCurve kCurve>
bool PrepareBaseline(const float* in, int n, float scale, float* v) {
  return Prepare<kCurve>(in, n, scale, v);
}
#ifdef PRT_TARGET_AVX2
template <ToneCurve kCurve>
PRT_TARGET_AVX2 bool PrepareAvx2(const float* in, int n, float scale, float* v) {
  return Prepare<kCurve>(in, n, scale, v);
}
#endif

template <ToneCurve kCurve>
PrepareFn ChoosePrepare() {
#ifdef PRT_TARGET_AVX2
  if (CpuVectorLevel() >= VectorLevel::kAvx2) return PrepareAvx2<kCurve>;
#endif
  return PrepareBaseline<kCurve>;
}

PrepareFn PrepareFor(ToneCurve curve) {
  static const PrepareFn srgb = ChoosePrepare<ToneCurve::kSrgb>();
  static const PrepareFn reinhard = ChoosePrepare<ToneCurve::kReinhard>();
  static const PrepareFn aces = ChoosePrepare<ToneCurve::kAces>();
  return curve == ToneCurve::kSrgb ? srgb : curve == ToneCurve::kReinhard ? reinhard : aces;
}

// Pixels of in[0 .. n) (n a multiple of 3) with a negative or a NaN channel.
void CountBad(const float* in, int n, float scale, std::size_t& negative, std::size_t& nan) {
  for (int i = 0; i < n; i += 3) {
    bool has_negative = false, has_nan = false;
    for (int c = 0; c < 3; ++c) {
      const float x = in[i + c] * scale;
      has_nan |= x != x;
      has_negative |= x < 0.f;
    }
    negative += has_negative;
    nan += has_nan;
  }
}

// One row of `width` pixels: the arithmetic in vectors, then one table load per value.
void MapRow(ToneCurve curve, const glm::vec3* row, int width, float scale, std::uint8_t* out,
            std::size_t& negative, std::size_t& nan) {
  const SrgbTable& table = Table();
  const PrepareFn prepare = PrepareFor(curve);
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "pixels are three packed floats");
  const float* in = reinterpret_cast<const float*>(row);
  float v[kBlock];
  for (int first = 0; first < 3 * width; first += kBlock) {
    const int n = std::min(kBlock, 3 * width - first);
    const bool bad = prepare(in + first, n, scale, v);
    if (bad) CountBad(in + first, n, scale, negative, nan);
    for (int i = 0; i < n; ++i) out[first + i] = EncodeUnit(table, v[i]);
  }
}

}  // namespace

std::uint8_t EncodeSrgb8(float v) {
  if (!(v > 0.f)) return 0;  // also NaN
  return EncodeUnit(Table(), std::min(v, 1.f));
}

ToneMapped ToneMap(const ImageF& image, const ToneMapOptions& options) {
  ToneMapped out;
  out.image = Image8(image.width, image.height);
  const float scale = std::exp2(options.exposure_ev);
  const std::size_t rows = static_cast<std::size_t>(std::max(0, image.height));
  // Per-row counts, summed afterwards: the same totals for any thread count.
  std::vector<std::size_t> negative(rows, 0), nan(rows, 0);
  ParallelFor(rows, 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y)
      MapRow(options.curve, &image.pixels[y * image.width], image.width, scale,
             &out.image.rgb[3 * y * image.width], negative[y], nan[y]);
  });
  for (std::size_t y = 0; y < rows; ++y) {
    out.negative_pixels += negative[y];
    out.nan_pixels += nan[y];
  }
  return out;
}

}  // namespace prt
