// VideoWriter (video/video_writer.h): frames that finish in any order, on any thread, are
// appended in frame order, so the file is byte for byte the one written in order; a failure is
// kept and refused again; the format follows the extension.
#include <doctest/doctest.h>

#include <string>
#include <thread>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/rng.h"
#include "io/png_io.h"
#include "tests/test_support.h"
#include "tests/video/apng_test_reader.h"
#include "video/video_writer.h"

namespace prt {
namespace {

Image8 Frame(int i) {
  Image8 image(9, 4);
  Pcg32 rng(std::uint64_t(i) + 1, 9);
  for (auto& v : image.rgb) v = std::uint8_t(rng.NextU32() & 0xff);
  return image;
}

VideoSpec Spec(int frames) {
  VideoSpec s;
  s.format = VideoFormat::kApng, s.width = 9, s.height = 4, s.frames = frames, s.fps = 12;
  return s;
}

/// The animated PNG of `order`'s frames added in that order.
std::string WriteInOrder(const std::string& path, const std::vector<int>& order) {
  VideoWriter writer(Spec(int(order.size())), path, path);
  for (int i : order) writer.AddFrame(i, Frame(i), EncodePng(Frame(i)));
  writer.Finish();
  return ReadFile(path);
}

}  // namespace

TEST_SUITE("video") {
  TEST_CASE("video writer: the format is the extension's, in any case") {
    CHECK(VideoFormatOf("a/turn.png") == VideoFormat::kApng);
    CHECK(VideoFormatOf("turn.APNG") == VideoFormat::kApng);
    CHECK(VideoFormatOf("x.y/turn.Mp4") == VideoFormat::kMp4);
    CHECK(VideoFormatOf("turn.webm") == VideoFormat::kWebm);
    CHECK_FALSE(VideoFormatOf("turn.gif").has_value());
    CHECK_FALSE(VideoFormatOf("turn").has_value());
    CHECK_FALSE(VideoFormatOf("folder.mp4/turn").has_value());
  }

  TEST_CASE("video writer: frames arriving out of order, from several threads, give the in-order file") {
    const std::string dir = test::ScratchDir("video_order");
    const int n = 12;
    std::vector<int> in_order(n);
    for (int i = 0; i < n; ++i) in_order[std::size_t(i)] = i;
    const std::string expected = WriteInOrder(dir + "/in_order.png", in_order);
    CHECK(WriteInOrder(dir + "/scrambled.png", {5, 3, 0, 11, 1, 2, 4, 10, 6, 9, 8, 7}) == expected);
    // Four threads, each its own frames in descending order.
    VideoWriter writer(Spec(n), dir + "/threads.png", "threads.png");
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&writer, t] {
        for (int i = n - 4 + t; i >= 0; i -= 4) writer.AddFrame(i, Frame(i), EncodePng(Frame(i)));
      });
    for (auto& thread : threads) thread.join();
    writer.Finish();
    CHECK(ReadFile(dir + "/threads.png") == expected);
    const test::ApngFile apng = test::ReadApng(expected);
    REQUIRE(apng.frames.size() == n);
    for (int i = 0; i < n; ++i) CHECK(DecodePng(test::FrameAsPng(apng, std::size_t(i)), "f").rgb == Frame(i).rgb);
  }

  TEST_CASE("video writer: a missing frame is an error, and a failed append is refused again") {
    const std::string dir = test::ScratchDir("video_fail");
    {
      VideoWriter writer(Spec(3), dir + "/gap.png", "gap.png");
      writer.AddFrame(0, Frame(0), EncodePng(Frame(0)));
      writer.AddFrame(2, Frame(2), EncodePng(Frame(2)));
      CHECK_THROWS_WITH_AS(writer.Finish(), doctest::Contains("1 of 3 frames"), Error);
    }
    VideoWriter writer(Spec(3), dir + "/bad.png", "bad.png");
    writer.AddFrame(0, Frame(0), EncodePng(Frame(0)));
    CHECK_THROWS_AS(writer.AddFrame(1, Frame(1), "not a png"), Error);
    CHECK_THROWS_AS(writer.AddFrame(2, Frame(2), EncodePng(Frame(2))), Error);
    CHECK_THROWS_AS(writer.Finish(), Error);
  }
}

}  // namespace prt
