#include "raster/tonemap.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/name_table.h"
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

constexpr auto kCurves = MakeNameTable<ToneCurve>({
    {ToneCurve::kSrgb, "srgb"},
    {ToneCurve::kReinhard, "reinhard"},
    {ToneCurve::kAces, "aces"},
});
static_assert(kCurves.Distinct());

}  // namespace

std::optional<ToneCurve> ParseToneCurve(const std::string& name) { return kCurves.Find(name); }

const char* ToneCurveName(ToneCurve curve) { return kCurves.Name(curve); }

std::vector<std::string> ToneCurveNames() { return kCurves.Names(); }

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

// The codes of n values in [0, 1] (EncodeUnit of each).
using EncodeFn = void (*)(const SrgbTable& t, const float* v, int n, std::uint8_t* out);

void EncodeBaseline(const SrgbTable& t, const float* v, int n, std::uint8_t* out) {
  for (int i = 0; i < n; ++i) out[i] = EncodeUnit(t, v[i]);
}

#ifdef PRT_TARGET_AVX2
// The same, 32 values at a time: the cell index, the cell's threshold and start code gathered
// for 8 values at once, the codes narrowed to bytes; the same table and comparisons as
// EncodeUnit, so the same codes.
PRT_TARGET_AVX2 void EncodeAvx2(const SrgbTable& t, const float* v, int n, std::uint8_t* out) {
  static_assert(sizeof(Cell) == 8, "the gathers step 8 bytes a cell");
  const float* next = &t.cell[0].next;
  const int* start = reinterpret_cast<const int*>(&t.cell[0].start);
  const __m256 cells = _mm256_set1_ps(static_cast<float>(kCells));
  // After the two packs, 32-bit group j of the result holds codes 4j..4j+3 of one input vector
  // in the order a0-3 b0-3 c0-3 d0-3 | a4-7 b4-7 c4-7 d4-7; this puts them back in order.
  const __m256i order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
  int i = 0;
  for (; i + 32 <= n; i += 32) {
    __m256i code[4];
    for (int j = 0; j < 4; ++j) {
      const __m256 x = _mm256_loadu_ps(v + i + 8 * j);
      const __m256i cell = _mm256_cvttps_epi32(_mm256_mul_ps(x, cells));
      const __m256 threshold = _mm256_i32gather_ps(next, cell, 8);
      const __m256i first = _mm256_i32gather_epi32(start, cell, 8);
      const __m256i above = _mm256_castps_si256(_mm256_cmp_ps(x, threshold, _CMP_GE_OQ));  // -1 where v >= next
      code[j] = _mm256_sub_epi32(first, above);
    }
    const __m256i bytes = _mm256_packus_epi16(_mm256_packus_epi32(code[0], code[1]), _mm256_packus_epi32(code[2], code[3]));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i), _mm256_permutevar8x32_epi32(bytes, order));
  }
  for (; i < n; ++i) out[i] = EncodeUnit(t, v[i]);
}
#endif

EncodeFn ChooseEncode() {
#ifdef PRT_TARGET_AVX2
  if (CpuVectorLevel() >= VectorLevel::kAvx2) return EncodeAvx2;
#endif
  return EncodeBaseline;
}

// One row of `width` pixels: the arithmetic in vectors, then one table load per value.
void MapRow(ToneCurve curve, const glm::vec3* row, int width, float scale, std::uint8_t* out,
            std::size_t& negative, std::size_t& nan) {
  const SrgbTable& table = Table();
  const PrepareFn prepare = PrepareFor(curve);
  static const EncodeFn encode = ChooseEncode();
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "pixels are three packed floats");
  const float* in = reinterpret_cast<const float*>(row);
  float v[kBlock];
  for (int first = 0; first < 3 * width; first += kBlock) {
    const int n = std::min(kBlock, 3 * width - first);
    const bool bad = prepare(in + first, n, scale, v);
    if (bad) CountBad(in + first, n, scale, negative, nan);
    encode(table, v, n, out + first);
  }
}

}  // namespace

std::uint8_t EncodeSrgb8(float v) {
  if (!(v > 0.f)) return 0;  // also NaN
  return EncodeUnit(Table(), std::min(v, 1.f));
}

ToneMapCounts ToneMapPixels(const glm::vec3* in, std::size_t count, const ToneMapOptions& options, std::uint8_t* out) {
  const float scale = std::exp2(options.exposure_ev);
  ToneMapCounts counts;
  // In pieces of at most 2^20 pixels, so that MapRow's int counts cannot overflow.
  constexpr std::size_t kPiece = 1 << 20;
  for (std::size_t first = 0; first < count; first += kPiece) {
    const std::size_t n = std::min(kPiece, count - first);
    MapRow(options.curve, in + first, static_cast<int>(n), scale, out + 3 * first, counts.negative_pixels,
           counts.nan_pixels);
  }
  return counts;
}

ToneMapCounts ToneMapRows(const ImageF& image, int row_begin, int row_end, const ToneMapOptions& options,
                          Image8& out) {
  const std::size_t first = static_cast<std::size_t>(row_begin) * image.width;
  const std::size_t count = static_cast<std::size_t>(std::max(0, row_end - row_begin)) * image.width;
  return ToneMapPixels(image.pixels.data() + first, count, options, out.rgb.data() + 3 * first);
}

ToneMapCounts ToneMapInto(const ImageF& image, const ToneMapOptions& options, Image8& out) {
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(3 * image.pixels.size());
  // Counts per block of rows, added up as they finish: integer sums, the same for any thread count.
  constexpr std::size_t kRows = 16;
  const std::size_t rows = static_cast<std::size_t>(std::max(0, image.height));
  std::atomic<std::size_t> negative{0}, nan{0};
  ParallelFor(rows, kRows, [&](std::size_t begin, std::size_t end) {
    const ToneMapCounts c = ToneMapRows(image, static_cast<int>(begin), static_cast<int>(end), options, out);
    negative += c.negative_pixels;
    nan += c.nan_pixels;
  });
  ToneMapCounts total;
  total.negative_pixels = negative;
  total.nan_pixels = nan;
  return total;
}

ToneMapped ToneMap(const ImageF& image, const ToneMapOptions& options) {
  ToneMapped out;
  static_cast<ToneMapCounts&>(out) = ToneMapInto(image, options, out.image);
  return out;
}

}  // namespace prt
