#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <stb_image_write.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/rng.h"
#include "io/png_io.h"
#include "tests/io/png_test_util.h"
#include "tests/test_support.h"

// Part of libstb's stb_image_write implementation, but not declared in its header.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len,
                                             int quality);

namespace {

using prt::test::BigEndian32;
using prt::test::Chunk;

prt::Image8 Noise(int w, int h, std::uint64_t seed) {
  prt::Pcg32 rng(seed, 1);
  prt::Image8 image(w, h);
  for (auto& v : image.rgb) v = static_cast<std::uint8_t>(rng.NextU32() & 0xff);
  return image;
}

// A 16-bit RGB PNG built by hand (stb cannot write one).
std::string Png16(int w, int h, const std::vector<std::uint16_t>& rgb) {
  std::string raw;
  for (int y = 0; y < h; ++y) {
    raw += '\0';  // filter: none
    for (int i = 0; i < 3 * w; ++i) {
      const std::uint16_t v = rgb[static_cast<std::size_t>(3 * w * y + i)];
      raw += char(v >> 8);
      raw += char(v & 0xff);
    }
  }
  int zlen = 0;
  unsigned char* z = stbi_zlib_compress(reinterpret_cast<unsigned char*>(raw.data()),
                                        static_cast<int>(raw.size()), &zlen, 8);
  const std::string zdata(reinterpret_cast<char*>(z), static_cast<std::size_t>(zlen));
  std::free(z);
  const std::string ihdr = BigEndian32(static_cast<std::uint32_t>(w)) +
                           BigEndian32(static_cast<std::uint32_t>(h)) + std::string("\x10\x02\0\0\0", 5);
  return std::string("\x89PNG\r\n\x1a\n", 8) + Chunk("IHDR", ihdr) + Chunk("IDAT", zdata) +
         Chunk("IEND", "");
}

}  // namespace

TEST_SUITE("io") {
  TEST_CASE("PNG round trip: write, read back, identical 8-bit pixels") {
    const std::string dir = prt::test::ScratchDir("png_roundtrip");
    for (auto [w, h] : {std::pair{1, 1}, std::pair{17, 5}, std::pair{64, 48}}) {
      const prt::Image8 image = Noise(w, h, static_cast<std::uint64_t>(w * 100 + h));
      const std::string path = dir + "/a.png";
      prt::WritePng(path, image);
      const prt::Image8 back = prt::ReadPng(path);
      CHECK(back.width == w);
      CHECK(back.height == h);
      CHECK(back.rgb == image.rgb);
    }
    int entries = 0;  // no temporary file left behind
    for (auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++entries;
    CHECK(entries == 1);
  }

  TEST_CASE("Every zlib level decodes to the same pixels; smaller levels are not larger files") {
    // A smooth image with noise, like a rendered frame: level 6 must not come out larger than
    // level 1 (a level argument that is ignored would give equal sizes, caught below).
    prt::Image8 image = Noise(64, 48, 3);
    for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i / 97 + image.rgb[i] % 4);
    std::vector<std::size_t> sizes;
    for (int level : {1, 2, 6, 9}) {
      const std::string bytes = prt::EncodePng(image, level);
      CHECK(prt::DecodePng(bytes, "level.png").rgb == image.rgb);
      sizes.push_back(bytes.size());
    }
    CHECK(sizes.back() < sizes.front());
    CHECK(prt::EncodePng(image) == prt::EncodePng(image, prt::kPngLevel));
    CHECK_THROWS_AS(prt::EncodePng(image, 0), prt::Error);
    CHECK_THROWS_AS(prt::EncodePng(image, 10), prt::Error);
  }

  TEST_CASE("Grey and RGBA PNGs are read as RGB, 16-bit channels are rounded") {
    const std::string dir = prt::test::ScratchDir("png_kinds");
    const unsigned char grey[4] = {0, 100, 200, 255};
    REQUIRE(stbi_write_png((dir + "/g.png").c_str(), 2, 2, 1, grey, 2));
    const prt::Image8 g = prt::ReadPng(dir + "/g.png");
    CHECK(g.rgb == std::vector<std::uint8_t>{0, 0, 0, 100, 100, 100, 200, 200, 200, 255, 255, 255});
    const unsigned char rgba[8] = {10, 20, 30, 0, 40, 50, 60, 128};
    REQUIRE(stbi_write_png((dir + "/a.png").c_str(), 2, 1, 4, rgba, 8));
    CHECK(prt::ReadPng(dir + "/a.png").rgb == std::vector<std::uint8_t>{10, 20, 30, 40, 50, 60});
    // v * 255 / 65535 rounded: 0x1234 -> 18.13 -> 18; 0x0081 -> 0.502 -> 1 (stb's own
    // conversion, v >> 8, would give 0); 0x0080 -> 0.498 -> 0; 0xfeff -> 254.0 -> 254.
    const prt::Image8 wide = prt::DecodePng(Png16(2, 1, {0x1234, 0x0081, 0xffff, 0, 0x0080, 0xfeff}), "x.png");
    CHECK(wide.rgb == std::vector<std::uint8_t>{18, 1, 255, 0, 0, 254});
  }

  TEST_CASE("Missing, non-PNG and truncated files give clear errors") {
    const std::string dir = prt::test::ScratchDir("png_errors");
    CHECK_THROWS_WITH_AS(prt::ReadPng(dir + "/missing.png"), doctest::Contains("missing.png: no such file"),
                         prt::Error);
    prt::WriteFileAtomic(dir + "/text.png", "hello, this is not an image");
    CHECK_THROWS_WITH_AS(prt::ReadPng(dir + "/text.png"), doctest::Contains("not a PNG file"), prt::Error);
    const std::string full = prt::EncodePng(Noise(40, 30, 5));
    prt::WriteFileAtomic(dir + "/cut.png", full.substr(0, full.size() / 2));
    CHECK_THROWS_WITH_AS(prt::ReadPng(dir + "/cut.png"), doctest::Contains("cut.png: cannot decode PNG"),
                         prt::Error);
    CHECK_THROWS_AS(prt::EncodePng(prt::Image8()), prt::Error);
  }
}
