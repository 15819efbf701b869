// The PNG chunk layer (io/png_chunks.h) against the specification's own numbers (the IEND
// chunk every PNG ends with, CRC AE 42 60 82) and the tests' bit-by-bit CRC, and against PNG
// files stb encodes: the chunks read back are the file, and damage is named.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "io/png_chunks.h"
#include "io/png_io.h"
#include "tests/io/png_test_util.h"

namespace prt {
namespace {

std::string RandomBytes(std::size_t n, std::uint64_t seed) {
  Pcg32 rng(seed, 3);
  std::string s(n, '\0');
  for (auto& c : s) c = char(rng.NextU32() & 0xff);
  return s;
}

Image8 Gradient(int w, int h) {
  Image8 image(w, h);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = std::uint8_t((i * 7) % 251);
  return image;
}

}  // namespace

TEST_SUITE("io") {
  TEST_CASE("PNG chunks: IEND is the specification's 12 bytes, any chunk matches the bit-by-bit CRC") {
    std::string iend;
    AppendPngChunk(iend, "IEND", {});
    CHECK(iend == std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12));
    for (std::size_t n : {1u, 13u, 1000u, 70000u}) {
      const std::string data = RandomBytes(n, n);
      std::string chunk;
      AppendPngChunk(chunk, "fdAT", data);
      CHECK(chunk == test::Chunk("fdAT", data));
    }
  }

  TEST_CASE("PNG chunks: an encoded PNG reads back chunk by chunk, its image data is the IDAT stream") {
    const std::string png = EncodePng(Gradient(37, 11));
    std::vector<std::string> types;
    std::string rebuilt(kPngSignatureBytes, 8);
    ForEachPngChunk(png, "gradient", [&](std::string_view type, std::string_view data) {
      types.emplace_back(type);
      AppendPngChunk(rebuilt, type, data);
    });
    REQUIRE(types.size() >= 3);
    CHECK(types.front() == "IHDR");
    CHECK(types.back() == "IEND");
    CHECK(rebuilt == png);
    const PngImageData image = ExtractPngImageData(png, "gradient");
    CHECK(image.width == 37);
    CHECK(image.height == 11);
    // The stream alone, rewrapped, is the same image.
    const std::string alone = test::kSignature + test::Chunk("IHDR", image.ihdr) + test::Chunk("IDAT", image.idat) +
                              test::Chunk("IEND", "");
    CHECK(DecodePng(alone, "rewrapped").rgb == Gradient(37, 11).rgb);
  }

  TEST_CASE("PNG chunks: a wrong CRC, a truncated file and a missing signature are named") {
    const std::string png = EncodePng(Gradient(8, 8));
    const auto visit_all = [](const std::string& bytes) {
      ForEachPngChunk(bytes, "f.png", [](std::string_view, std::string_view) {});
    };
    CHECK_NOTHROW(visit_all(png));
    std::string flipped = png;
    flipped[40] = char(flipped[40] ^ 1);  // inside IDAT's data
    CHECK_THROWS_WITH_AS(visit_all(flipped), doctest::Contains("wrong CRC"), Error);
    CHECK_THROWS_WITH_AS(visit_all(png.substr(0, png.size() - 12)), doctest::Contains("ends before its IEND"), Error);
    CHECK_THROWS_WITH_AS(visit_all(png.substr(0, 50)), doctest::Contains("f.png"), Error);
    CHECK_THROWS_WITH_AS(visit_all("GIF89a" + png), doctest::Contains("not a PNG"), Error);
  }
}

}  // namespace prt
