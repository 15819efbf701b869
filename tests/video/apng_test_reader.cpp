#include "tests/video/apng_test_reader.h"

#include <cctype>
#include <stdexcept>

#include "tests/io/png_test_util.h"

namespace prt::test {
namespace {

[[noreturn]] void Bad(const std::string& what) { throw std::runtime_error("APNG: " + what); }

std::uint16_t FromBigEndian16(const std::string& bytes, std::size_t at) {
  return std::uint16_t((static_cast<unsigned char>(bytes.at(at)) << 8) | static_cast<unsigned char>(bytes.at(at + 1)));
}

}  // namespace

ApngFile ReadApng(const std::string& bytes) {
  if (bytes.compare(0, 8, kSignature) != 0) Bad("no PNG signature");
  ApngFile file;
  std::uint32_t next_sequence = 0;
  bool actl = false, idat_seen = false, iend = false;
  ApngFrame* current = nullptr;  // the frame whose data chunks are being read
  std::size_t at = 8;
  for (int index = 0; !iend; ++index) {
    if (at + 12 > bytes.size()) Bad("the file ends before IEND");
    const std::uint32_t length = FromBigEndian32(bytes, at);
    if (at + 12 + length > bytes.size()) Bad("a chunk runs past the end");
    const std::string type = bytes.substr(at + 4, 4), data = bytes.substr(at + 8, length);
    if (FromBigEndian32(bytes, at + 8 + length) != Crc32(type + data)) Bad(type + ": wrong CRC");
    at += 12 + length;
    if (index == 0 && type != "IHDR") Bad("the first chunk is " + type + ", not IHDR");
    if (type == "IHDR") {
      if (index != 0 || length != 13) Bad("IHDR misplaced or not 13 bytes");
      file.ihdr = data;
    } else if (type == "acTL") {
      if (actl || idat_seen || length != 8) Bad("acTL repeated, after IDAT, or not 8 bytes");
      actl = true;
      file.announced_frames = FromBigEndian32(data, 0), file.plays = FromBigEndian32(data, 4);
    } else if (type == "fcTL") {
      if (length != 26) Bad("fcTL not 26 bytes");
      if (FromBigEndian32(data, 0) != next_sequence++) Bad("fcTL sequence number out of order");
      ApngFrame f;
      f.width = FromBigEndian32(data, 4), f.height = FromBigEndian32(data, 8);
      f.x = FromBigEndian32(data, 12), f.y = FromBigEndian32(data, 16);
      f.delay_num = FromBigEndian16(data, 20), f.delay_den = FromBigEndian16(data, 22);
      f.dispose = static_cast<std::uint8_t>(data[24]), f.blend = static_cast<std::uint8_t>(data[25]);
      if (file.frames.empty() && !idat_seen) file.first_frame_is_default_image = true;
      file.frames.push_back(f);
      current = &file.frames.back();
    } else if (type == "IDAT") {
      if (!actl) Bad("IDAT before acTL");
      if (!current || file.frames.size() != 1) Bad("IDAT not preceded by frame 0's fcTL");
      idat_seen = true;
      current->zlib += data;
    } else if (type == "fdAT") {
      if (!current || file.frames.size() < 2) Bad("fdAT without a later frame's fcTL");
      if (length < 4 || FromBigEndian32(data, 0) != next_sequence++) Bad("fdAT sequence number out of order");
      current->zlib += data.substr(4);
    } else if (type == "IEND") {
      iend = true;
    } else if (std::isupper(static_cast<unsigned char>(type[0]))) {
      Bad("unexpected critical chunk " + type);
    }
  }
  if (at != bytes.size()) Bad("bytes after IEND");
  if (!actl) Bad("no acTL: a still PNG");
  if (!idat_seen) Bad("no IDAT");
  return file;
}

std::string FrameAsPng(const ApngFile& file, std::size_t i) {
  const ApngFrame& f = file.frames.at(i);
  const std::string ihdr = BigEndian32(f.width) + BigEndian32(f.height) + file.ihdr.substr(8);
  return kSignature + Chunk("IHDR", ihdr) + Chunk("IDAT", f.zlib) + Chunk("IEND", "");
}

}  // namespace prt::test
