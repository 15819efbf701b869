#pragma once
/// \file
/// A strict reader of animated PNGs for the tests, written from the APNG specification (W3C PNG
/// 3rd edition, 11.3.6) and independent of src/io and src/video: it checks every CRC (with the
/// tests' own CRC, tests/io/png_test_util.h), the chunk order (IHDR first, acTL before the first
/// image data, IEND last) and that fcTL and fdAT sequence numbers run 0, 1, 2, ... Each frame
/// can be turned back into a standalone PNG and decoded.

#include <cstdint>
#include <string>
#include <vector>

namespace prt::test {

struct ApngFrame {
  std::uint32_t width = 0, height = 0, x = 0, y = 0;
  std::uint16_t delay_num = 0, delay_den = 0;
  std::uint8_t dispose = 255, blend = 255;
  std::string zlib;  ///< the frame's image data (IDAT or fdAT contents, sequence numbers removed)
};

struct ApngFile {
  std::string ihdr;  ///< 13 bytes
  std::uint32_t announced_frames = 0, plays = 0;
  bool first_frame_is_default_image = false;  ///< frame 0's fcTL came before the IDAT chunks
  std::vector<ApngFrame> frames;
};

/// Parses `bytes`; throws std::runtime_error saying what is wrong with the file.
ApngFile ReadApng(const std::string& bytes);

/// Frame `i` as a PNG file of its own (the animation's IHDR with the frame's size, its image
/// data as IDAT), for DecodePng.
std::string FrameAsPng(const ApngFile& file, std::size_t i);

}  // namespace prt::test
