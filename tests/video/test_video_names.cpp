// The names of video/ (core/name_table.h): each extension's format, the run summary's name of
// each format and the ffmpeg encoder of each codec, against the words written out here, and
// the encoder the arguments ask ffmpeg for is the one FindFfmpeg looks for.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "video/ffmpeg_encoder.h"
#include "video/video_writer.h"

namespace prt {

TEST_SUITE("video") {
  TEST_CASE("video names: each extension names its own format, and no other name is one") {
    CHECK(VideoFormatOf("turn.png") == VideoFormat::kApng);
    CHECK(VideoFormatOf("turn.apng") == VideoFormat::kApng);
    CHECK(VideoFormatOf("turn.mp4") == VideoFormat::kMp4);
    CHECK(VideoFormatOf("turn.webm") == VideoFormat::kWebm);
    for (const char* path : {"turn.", "turn.pn", "turn.pngx", "turn.mp", "turn.mp4 ", "turn.web", "turn.gif", "turn.mkv",
                             "turn.apn", ".", ""}) {
      CAPTURE(path);
      CHECK_FALSE(VideoFormatOf(path).has_value());
    }
  }

  TEST_CASE("video names: the run summary names each format as its own") {
    CHECK(std::string(VideoFormatName(VideoFormat::kApng)) == "animated PNG");
    CHECK(std::string(VideoFormatName(VideoFormat::kMp4)) == "H.264 MP4 (ffmpeg)");
    CHECK(std::string(VideoFormatName(VideoFormat::kWebm)) == "VP9 WebM (ffmpeg)");
  }

  TEST_CASE("video names: each codec's encoder, the one its ffmpeg arguments ask for") {
    CHECK(std::string(FfmpegEncoderName(FfmpegCodec::kH264Mp4)) == "libx264");
    CHECK(std::string(FfmpegEncoderName(FfmpegCodec::kVp9Webm)) == "libvpx-vp9");
    for (const auto& [codec, container] : {std::pair{FfmpegCodec::kH264Mp4, "mp4"}, std::pair{FfmpegCodec::kVp9Webm, "webm"}}) {
      CAPTURE(container);
      const std::vector<std::string> a = FfmpegArguments("ffmpeg", codec, 8, 6, 30.0, "turn");
      const auto c = std::find(a.begin(), a.end(), "-c:v");
      REQUIRE(c != a.end());
      REQUIRE(c + 1 != a.end());
      CHECK(*(c + 1) == FfmpegEncoderName(codec));
      const auto f = std::find(c, a.end(), "-f");
      REQUIRE(f + 1 < a.end());
      CHECK(*(f + 1) == container);
      CHECK(a.back() == "turn");
    }
  }
}

}  // namespace prt
