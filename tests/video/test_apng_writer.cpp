// The animated PNG writer (video/apng_writer.h) read back by the tests' own strict reader
// (tests/video/apng_test_reader.h): the chunk order and sequence numbers of the APNG
// specification, a loop for ever, each frame covering the image for 1/fps seconds, and every
// frame decoding to exactly the pixels of the PNG it came from.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/rng.h"
#include "io/png_io.h"
#include "tests/test_support.h"
#include "tests/video/apng_test_reader.h"
#include "video/apng_writer.h"

namespace prt {
namespace {

/// Frame `i` of a test animation: noise, different in every frame (so a reordered or repeated
/// frame is seen), of an odd size (so width and height cannot be swapped unseen).
Image8 NoiseFrame(int i, int w = 7, int h = 5) {
  Pcg32 rng(std::uint64_t(i) + 11, 5);
  Image8 image(w, h);
  for (auto& v : image.rgb) v = std::uint8_t(rng.NextU32() & 0xff);
  return image;
}

/// Writes frames 0..n-1 at `fps` to `path` and returns the file's bytes.
std::string WriteApng(const std::string& path, int n, double fps) {
  ApngWriter writer(path, path, n, fps);
  for (int i = 0; i < n; ++i) writer.AddFrame(EncodePng(NoiseFrame(i)));
  writer.Finish();
  return ReadFile(path);
}

}  // namespace

TEST_SUITE("video") {
  TEST_CASE("APNG delay: the closest fraction of 16-bit terms to 1/fps") {
    const auto check = [](double fps, int num, int den) {
      CAPTURE(fps);
      const ApngDelay d = ApngDelayOf(fps);
      CHECK(d.num == num);
      CHECK(d.den == den);
    };
    check(30, 1, 30);
    check(24, 1, 24);
    check(29.97, 100, 2997);
    check(23.976, 125, 2997);
    check(0.5, 2, 1);
    check(0.1, 10, 1);
    check(240, 1, 240);
    check(2.5, 2, 5);
  }

  TEST_CASE("APNG: the specification's chunks, numbered in order, a loop, every frame the PNG's pixels") {
    const std::string dir = test::ScratchDir("apng_structure");
    const int n = 5;
    const double fps = 29.97;
    const test::ApngFile apng = test::ReadApng(WriteApng(dir + "/a.png", n, fps));
    CHECK(apng.announced_frames == n);
    CHECK(apng.plays == 0);  // for ever
    CHECK(apng.first_frame_is_default_image);
    REQUIRE(apng.frames.size() == n);
    const ApngDelay delay = ApngDelayOf(fps);
    for (int i = 0; i < n; ++i) {
      CAPTURE(i);
      const test::ApngFrame& f = apng.frames[std::size_t(i)];
      CHECK(f.width == 7);
      CHECK(f.height == 5);
      CHECK(f.x == 0);
      CHECK(f.y == 0);
      CHECK(f.delay_num == delay.num);
      CHECK(f.delay_den == delay.den);
      CHECK(f.dispose == 0);  // NONE
      CHECK(f.blend == 0);    // SOURCE
      CHECK(DecodePng(test::FrameAsPng(apng, std::size_t(i)), "frame").rgb == NoiseFrame(i).rgb);
    }
  }

  TEST_CASE("APNG: one frame is a valid animation; a viewer without APNG shows frame 0") {
    const std::string dir = test::ScratchDir("apng_one");
    const std::string bytes = WriteApng(dir + "/one.png", 1, 30);
    const test::ApngFile apng = test::ReadApng(bytes);
    CHECK(apng.frames.size() == 1);
    // A plain PNG decoder skips the animation chunks and sees the default image.
    CHECK(DecodePng(bytes, "one.png").rgb == NoiseFrame(0).rgb);
  }

  TEST_CASE("APNG: too few or too many frames, a frame of another size, an unwritable path are errors") {
    const std::string dir = test::ScratchDir("apng_errors");
    {
      ApngWriter writer(dir + "/few.png", "few.png", 3, 30);
      writer.AddFrame(EncodePng(NoiseFrame(0)));
      CHECK_THROWS_WITH_AS(writer.Finish(), doctest::Contains("1 frames written (expected 3)"), Error);
    }
    {
      ApngWriter writer(dir + "/many.png", "many.png", 1, 30);
      writer.AddFrame(EncodePng(NoiseFrame(0)));
      CHECK_THROWS_WITH_AS(writer.AddFrame(EncodePng(NoiseFrame(1))), doctest::Contains("one too many"), Error);
    }
    {
      ApngWriter writer(dir + "/size.png", "size.png", 2, 30);
      writer.AddFrame(EncodePng(NoiseFrame(0)));
      CHECK_THROWS_WITH_AS(writer.AddFrame(EncodePng(NoiseFrame(1, 5, 7))), doctest::Contains("differs from frame 0"),
                           Error);
    }
    CHECK_THROWS_WITH_AS(ApngWriter(dir + "/missing/x.png", "missing/x.png", 1, 30),
                         doctest::Contains("does not exist"), Error);
  }
}

}  // namespace prt
