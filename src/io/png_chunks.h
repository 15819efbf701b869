#pragma once
/// \file
/// The chunk layer of the PNG format (PNG specification, 3rd edition, section 5): after the
/// 8-byte signature a file is a list of chunks, each
///     length (4 bytes, big-endian) | type (4 ASCII letters) | data (length bytes) | CRC-32
/// where the CRC covers type and data. The animated PNG writer (video/apng_writer.h) takes the
/// compressed image data (IDAT) of PNGs encoded by io/png_io.h and wraps it in its own chunks.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace prt {

/// The 8 bytes every PNG file starts with.
extern const char kPngSignatureBytes[8];

/// `value` as 4 big-endian bytes appended to `out`.
void AppendU32(std::string& out, std::uint32_t value);

/// The 4 big-endian bytes at `p` as a number.
std::uint32_t ReadU32(const char* p);

/// Appends one chunk, its length and CRC computed here, to `out`.
void AppendPngChunk(std::string& out, std::string_view type, std::string_view data);

/// Calls `visit(type, data)` for each chunk of the PNG file `png`, in order, up to and including
/// IEND. Throws Error naming `name` when the signature is missing, a chunk runs past the end,
/// its CRC does not match or the file ends before IEND.
void ForEachPngChunk(std::string_view png, const std::string& name,
                     const std::function<void(std::string_view type, std::string_view data)>& visit);

/// The concatenated data of every IDAT chunk of `png` (one zlib stream, PNG section 10), and its
/// IHDR's width and height. Throws Error (see ForEachPngChunk) when there is no IHDR or IDAT.
struct PngImageData {
  std::uint32_t width = 0, height = 0;
  std::string ihdr;  ///< the IHDR chunk's 13 data bytes
  std::string idat;  ///< the zlib stream
};
PngImageData ExtractPngImageData(std::string_view png, const std::string& name);

}  // namespace prt
