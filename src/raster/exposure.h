#pragma once
/// \file
/// Automatic exposure: the EV (radiance times 2^EV before the tone curve, as ToneMapOptions
/// uses it) that makes a drawn frame a well-exposed picture.
///
/// What is measured. Only the mesh: pixels the rasterizer covered completely (coverage 1), so a
/// bright sun or sky behind the mesh cannot darken it; when the mesh covers no pixel completely
/// (smaller than a pixel), every pixel it touches. Pixels with a NaN, infinite or negative
/// channel (ringing of a truncated SH series) and black pixels are left out: they say nothing
/// about the exposure and have no logarithm. The luminance of a linear sRGB/Rec. 709 pixel is
/// Y = 0.2126 R + 0.7152 G + 0.0722 B [1].
///
/// Two statistics, each for what it protects:
///  - the key, the log-average luminance exp(mean log Y) of Reinhard et al. [2, eq. 1]. It is the
///    geometric mean, so a few very bright or very dark pixels move it little (unlike the mean),
///    and it scales exactly with the image. The key is mapped to the exposed value that the
///    curve shows as kKeyDisplay, display-linear 0.3 (sRGB code 149). Reinhard's "key value"
///    and the photographer's grey card use middle grey, 0.18; but prt's scenes are mostly light
///    diffuse surfaces (albedo 0.5 to 0.8; the course's mary is 0.8), which a grey-card meter
///    darkens to grey, as it does snow. 0.3 was chosen by eye on the embedded demo scene, mary
///    under the course's four cubemaps and the sky with a 100x sun (`--env sky:sun=100`): the
///    keys of those scenes then land 0.5 to 0.8 EV brighter than with 0.18, and no lit surface
///    clips. The exposed value depends on the curve: 0.3 for srgb (no curve), 0.3 / 0.7 = 0.43
///    for Reinhard's x / (1 + x), and about 0.2 for the ACES fit.
///  - the highlights, the kHighlightPercentile (99th) percentile of Y. The srgb curve clips at
///    display 1 and ACES reaches 1 near x = 7.2, so a key alone would clip the lit side of
///    high-contrast scenes (sun on a floor beside deep shadow): the EV is lowered, if needed, so
///    that this percentile shows at display kHighlightDisplay (0.95) or below. Reinhard never
///    clips and its 0.95 lies at x = 19, so there the key nearly always decides.
/// EV = min(log2(grey / key), log2(highlight / p99)), clamped to [-kMaxAutoEv, kMaxAutoEv] and
/// rounded to kAutoEvStep (0.1 EV), so the EV printed with one decimal, passed back as
/// `--exposure`, reproduces the image exactly. Scaling the frame by 2^k moves the EV by -k up
/// to that rounding. No measurable pixel: 0 EV.
///
/// References:
///  [1] ITU-R BT.709-6, item 3.2 (luminance of the sRGB primaries).
///  [2] E. Reinhard, M. Stark, P. Shirley, J. Ferwerda, "Photographic Tone Reproduction for
///      Digital Images", SIGGRAPH 2002, section 3.1.

#include <string>

#include "raster/rasterizer.h"
#include "raster/tonemap.h"

namespace prt {

/// Display-linear value (after the curve, before the sRGB encoding) that the key maps to (see
/// the file comment for why it is above middle grey, 0.18).
constexpr double kKeyDisplay = 0.3;
/// Fraction of measured pixels at or below the highlight level that must not clip.
constexpr double kHighlightPercentile = 0.99;
/// Display-linear value the highlight percentile may reach at most (just under white).
constexpr double kHighlightDisplay = 0.95;
/// Automatic exposures are clamped to [-kMaxAutoEv, kMaxAutoEv].
constexpr double kMaxAutoEv = 20.0;

/// For the run summary: empty for an EV inside the range, else a note that `ev` is the clamped
/// limit and the picture will be too bright or too dark.
std::string AutoExposureLimitNote(double ev);
/// Automatic exposures are multiples of this step (one printed decimal).
constexpr double kAutoEvStep = 0.1;

/// The exposed value x >= 0 that `curve` shows as the display-linear value `display` in (0, 1)
/// (the curve's inverse; for srgb, display itself).
double InverseToneCurve(ToneCurve curve, double display);

/// The automatic exposure of a drawn frame for `curve`, in EV (see the file comment): a
/// multiple of kAutoEvStep in [-kMaxAutoEv, kMaxAutoEv], 0 when no covered pixel is measurable.
/// Deterministic. Precondition: frame.coverage has one entry per pixel (as Rasterizer draws it).
double AutoExposureEv(const RasterImage& frame, ToneCurve curve);

}  // namespace prt
