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

/// zlib's compression level for frames (1 fastest .. 9 smallest), chosen by `prt bench raster`,
/// which encodes its 1080p frame at each level: on an AMD EPYC (Zen 4) level 2 took within a
/// few percent of level 1's time for a smaller file, and level 6 about three times as long for a
/// file a fifth smaller.
constexpr int kPngLevel = 2;

/// Appends the PNG file of an 8-bit RGB image (row-major, 3 * width * height bytes), deflated at
/// zlib `level` (1..9), to `out`. Returns false if encoding failed (out of memory).
bool EncodePngZlib(const std::uint8_t* rgb, int width, int height, int level, std::string& out);

}  // namespace prt
