#include "io/image_load.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>

#include <stb_image.h>

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

#include "core/atomic_file.h"
#include "core/error.h"

namespace prt {
namespace fs = std::filesystem;

namespace {

std::string Lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void CheckReadable(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path + ": no such file");
  if (fs::is_directory(path, ec)) throw Error(path + ": is a directory (expected an image file)");
  if (fs::file_size(path, ec) == 0) throw Error(path + ": empty file (expected an image)");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw Error(path + ": cannot open (" + std::strerror(errno) + ")");
  std::fclose(f);
}

void CheckSize(const std::string& path, long long w, long long h) {
  if (w <= 0 || h <= 0) throw Error(path + ": image has no pixels");
  if (w > kMaxImageSide || h > kMaxImageSide ||
      static_cast<unsigned long long>(w * h) > kMaxImagePixels)
    throw Error(path + ": image of " + std::to_string(w) + "x" + std::to_string(h) +
                " is too large (at most " + std::to_string(kMaxImageSide) + " per side and " +
                std::to_string(kMaxImagePixels) + " pixels)");
}

bool IsExr(const std::string& path) { return Lower(fs::path(path).extension().string()) == ".exr"; }

// stb_image (Debian's 2.27) trusts the pixel data of a Radiance .hdr file: a truncated flat file
// decodes silently from whatever the buffer held, and an RLE count of 0 (or a run of 0) loops
// forever. So the payload is walked here first, exactly as stb will read it, and a file that
// ends early or has a zero-length run is an error. Other faults (a scanline of the wrong
// length, a run past the end of the line) stb reports itself.
void CheckHdrPayload(const std::string& path, const std::string& bytes, long long width, long long height) {
  auto fail = [&](const std::string& problem) {
    throw Error(path + ": truncated or corrupt HDR image (" + problem + "; expected " +
                std::to_string(width) + "x" + std::to_string(height) + " RGBE pixels)");
  };
  // The header ends at an empty line; the resolution line follows.
  std::size_t pos = bytes.find("\n\n");
  if (pos == std::string::npos) return;  // stb rejects the header itself
  pos = bytes.find('\n', pos + 2);
  if (pos == std::string::npos) fail("no pixel data");
  ++pos;
  const auto left = [&] { return static_cast<long long>(bytes.size() - pos); };
  const long long flat_bytes = 4 * width * height;
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  if (width < 8 || width >= 32768) {
    if (left() < flat_bytes) fail("the file ends after " + std::to_string(left() / 4) + " pixels");
    return;
  }
  for (long long row = 0; row < height; ++row) {
    if (left() < 4) fail("the file ends at scanline " + std::to_string(row));
    if (byte(pos) != 2 || byte(pos + 1) != 2 || (byte(pos + 2) & 0x80)) {
      // Not run-length encoded: stb reads the whole image as flat pixels from here.
      if (left() < flat_bytes) fail("the file ends before the last flat pixel");
      return;
    }
    if (((byte(pos + 2) << 8) | byte(pos + 3)) != width) return;  // stb reports it
    pos += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (long long x = 0; x < width;) {
        if (left() < 1) fail("the file ends in scanline " + std::to_string(row));
        const int count = byte(pos++);
        const int run = count > 128 ? count - 128 : count;
        if (run == 0) fail("a run of length 0 in scanline " + std::to_string(row));
        if (run > width - x) return;  // stb reports it
        const long long need = count > 128 ? 1 : run;
        if (left() < need) fail("the file ends in scanline " + std::to_string(row));
        pos += static_cast<std::size_t>(need);
        x += run;
      }
    }
  }
}

// stb's info call gives "unknown image type" for a PNG larger than it decodes; read the size
// from the IHDR chunk of the file's first bytes then, so the message says what is wrong.
void CheckPngHeaderSize(const std::string& path, const std::string& head) {
  unsigned char h[24] = {};
  const std::size_t n = std::min(head.size(), sizeof h);
  std::memcpy(h, head.data(), n);
  static const unsigned char kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (n < sizeof h || std::memcmp(h, kSignature, 8) != 0 || std::memcmp(h + 12, "IHDR", 4) != 0) return;
  auto be32 = [&](int i) {
    return static_cast<long long>(h[i]) << 24 | h[i + 1] << 16 | h[i + 2] << 8 | h[i + 3];
  };
  CheckSize(path, be32(16), be32(20));
}

ImageF LoadExr(const std::string& path) {
  try {
    Imf::RgbaInputFile file(path.c_str());
    const Imath::Box2i dw = file.dataWindow();
    const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
    const long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
    CheckSize(path, w, h);
    Imf::Array2D<Imf::Rgba> pixels(h, w);
    file.setFrameBuffer(&pixels[0][0] - dw.min.x - static_cast<long long>(dw.min.y) * w, 1, w);
    file.readPixels(dw.min.y, dw.max.y);
    ImageF image(static_cast<int>(w), static_cast<int>(h));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Imf::Rgba& p = pixels[y][x];
        image.at(x, y) = {float(p.r), float(p.g), float(p.b)};
      }
    return image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    std::string what = e.what();
    if (const auto nl = what.find('\n'); nl != std::string::npos) what.resize(nl);
    throw Error(path + ": cannot read OpenEXR file (" + what + ")");
  }
}

// The first `count` bytes of the file (fewer if it is shorter).
std::string ReadHead(const std::string& path, std::size_t count) {
  std::string head(count, '\0');
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {};
  head.resize(std::fread(head.data(), 1, count, f));
  std::fclose(f);
  return head;
}

// The file read once, then decoded from memory.
ImageF LoadStb(const std::string& path, LdrDecode ldr) {
  const std::string file = ReadFile(path);
  if (file.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(path + ": file of " + std::to_string(file.size()) + " bytes is too large for an image");
  const auto* bytes = reinterpret_cast<const stbi_uc*>(file.data());
  const int size = static_cast<int>(file.size());
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(bytes, size, &w, &h, &n)) {
    const std::string reason = stbi_failure_reason();
    CheckPngHeaderSize(path, file);
    throw Error(path + ": not a readable image (" + reason + "; expected jpg, png, hdr or exr)");
  }
  CheckSize(path, w, h);
  const bool hdr = stbi_is_hdr_from_memory(bytes, size);
  if (hdr) CheckHdrPayload(path, file, w, h);
  ImageF image(w, h);
  const std::size_t count = static_cast<std::size_t>(w) * h;
  if (hdr) {
    std::unique_ptr<float, void (*)(void*)> data(stbi_loadf_from_memory(bytes, size, &w, &h, &n, 3), stbi_image_free);
    if (!data) throw Error(path + ": truncated or corrupt HDR image (" + stbi_failure_reason() + ")");
    for (std::size_t i = 0; i < count; ++i)
      image.pixels[i] = {data.get()[3 * i], data.get()[3 * i + 1], data.get()[3 * i + 2]};
    return image;
  }
  // LDR: decode through a lookup table of the transfer curve.
  const bool sixteen = stbi_is_16_bit_from_memory(bytes, size);
  const int levels = sixteen ? 65536 : 256;
  std::vector<float> lut(levels);
  for (int i = 0; i < levels; ++i) {
    const double c = double(i) / (levels - 1);
    lut[i] = float(ldr == LdrDecode::kSrgb ? SrgbToLinear(c) : std::pow(c, 2.2));
  }
  if (sixteen) {
    std::unique_ptr<stbi_us, void (*)(void*)> data(stbi_load_16_from_memory(bytes, size, &w, &h, &n, 3), stbi_image_free);
    if (!data) throw Error(path + ": truncated or corrupt image (" + stbi_failure_reason() + ")");
    for (std::size_t i = 0; i < count; ++i)
      image.pixels[i] = {lut[data.get()[3 * i]], lut[data.get()[3 * i + 1]], lut[data.get()[3 * i + 2]]};
  } else {
    std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load_from_memory(bytes, size, &w, &h, &n, 3), stbi_image_free);
    if (!data) throw Error(path + ": truncated or corrupt image (" + stbi_failure_reason() + ")");
    for (std::size_t i = 0; i < count; ++i)
      image.pixels[i] = {lut[data.get()[3 * i]], lut[data.get()[3 * i + 1]], lut[data.get()[3 * i + 2]]};
  }
  return image;
}

}  // namespace

double SrgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

void ImageSize(const std::string& path, int& width, int& height) {
  CheckReadable(path);
  if (IsExr(path)) {
    try {
      Imf::RgbaInputFile file(path.c_str());
      const Imath::Box2i dw = file.dataWindow();
      width = dw.max.x - dw.min.x + 1;
      height = dw.max.y - dw.min.y + 1;
      return;
    } catch (const std::exception& e) {
      throw Error(path + ": cannot read OpenEXR header");
    }
  }
  int n = 0;
  if (!stbi_info(path.c_str(), &width, &height, &n)) {
    CheckPngHeaderSize(path, ReadHead(path, 24));
    throw Error(path + ": not a readable image (expected jpg, png, hdr or exr)");
  }
}

ImageF LoadImageLinear(const std::string& path, LdrDecode ldr) {
  CheckReadable(path);
  return IsExr(path) ? LoadExr(path) : LoadStb(path, ldr);
}

SanitizeCounts SanitizeRadiance(ImageF& image) {
  SanitizeCounts counts;
  for (auto& p : image.pixels) {
    for (int c = 0; c < 3; ++c) {
      float& v = p[c];
      if (!std::isfinite(v)) {
        v = 0.0f;
        ++counts.non_finite;
      } else if (v < 0.0f) {
        v = 0.0f;
        ++counts.negative;
      } else if (v > kMaxRadiance) {
        v = kMaxRadiance;
        ++counts.enormous;
      }
    }
  }
  return counts;
}

std::string DescribeSanitized(const SanitizeCounts& c) {
  std::string s;
  auto add = [&](std::size_t n, const char* what) {
    if (n == 0) return;
    s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(c.non_finite, "NaN/Inf values set to 0");
  add(c.negative, "negative values set to 0");
  add(c.enormous, "values above 1e15 clamped");
  return s;
}

}  // namespace prt
