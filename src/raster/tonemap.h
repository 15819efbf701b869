#pragma once
/// \file
/// From linear radiance to 8-bit display values: exposure, an optional tone curve, the sRGB
/// transfer function [1], rounding to 8 bits.
///
/// Out-of-range input is never wrapped: negative radiance (ringing of a truncated SH series)
/// clamps to 0 and NaN becomes 0, and both are counted so the run summary can report them.
///
/// References:
///  [1] IEC 61966-2-1:1999, sRGB: encode 12.92 v for v <= 0.0031308, else 1.055 v^(1/2.4) - 0.055.
///  [2] E. Reinhard, M. Stark, P. Shirley, J. Ferwerda, "Photographic Tone Reproduction for
///      Digital Images", SIGGRAPH 2002, eq. 3: L / (1 + L) (applied per channel here).
///  [3] K. Narkowicz, "ACES Filmic Tone Mapping Curve", 2016,
///      https://knarkowicz.wordpress.com/2016/01/06/aces-filmic-tone-mapping-curve/ :
///      x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), a fit (max error 0.0138) of the ACES
///      RRT + ODT, pre-exposed so that 1 maps to about 0.8. Used as published.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"

namespace prt {

/// The tone curve applied after exposure and before the sRGB encoding.
enum class ToneCurve {
  kSrgb,      ///< none: clamp to [0, 1] (the default)
  kReinhard,  ///< x / (1 + x) [2]
  kAces,      ///< Narkowicz's ACES fit [3]
};

/// "srgb", "reinhard", "aces" (the `--tonemap` values), or nothing.
std::optional<ToneCurve> ParseToneCurve(const std::string& name);
/// The `--tonemap` name of a curve.
const char* ToneCurveName(ToneCurve curve);
/// Every curve's `--tonemap` name, in the enum's order.
std::vector<std::string> ToneCurveNames();

/// How to map radiance to display values.
struct ToneMapOptions {
  ToneCurve curve = ToneCurve::kSrgb;
  float exposure_ev = 0.f;  ///< radiance is multiplied by 2^exposure_ev first
};

/// What had to be repaired on the way to 8 bits.
struct ToneMapCounts {
  std::size_t negative_pixels = 0;  ///< pixels with a channel < 0, clamped to 0
  std::size_t nan_pixels = 0;       ///< pixels with a NaN channel, set to 0
  ToneMapCounts& operator+=(const ToneMapCounts& o) {
    negative_pixels += o.negative_pixels;
    nan_pixels += o.nan_pixels;
    return *this;
  }
};

/// The 8-bit image and what had to be repaired on the way.
struct ToneMapped : ToneMapCounts {
  Image8 image;
};

/// Tone-maps a linear image (any size, including empty) into a new image.
ToneMapped ToneMap(const ImageF& image, const ToneMapOptions& options = {});

/// The same into `out`, which is resized to the image's size: a render loop passes the same
/// buffer every frame, so that after the first frame tone mapping allocates nothing (a fresh
/// buffer costs a page fault per 4 KiB the first time it is written).
ToneMapCounts ToneMapInto(const ImageF& image, const ToneMapOptions& options, Image8& out);

/// Rows [row_begin, row_end) of `image` into the same rows of `out` (already image's size), on
/// the calling thread. The rows' bytes equal ToneMapInto's.
ToneMapCounts ToneMapRows(const ImageF& image, int row_begin, int row_end, const ToneMapOptions& options,
                          Image8& out);

/// `count` pixels from `in` to 3 * count bytes at `out`, on the calling thread: what the
/// rasterizer calls per band while the band is still in cache (raster/rasterizer.h,
/// RasterOptions::tone_map). The same bytes as ToneMapInto gives those pixels.
ToneMapCounts ToneMapPixels(const glm::vec3* in, std::size_t count, const ToneMapOptions& options,
                            std::uint8_t* out);

/// One value through a curve (display-linear result in [0, 1]); x >= 0 and not NaN.
float ApplyToneCurve(ToneCurve curve, float x);

/// round(255 * srgb(clamp(v, 0, 1))) for a display-linear v, exact except within a float ulp
/// of a rounding threshold. NaN maps to 0.
std::uint8_t EncodeSrgb8(float v);

}  // namespace prt
