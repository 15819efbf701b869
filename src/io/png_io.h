#pragma once
/// \file
/// PNG files: 8-bit RGB out (io/png_encoder.h), any PNG in (through stb, Debian's libstb).
///
/// Writing favours speed over size (frames are written by the hundred): a low zlib level and one
/// fixed row filter. Files are written under a temporary name and renamed
/// (core/atomic_file.h), so a failed write never leaves a partial PNG.

#include <string>

#include "core/image.h"
#include "io/png_encoder.h"

namespace prt {

/// The PNG encoding of an 8-bit RGB image, in memory (for encoding on another thread), deflated
/// at zlib `level` (frames use kPngLevel, png_encoder.h; a render loop keeps a PngEncoder instead). Throws Error if the image is
/// empty, its buffer is not 3 * width * height bytes, or the level is not 1..9.
std::string EncodePng(const Image8& image, int level = kPngLevel);

/// Writes `image` to `path` atomically. Throws Error naming `path` on failure.
void WritePng(const std::string& path, const Image8& image);

/// Decodes PNG bytes; `name` (usually the path) prefixes error messages. Grey, grey + alpha,
/// palette and RGBA images become RGB (alpha is dropped, not composited); 16-bit channels are
/// rounded to 8 bits. Throws Error for data that is not a PNG or is truncated or corrupt.
Image8 DecodePng(const std::string& bytes, const std::string& name);

/// Reads a PNG file as 8-bit RGB (see DecodePng). Throws Error naming `path` when it is missing,
/// unreadable, not a PNG, truncated or corrupt.
Image8 ReadPng(const std::string& path);

}  // namespace prt
