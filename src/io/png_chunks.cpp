#include "io/png_chunks.h"

#include <cstring>

#include <zlib.h>

#include "core/error.h"

namespace prt {

const char kPngSignatureBytes[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};

void AppendU32(std::string& out, std::uint32_t value) {
  const char bytes[4] = {char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
  out.append(bytes, 4);
}

std::uint32_t ReadU32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(u[0]) << 24 | std::uint32_t(u[1]) << 16 | std::uint32_t(u[2]) << 8 | std::uint32_t(u[3]);
}

void AppendPngChunk(std::string& out, std::string_view type, std::string_view data) {
  AppendU32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.append(type);
  out.append(data);
  // CRC-32 (ISO 3309, the one zlib computes) of the type and data bytes.
  const auto crc = crc32(0L, reinterpret_cast<const Bytef*>(out.data() + start), static_cast<uInt>(out.size() - start));
  AppendU32(out, static_cast<std::uint32_t>(crc));
}

void ForEachPngChunk(std::string_view png, const std::string& name,
                     const std::function<void(std::string_view, std::string_view)>& visit) {
  if (png.size() < 8 || std::memcmp(png.data(), kPngSignatureBytes, 8) != 0)
    throw Error(name + ": not a PNG file (expected the PNG signature)");
  std::size_t at = 8;
  while (true) {
    if (png.size() - at < 12) throw Error(name + ": PNG ends before its IEND chunk (expected a complete file)");
    const std::uint32_t length = ReadU32(png.data() + at);
    if (length > png.size() - at - 12) throw Error(name + ": a PNG chunk runs past the end of the file (expected a complete file)");
    const std::string_view type = png.substr(at + 4, 4), data = png.substr(at + 8, length);
    const auto crc = crc32(0L, reinterpret_cast<const Bytef*>(png.data() + at + 4), length + 4);
    if (static_cast<std::uint32_t>(crc) != ReadU32(png.data() + at + 8 + length))
      throw Error(name + ": PNG chunk " + std::string(type) + " has a wrong CRC (expected an uncorrupted file)");
    visit(type, data);
    at += 12 + length;
    if (type == "IEND") return;
  }
}

PngImageData ExtractPngImageData(std::string_view png, const std::string& name) {
  PngImageData out;
  ForEachPngChunk(png, name, [&](std::string_view type, std::string_view data) {
    if (type == "IHDR" && data.size() == 13) {
      out.ihdr = std::string(data);
      out.width = ReadU32(data.data()), out.height = ReadU32(data.data() + 4);
    }
    if (type == "IDAT") out.idat.append(data);
  });
  if (out.ihdr.empty() || out.idat.empty()) throw Error(name + ": PNG without IHDR or IDAT (expected an image)");
  return out;
}

}  // namespace prt
