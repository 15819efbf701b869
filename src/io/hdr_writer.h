#pragma once
/// \file
/// Radiance .hdr (RGBE) files, written flat (no run-length encoding), which every reader that
/// handles the format accepts [1]: the header `#?RADIANCE`, `FORMAT=32-bit_rle_rgbe`, a blank
/// line, the resolution line `-Y H +X W` (rows top to bottom), then four bytes a pixel: a
/// shared exponent e and three mantissas, so a channel c is stored as floor(c 2^(8 - e')) with
/// 2^(e' - 1) <= max channel < 2^e', e = e' + 128. Relative error at most 2^-8 of the largest
/// channel.
///
/// References
/// [1] G. Ward, "Real Pixels", Graphics Gems II, 1991 (the RGBE encoding).

#include <string>

#include "core/image.h"

namespace prt {

/// The .hdr bytes of a linear image; negative and non-finite channels are written as 0.
/// Throws Error for an empty image.
std::string EncodeHdr(const ImageF& image);

}  // namespace prt
