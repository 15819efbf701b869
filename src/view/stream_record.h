#pragma once
/// \file
/// The records of `prt view`'s frame stream (GET /stream, view/frame_stream.h), as the page reads
/// them (view/page/view.js, readStream). Each record starts with a 32-byte header of eight
/// little-endian uint32 fields, the first four bytes naming its kind:
///
///   "PRTF" frame  input  width  height  draw_us  flags  0,  then width x height x 4 bytes RGBA,
///                 rows from the top (flags bit 0: still quality, the bytes `prt render` writes)
///   "PRTE" frame  input  length 0 0 0 0,                     then `length` bytes of UTF-8: why
///                 that input cannot be drawn (the frame's 400 or 409 text)
///   "PRTK" 0 ...                                              a keep-alive, nothing to draw
///
/// RGBA rather than the RGB of /frame: the page puts the bytes on its canvas as they come,
/// without a pass over them in JavaScript.

#include <cstdint>
#include <string>

#include "core/image.h"

namespace prt {

inline constexpr std::size_t kStreamHeaderBytes = 32;
inline constexpr std::uint32_t kStillFlag = 1;

/// A frame record of `image` answering `input`, the `frame`-th of its stream.
std::string FrameRecord(const Image8& image, std::uint64_t frame, std::uint64_t input, double draw_ms, bool still);
/// An error record: input `input` cannot be drawn, because `why`.
std::string ErrorRecord(std::uint64_t frame, std::uint64_t input, const std::string& why);
std::string KeepAliveRecord();

}  // namespace prt
