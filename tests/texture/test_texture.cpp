// The texture itself: mip pyramid, orientation of v, wrapping, trilinear blending, the level of
// detail, and reading texture files (sRGB vs linear, clamping, errors).
#include <doctest/doctest.h>

#include <cmath>

#include "core/atomic_file.h"
#include "core/error.h"
#include "io/hdr_writer.h"
#include "io/image_load.h"
#include "io/load_texture.h"
#include "io/png_io.h"
#include "texture/texture.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("texture");

namespace {

// Sampling sums a few float products of values in [0, 1]: a few ulps of 1.
constexpr float kSampleTolerance = 1e-6f;

// A w x h texture whose texel (x, y) has a colour no other texel has.
ImageF Distinct(int w, int h) {
  ImageF image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.at(x, y) = glm::vec3(float(x) / float(w), float(y) / float(h), float(x * h + y) / float(w * h));
  return image;
}

bool Near(const glm::vec3& a, const glm::vec3& b, float tolerance = kSampleTolerance) {
  return std::fabs(a.x - b.x) <= tolerance && std::fabs(a.y - b.y) <= tolerance && std::fabs(a.z - b.z) <= tolerance;
}

}  // namespace

TEST_CASE("texture: each mip level halves the sides (rounding up) and averages 2 x 2 texels") {
  const ImageF image = Distinct(5, 3);
  const Texture t(image, "distinct");
  REQUIRE(t.level_count() == 4);  // 5x3, 3x2, 2x1, 1x1
  CHECK(t.level(1).width == 3);
  CHECK(t.level(1).height == 2);
  CHECK(t.level(2).width == 2);
  CHECK(t.level(2).height == 1);
  CHECK(t.level(3).width == 1);
  // Level 1, texel (0, 0): the mean of level 0's (0..1, 0..1); texel (2, 1): the edge repeated.
  CHECK(Near(t.level(1).at(0, 0), 0.25f * (image.at(0, 0) + image.at(1, 0) + image.at(0, 1) + image.at(1, 1))));
  CHECK(Near(t.level(1).at(2, 1), image.at(4, 2)));
  // A power-of-two texture's last level is its exact mean.
  const ImageF square = Distinct(4, 4);
  glm::vec3 sum(0.f);
  for (const glm::vec3& p : square.pixels) sum += p;
  CHECK(Near(Texture(square, "square").mean(), sum / 16.f));
}

TEST_CASE("texture: v runs up (row 0 is the top), texel centres sample exactly, coordinates repeat") {
  const ImageF image = Distinct(4, 2);
  const Texture t(image, "distinct");
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      const glm::vec2 uv((float(x) + 0.5f) / 4.f, 1.f - (float(y) + 0.5f) / 2.f);
      CHECK(Near(t.Sample(uv, 0.f), image.at(x, y)));
      CHECK(Near(t.Sample(uv + glm::vec2(3.f, -2.f), 0.f), image.at(x, y)));  // repeat
    }
  // Halfway between two texel centres: their mean (bilinear), across the wrap too.
  CHECK(Near(t.Sample({0.25f, 0.75f}, 0.f), 0.5f * (image.at(0, 0) + image.at(1, 0))));
  CHECK(Near(t.Sample({0.f, 0.75f}, 0.f), 0.5f * (image.at(3, 0) + image.at(0, 0))));
}

TEST_CASE("texture: the level of detail blends the two nearest levels and follows the footprint") {
  const Texture t(Distinct(8, 8), "distinct");
  const glm::vec2 uv(0.3f, 0.6f);
  const glm::vec3 l1 = t.Sample(uv, 1.f), l2 = t.Sample(uv, 2.f);
  CHECK(Near(t.Sample(uv, 1.25f), l1 + 0.25f * (l2 - l1)));
  CHECK(Near(t.Sample(uv, 99.f), t.mean()));
  CHECK(Near(t.Sample(uv, -3.f), t.Sample(uv, 0.f)));
  // One texel per pixel: level 0; four texels (along either axis): level 2.
  CHECK(t.LodOf({1.f / 8, 0.f}, {0.f, 1.f / 8}) == doctest::Approx(0.0));
  CHECK(t.LodOf({0.f, 0.f}, {0.f, 4.f / 8}) == doctest::Approx(2.0));
  CHECK(t.LodOf({4.f / 8, 0.f}, {0.f, 0.f}) == doctest::Approx(2.0));
}

TEST_CASE("texture files: png is sRGB-decoded, hdr is linear; out-of-range texels are clamped with a warning") {
  const std::string dir = test::ScratchDir("texture_files");
  Image8 png(2, 1);
  png.rgb = {128, 0, 255, 10, 200, 30};
  WritePng(dir + "/a.png", png);
  std::vector<std::string> warnings;
  const Texture a = LoadTexture(dir + "/a.png", warnings);
  CHECK(warnings.empty());
  CHECK(Near(a.level(0).at(0, 0), glm::vec3(float(SrgbToLinear(128 / 255.0)), 0.f, 1.f)));
  CHECK(Near(a.level(0).at(1, 0),
             glm::vec3(float(SrgbToLinear(10 / 255.0)), float(SrgbToLinear(200 / 255.0)), float(SrgbToLinear(30 / 255.0)))));
  ImageF hdr(2, 1);
  hdr.pixels = {glm::vec3(0.25f, 0.5f, 0.75f), glm::vec3(3.f, 0.5f, 0.f)};
  WriteFileAtomic(dir + "/b.hdr", EncodeHdr(hdr));
  const Texture b = LoadTexture(dir + "/b.hdr", warnings);
  CHECK(Near(b.level(0).at(0, 0), glm::vec3(0.25f, 0.5f, 0.75f), 1e-2f));  // RGBE keeps 8 bits of mantissa
  CHECK(b.level(0).at(1, 0).x == 1.f);                                        // 3 clamped to 1
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("clamped") != std::string::npos);
}

TEST_CASE("texture files: missing, corrupt and directory paths are one-line errors naming the path") {
  const std::string dir = test::ScratchDir("texture_errors");
  WriteFileAtomic(dir + "/bad.png", "not a png at all");
  std::vector<std::string> warnings;
  for (const std::string& path : {dir + "/none.png", dir + "/bad.png", dir}) {
    try {
      LoadTexture(path, warnings);
      FAIL("no error for " << path);
    } catch (const Error& e) {
      const std::string message = e.what();
      CHECK(message.rfind(path + ":", 0) == 0);
      CHECK(message.find('\n') == std::string::npos);
    }
  }
}

TEST_SUITE_END();
