#pragma once
/// \file
/// The PNG encoder of frames: 8-bit RGB, written by the hundred, so favouring speed over size
/// and never allocating once warm.
///
/// A PNG file [1] here is the signature, an IHDR chunk (width, height, 8 bits, colour type 2:
/// RGB, no interlace), one IDAT chunk and IEND; each chunk ends with the CRC-32 of its type and
/// data. IDAT holds one zlib stream [2] of the rows, each row prefixed by its filter type. Every
/// row uses filter 1 ("sub": each byte minus the byte one pixel to its left), which is as fast
/// as any and compresses smooth rendered images well; the stream is zlib's deflate with its
/// default window and memory level at `level`.
///
/// An encoder keeps its deflate state, its filtered rows and its output between calls
/// (deflateReset instead of a new stream): after the first frame of a given size, encoding
/// touches no fresh memory. Each encoder is used by one thread at a time.
///
/// References:
///  [1] W3C, "Portable Network Graphics (PNG) Specification (Second Edition)", 2003:
///      sections 5 (datastream), 9.2 (filter type 1), 11.2.2 (IHDR).
///  [2] P. Deutsch, J-L. Gailly, RFC 1950 (zlib format) and RFC 1951 (deflate), 1996.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/image.h"

namespace prt {

/// zlib's compression level for frames (1 fastest .. 9 smallest), chosen by `prt bench raster`,
/// which encodes its 1080p frame at each level: on an AMD EPYC (Zen 4) level 2 took within a
/// few percent of level 1's time for a smaller file, and level 6 about three times as long for a
/// file a fifth smaller.
constexpr int kPngLevel = 2;

class PngEncoder {
 public:
  PngEncoder();
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  /// The PNG file of `image`, deflated at zlib `level`; valid until the next Encode. Throws
  /// Error if the image is empty, its buffer is not 3 * width * height bytes, or the level is
  /// not 1..9.
  const std::string& Encode(const Image8& image, int level = kPngLevel);
  /// The last file Encode returned (empty before the first).
  const std::string& last() const { return png_; }

 private:
  struct Deflater;
  std::unique_ptr<Deflater> deflater_;
  std::vector<std::uint8_t> filtered_;  // the rows, each prefixed by its filter type
  std::vector<std::uint8_t> deflated_;  // their zlib stream
  std::string png_;
};

}  // namespace prt
