#pragma once
/// \file
/// Reading a diffuse texture: png/jpg (8 or 16 bit) are sRGB-encoded reflectance, decoded to
/// linear with the exact sRGB curve; .hdr and .exr are linear already (io/image_load.h). A
/// reflectance must lie in [0, 1]: texels above 1 (an HDR painted too bright) are clamped to 1
/// and texels below 0 set to 0, with one warning per file; a NaN or infinite texel is refused.

#include <string>
#include <vector>

#include "texture/texture.h"

namespace prt {

/// Loads `path` as an albedo texture. Throws prt::Error `<path>: <problem> (<expected>)` for a
/// missing, unreadable, truncated, oversized or unrecognised file or a non-finite texel; appends
/// a warning to `warnings` when texels were clamped into [0, 1].
Texture LoadTexture(const std::string& path, std::vector<std::string>& warnings);

}  // namespace prt
