// FrameWriter (render/frame_writer.h): frames encoded on worker threads land in their files and
// reach the video in frame order, each slot's image is reused rather than allocated again, a
// failed write is rethrown, and frames out of order are refused.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/rng.h"
#include "io/png_io.h"
#include "render/frame_writer.h"
#include "tests/test_support.h"
#include "tests/video/apng_test_reader.h"
#include "video/video_writer.h"

namespace prt {
namespace {

void Fill(Image8& image, int i) {
  image.width = 13;  // the same size every frame: the slot's buffer is kept
  image.height = 7;
  image.rgb.resize(3 * 13 * 7);
  Pcg32 rng(std::uint64_t(i) + 1, 4);
  for (auto& v : image.rgb) v = std::uint8_t(rng.NextU32() & 0xff);
}

Image8 Expected(int i) {
  Image8 image;
  Fill(image, i);
  return image;
}

}  // namespace

TEST_SUITE("render") {
  TEST_CASE("frame writer: every frame's file, the video in frame order, slots reused") {
    const std::string dir = test::ScratchDir("frame_writer");
    const int n = 11;
    for (int workers : {1, 3}) {
      VideoSpec spec;
      spec.format = VideoFormat::kApng, spec.width = 13, spec.height = 7, spec.frames = n, spec.fps = 10;
      const std::string video_path = dir + "/v" + std::to_string(workers) + ".png";
      std::vector<const Image8*> slot_of(n);
      {
        VideoWriter video(spec, video_path, "v.png");
        FrameWriter writer(workers, &video);
        for (int i = 0; i < n; ++i) {
          Image8& image = writer.Next(i);
          slot_of[std::size_t(i)] = &image;
          // The slot comes back as the frame before left it: its buffer, not a new one.
          if (i > workers) CHECK(image.rgb == Expected(i - workers - 1).rgb);
          Fill(image, i);
          writer.Submit(dir + "/f" + std::to_string(workers) + "_" + std::to_string(i) + ".png");
        }
        writer.Finish();
        video.Finish();
      }
      for (int i = 0; i < n; ++i)
        CHECK(ReadPng(dir + "/f" + std::to_string(workers) + "_" + std::to_string(i) + ".png").rgb == Expected(i).rgb);
      const test::ApngFile apng = test::ReadApng(ReadFile(video_path));
      REQUIRE(apng.frames.size() == std::size_t(n));
      for (int i = 0; i < n; ++i) CHECK(DecodePng(test::FrameAsPng(apng, std::size_t(i)), "f").rgb == Expected(i).rgb);
      // workers + 1 slots, in turn: frame i and frame i + workers + 1 share an image.
      for (int i = 0; i + workers + 1 < n; ++i) CHECK(slot_of[std::size_t(i)] == slot_of[std::size_t(i + workers + 1)]);
      CHECK(slot_of[0] != slot_of[1]);
    }
  }

  TEST_CASE("frame writer: a frame that cannot be written is an error of a later Next or of Finish") {
    const std::string dir = test::ScratchDir("frame_writer_fail");
    FrameWriter writer(1, nullptr);
    Fill(writer.Next(0), 0);
    writer.Submit(dir + "/no_such_folder/f0.png");
    Fill(writer.Next(1), 1);
    writer.Submit(dir + "/f1.png");
    CHECK_THROWS_WITH_AS(writer.Next(2), doctest::Contains("no_such_folder"), Error);
    FrameWriter second(2, nullptr);
    Fill(second.Next(0), 0);
    second.Submit(dir + "/missing/f0.png");
    CHECK_THROWS_WITH_AS(second.Finish(), doctest::Contains("missing"), Error);
  }

  TEST_CASE("frame writer: frames out of order, or submitted without Next, are refused") {
    FrameWriter writer(1, nullptr);
    CHECK_THROWS_AS(writer.Next(1), Error);
    CHECK_THROWS_AS(writer.Submit(""), Error);
    Fill(writer.Next(0), 0);
    CHECK_THROWS_AS(writer.Next(1), Error);  // frame 0 not submitted yet
    writer.Submit("");
    CHECK(writer.Finish() >= 0.0);
  }
}

}  // namespace prt
