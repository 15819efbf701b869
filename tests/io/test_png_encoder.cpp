// PngEncoder (io/png_encoder.h): byte for byte what stb_image_write writes with zlib and the
// "sub" filter (an independent writer of the same PNG), pixels that decode back exactly, and an
// encoder reused across sizes and levels that writes what a fresh one writes.
#include <doctest/doctest.h>

#include <string>

#include "core/error.h"
#include "core/rng.h"
#include "io/png_encoder.h"
#include "io/png_io.h"
#include "tests/io/stb_png_reference.h"

namespace {

// Smooth gradients with noise in every seventh byte: long matches and literals both, so the
// filter and deflate see what frames give them.
prt::Image8 Frame(int w, int h, std::uint64_t seed) {
  prt::Pcg32 rng(seed, 3);
  prt::Image8 image(w, h);
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = i % 7 == 0 ? static_cast<std::uint8_t>(rng.NextU32()) : static_cast<std::uint8_t>((i / 3 + i % 3 * 40) % 256);
  return image;
}

TEST_SUITE("io") {
  TEST_CASE("PngEncoder writes stb_image_write's bytes, and a reused encoder a fresh one's") {
    prt::PngEncoder reused;
    int checked = 0;
    for (int w : {1, 2, 5, 64, 333})
      for (int h : {1, 3, 40})
        for (int level : {1, prt::kPngLevel, 6, 9}) {
          const prt::Image8 image = Frame(w, h, 10u * w + h);
          const std::string expected = test::StbPng(image, level);
          REQUIRE(!expected.empty());
          CHECK(reused.Encode(image, level) == expected);
          prt::PngEncoder fresh;
          CHECK(fresh.Encode(image, level) == expected);
          ++checked;
        }
    CHECK(checked == 60);
  }

  TEST_CASE("PngEncoder's file decodes to the image's pixels, at the frame sizes render uses") {
    prt::PngEncoder encoder;
    for (const auto& [w, h] : {std::pair{640, 480}, std::pair{97, 1080}}) {
      const prt::Image8 image = Frame(w, h, 7);
      const prt::Image8 back = prt::DecodePng(encoder.Encode(image), "frame");
      CHECK(back.width == w);
      CHECK(back.height == h);
      CHECK(back.rgb == image.rgb);
    }
  }

  TEST_CASE("PngEncoder refuses an empty or inconsistent image and a level outside 1..9") {
    prt::PngEncoder encoder;
    CHECK_THROWS_AS(encoder.Encode(prt::Image8()), prt::Error);
    prt::Image8 short_buffer(4, 4);
    short_buffer.rgb.pop_back();
    CHECK_THROWS_AS(encoder.Encode(short_buffer), prt::Error);
    const prt::Image8 image = Frame(4, 4, 1);
    CHECK_THROWS_AS(encoder.Encode(image, 0), prt::Error);
    CHECK_THROWS_AS(encoder.Encode(image, 10), prt::Error);
    CHECK(encoder.Encode(image, 9) == test::StbPng(image, 9));  // still usable after the errors
  }
}

}  // namespace
