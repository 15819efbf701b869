#include "view/stream_record.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace prt {
namespace {

std::uint32_t Low32(std::uint64_t v) { return static_cast<std::uint32_t>(v & 0xffffffffu); }

/// The header, its eight fields written little-endian whatever the machine.
std::string Header(const char kind[4], const std::uint32_t (&fields)[7]) {
  std::string h(kStreamHeaderBytes, '\0');
  std::memcpy(&h[0], kind, 4);
  for (int i = 0; i < 7; ++i)
    for (int b = 0; b < 4; ++b) h[4 + 4 * i + b] = static_cast<char>((fields[i] >> (8 * b)) & 0xffu);
  return h;
}

}  // namespace

std::string FrameRecord(const Image8& image, std::uint64_t frame, std::uint64_t input, double draw_ms, bool still) {
  const double us = std::clamp(std::round(draw_ms * 1000.0), 0.0, 4294967295.0);
  std::string record = Header("PRTF", {Low32(frame), Low32(input), static_cast<std::uint32_t>(image.width),
                                       static_cast<std::uint32_t>(image.height), static_cast<std::uint32_t>(us),
                                       still ? kStillFlag : 0u, 0u});
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  record.resize(kStreamHeaderBytes + 4 * pixels);
  char* out = &record[kStreamHeaderBytes];
  const std::uint8_t* in = image.rgb.data();
  for (std::size_t p = 0; p < pixels; ++p, out += 4, in += 3) {
    out[0] = static_cast<char>(in[0]);
    out[1] = static_cast<char>(in[1]);
    out[2] = static_cast<char>(in[2]);
    out[3] = static_cast<char>(0xff);
  }
  return record;
}

std::string ErrorRecord(std::uint64_t frame, std::uint64_t input, const std::string& why) {
  return Header("PRTE", {Low32(frame), Low32(input), static_cast<std::uint32_t>(why.size()), 0u, 0u, 0u, 0u}) + why;
}

std::string KeepAliveRecord() { return Header("PRTK", {0u, 0u, 0u, 0u, 0u, 0u, 0u}); }

}  // namespace prt
