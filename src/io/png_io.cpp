#include "io/png_io.h"

#include <cstring>
#include <filesystem>
#include <memory>

#include <stb_image.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "io/png_chunks.h"

namespace prt {

std::string EncodePng(const Image8& image, int level) {
  PngEncoder encoder;
  return encoder.Encode(image, level);
}

void WritePng(const std::string& path, const Image8& image) {
  WriteFileAtomic(path, EncodePng(image));
}

Image8 DecodePng(const std::string& bytes, const std::string& name) {
  if (bytes.size() < sizeof kPngSignatureBytes ||
      std::memcmp(bytes.data(), kPngSignatureBytes, sizeof kPngSignatureBytes) != 0)
    throw Error(name + ": not a PNG file (expected the PNG signature)");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(std::min<std::size_t>(bytes.size(), 0x7fffffff));
  int width = 0, height = 0, channels = 0;
  Image8 image;
  if (stbi_is_16_bit_from_memory(data, size)) {
    // Round 16-bit channels to 8 bits (stb's own conversion truncates).
    std::unique_ptr<stbi_us, void (*)(void*)> pixels(
        stbi_load_16_from_memory(data, size, &width, &height, &channels, 3), stbi_image_free);
    if (!pixels) throw Error(name + ": cannot decode PNG: " + stbi_failure_reason() +
                             " (expected a complete, uncorrupted file)");
    image = Image8(width, height);
    for (std::size_t i = 0; i < image.rgb.size(); ++i)
      image.rgb[i] = static_cast<std::uint8_t>((pixels.get()[i] * 255u + 32767u) / 65535u);
    return image;
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(data, size, &width, &height, &channels, 3), stbi_image_free);
  if (!pixels) throw Error(name + ": cannot decode PNG: " + stbi_failure_reason() +
                           " (expected a complete, uncorrupted file)");
  image = Image8(width, height);
  std::memcpy(image.rgb.data(), pixels.get(), image.rgb.size());
  return image;
}

Image8 ReadPng(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error(path + ": no such file (expected a PNG image)");
  return DecodePng(ReadFile(path), path);
}

}  // namespace prt
