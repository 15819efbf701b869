#pragma once
/// \file
/// Reading environment images as linear RGB radiance.
///
/// - jpg / png (8 or 16 bit, grey, grey+alpha, RGB, RGBA) are display-referred sRGB: decoded to
///   linear with the exact sRGB curve [1], or with pow(x, 2.2) as the course did (stb's float
///   loader), which `--games202-faces` selects to reproduce the course's published files.
/// - .hdr (Radiance RGBE) is linear already (stb).
/// - .exr through OpenEXR, any compression it knows (including DWAA/DWAB from Blender and
///   Poly Haven); alpha is ignored.
/// Sizes are checked from the header before any pixel is allocated.
///
/// References
/// [1] IEC 61966-2-1:1999 (sRGB): linear = c/12.92 for c <= 0.04045, else ((c+0.055)/1.055)^2.4.

#include <cstddef>
#include <string>

#include "core/image.h"

namespace prt {

enum class LdrDecode { kSrgb, kGamma22 };

/// Largest width or height accepted, and largest pixel count (a 16384 x 8192 equirect).
constexpr int kMaxImageSide = 16384;
constexpr std::size_t kMaxImagePixels = std::size_t(16384) * 8192;

/// Loads `path` as linear RGB. Throws Error `<path>: <problem> (<expected>)` for a missing,
/// unreadable, truncated, oversized or unrecognised file. Pixel values are returned as stored
/// (see SanitizeRadiance).
ImageF LoadImageLinear(const std::string& path, LdrDecode ldr = LdrDecode::kSrgb);

/// Reads only the size of an image (no pixels). Throws like LoadImageLinear.
void ImageSize(const std::string& path, int& width, int& height);

/// Radiance above this is treated as corrupt (the sun is about 1.6e9 in cd/m^2).
constexpr float kMaxRadiance = 1e15f;

/// What SanitizeRadiance replaced.
struct SanitizeCounts {
  std::size_t non_finite = 0;  ///< NaN or Inf, set to 0
  std::size_t negative = 0;    ///< below 0, set to 0
  std::size_t enormous = 0;    ///< above kMaxRadiance, clamped to it
  std::size_t total() const { return non_finite + negative + enormous; }
};

/// Makes every channel finite, non-negative and at most kMaxRadiance; returns what it changed.
SanitizeCounts SanitizeRadiance(ImageF& image);

/// One-line description of SanitizeCounts for a warning: "3 NaN/Inf, 2 negative texels set to 0".
std::string DescribeSanitized(const SanitizeCounts& counts);

/// The exact sRGB decoding curve of one channel value in [0, 1].
double SrgbToLinear(double c);

}  // namespace prt
