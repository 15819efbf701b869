#pragma once
/// \file
/// PNG encoding by stb_image_write with zlib's deflate in place of stb's own compressor.
/// stb's built-in deflate is simple and slow (65-100 ms for a 1080p frame at its fastest
/// setting); zlib at level 2 writes the same valid PNG several times faster. stb supports this
/// replacement through its STBIW_ZLIB_COMPRESS hook; its implementation is compiled here from
/// Debian's header, with internal linkage so it cannot clash with libstb's copy.

#include <cstdint>
#include <string>

namespace prt {

/// Appends the PNG file of an 8-bit RGB image (row-major, 3 * width * height bytes) to `out`.
/// Returns false if encoding failed (out of memory).
bool EncodePngZlib(const std::uint8_t* rgb, int width, int height, std::string& out);

}  // namespace prt
