#pragma once
/// \file
/// PNG chunks built by the tests themselves, independently of src/io (the CRC bit by bit from
/// the polynomial of the PNG specification, annex D), for hand-made PNG files and for reading
/// back the animated PNGs prt writes.

#include <cstdint>
#include <string>

namespace prt::test {

/// CRC-32 of `bytes` (PNG specification, annex D: polynomial 0xedb88320, reflected).
inline std::uint32_t Crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline std::string BigEndian32(std::uint32_t v) {
  return {char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
}

inline std::uint32_t FromBigEndian32(const std::string& bytes, std::size_t at) {
  const auto b = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(bytes.at(at + i))); };
  return b(0) << 24 | b(1) << 16 | b(2) << 8 | b(3);
}

/// One chunk: length, type, data, CRC of type and data.
inline std::string Chunk(const std::string& type, const std::string& data) {
  return BigEndian32(static_cast<std::uint32_t>(data.size())) + type + data + BigEndian32(Crc32(type + data));
}

inline const std::string kSignature("\x89PNG\r\n\x1a\n", 8);

}  // namespace prt::test
