#include "io/png_encoder.h"

#include <cstring>

#include <zlib.h>

#include "core/error.h"

namespace prt {
namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::uint8_t kSubFilter = 1;

void PutBigEndian32(std::string& out, std::uint32_t v) {
  const char bytes[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
  out.append(bytes, 4);
}

// Length, type and data are appended by the caller from `start` (the length's offset); this
// fills in the length and appends the CRC of type and data.
void EndChunk(std::string& out, std::size_t start) {
  const std::size_t length = out.size() - start - 8;
  for (int i = 0; i < 4; ++i) out[start + i] = char(length >> (24 - 8 * i));
  const auto* typed = reinterpret_cast<const Bytef*>(out.data() + start + 4);
  PutBigEndian32(out, static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0), typed, static_cast<uInt>(length + 4))));
}

std::size_t BeginChunk(std::string& out, const char (&type)[5]) {
  const std::size_t start = out.size();
  out.append(4, '\0');
  out.append(type, 4);
  return start;
}

}  // namespace

// One deflate stream, reset between images; its level is changed only when asked.
struct PngEncoder::Deflater {
  z_stream stream{};
  int level = 0;
  ~Deflater() {
    if (level) deflateEnd(&stream);
  }
  void Start(int wanted) {
    if (level == wanted) {
      deflateReset(&stream);
      return;
    }
    if (level) deflateEnd(&stream);
    level = 0;
    stream = z_stream{};
    if (deflateInit(&stream, wanted) != Z_OK) throw Error("PNG encoder: zlib could not start (expected enough memory)");
    level = wanted;
  }
};

PngEncoder::PngEncoder() : deflater_(std::make_unique<Deflater>()) {}
PngEncoder::~PngEncoder() = default;

const std::string& PngEncoder::Encode(const Image8& image, int level) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * image.height)
    throw Error("PNG encoder: image " + std::to_string(image.width) + "x" + std::to_string(image.height) + " with " +
                std::to_string(image.rgb.size()) + " bytes (expected a non-empty image of 3 * width * height bytes)");
  if (level < 1 || level > 9) throw Error("PNG encoder: zlib level " + std::to_string(level) + " (expected 1 to 9)");

  // The rows, filtered.
  const std::size_t row_bytes = 3 * static_cast<std::size_t>(image.width);
  filtered_.resize((row_bytes + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* in = &image.rgb[y * row_bytes];
    std::uint8_t* out = &filtered_[y * (row_bytes + 1)];
    out[0] = kSubFilter;
    std::memcpy(out + 1, in, 3);
    for (std::size_t i = 3; i < row_bytes; ++i) out[1 + i] = static_cast<std::uint8_t>(in[i] - in[i - 3]);
  }

  png_.clear();  // keeps its capacity
  png_.append(reinterpret_cast<const char*>(kSignature), sizeof kSignature);
  std::size_t chunk = BeginChunk(png_, "IHDR");
  PutBigEndian32(png_, static_cast<std::uint32_t>(image.width));
  PutBigEndian32(png_, static_cast<std::uint32_t>(image.height));
  const char format[5] = {8, 2, 0, 0, 0};  // bit depth, RGB, deflate, adaptive filtering, no interlace
  png_.append(format, 5);
  EndChunk(png_, chunk);

  chunk = BeginChunk(png_, "IDAT");
  Deflater& d = *deflater_;
  d.Start(level);
  const std::size_t bound = deflateBound(&d.stream, static_cast<uLong>(filtered_.size()));
  if (deflated_.size() < bound) deflated_.resize(bound);  // grows only: no fill per frame
  d.stream.next_in = filtered_.data();
  d.stream.avail_in = static_cast<uInt>(filtered_.size());
  d.stream.next_out = deflated_.data();
  d.stream.avail_out = static_cast<uInt>(deflated_.size());
  if (deflate(&d.stream, Z_FINISH) != Z_STREAM_END)
    throw Error("PNG encoder: zlib did not finish the stream (expected enough output space)");
  png_.append(reinterpret_cast<const char*>(deflated_.data()), d.stream.total_out);
  EndChunk(png_, chunk);
  EndChunk(png_, BeginChunk(png_, "IEND"));
  return png_;
}

}  // namespace prt
