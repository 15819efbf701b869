#pragma once
/// \file
/// The course's `light.txt`: (lmax+1)^2 lines `R G B`, one per SH coefficient in flat order
/// k = l(l+1) + m. Written with 9 significant digits, which round-trips to 1e-9 relative.

#include <string>

#include "sh/coeffs.h"

namespace prt {

/// The text of a light.txt for `coeffs`.
std::string FormatLightTxt(const ShRgb& coeffs);

/// Parses light.txt text; `path` names the source in errors. Throws Error if a line is not three
/// finite numbers or the line count is not a perfect square.
ShRgb ParseLightTxt(const std::string& text, const std::string& path);

}  // namespace prt
