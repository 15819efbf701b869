// `--video` through the binary, as a user runs it. The animated PNG is read back by the tests'
// own strict reader and, where Debian's ffmpeg is installed, by ffmpeg as a standard decoder:
// its frame count, size, rate and loop, and every frame equal to the matching frame_NNNN.png.
// The .mp4 and .webm paths (ffmpeg) are checked by ffprobe and by decoding them: H.264 4:2:0
// with the BT.709 matrix, so a flat colour comes back as the PNG's colour. Bad requests are
// refused before any work; a failing encoder fails the run without a partial video.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "io/png_io.h"
#include "raster/image_diff.h"
#include "tests/test_process.h"
#include "tests/video/apng_test_reader.h"
#include "video/apng_writer.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// The embedded scene in closed form, small and quick, with frames that differ (the sky turns).
const std::string kScene = "--transport unshadowed --cache none --quiet --size 64x48 ";

/// H.264 at CRF 18 in 4:2:0 against the lossless frames: the mean absolute difference per
/// channel value measured 1.5 to 1.7 on the demo scene; twice that still fails a frame that is
/// another frame, a shifted image or another colour matrix.
constexpr double kLossyMeanAbs = 3.5;
/// A flat colour through 4:2:0 and limited range comes back within a few codes (measured: 2 on
/// a saturated red); the BT.601 matrix in place of BT.709 moves it by 13 and more.
constexpr int kFlatColourAbs = 4;

/// Runs `prt render` with `options`; requires success.
void Render(const std::string& options) {
  const auto r = test::RunPrt("render " + options);
  CAPTURE(options);
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
}

/// ffprobe's value of `entry` (stream=... or format=...) for the first video stream of `file`.
std::string Probe(const std::string& file, const std::string& entry) {
  const std::string ffprobe = fs::path(*test::Ffmpeg()).parent_path().string() + "/ffprobe";
  const auto r = test::RunCommand(Q(ffprobe) + " -v error -count_frames -select_streams v:0 -show_entries " + entry +
                                  " -of default=noprint_wrappers=1:nokey=1 " + Q(file));
  std::string out = r.out;
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

/// Every frame of `file` decoded by ffmpeg to 8-bit RGB images of `width` x `height`.
std::vector<Image8> DecodeWithFfmpeg(const std::string& file, int width, int height) {
  const auto r = test::RunCommand(Q(*test::Ffmpeg()) + " -v error -i " + Q(file) + " -f rawvideo -pix_fmt rgb24 -");
  REQUIRE(r.exit_code == 0);
  const std::size_t size = 3 * std::size_t(width) * std::size_t(height);
  REQUIRE(r.out.size() % size == 0);
  std::vector<Image8> frames;
  for (std::size_t at = 0; at < r.out.size(); at += size) {
    Image8& frame = frames.emplace_back(width, height);
    std::copy(r.out.begin() + std::ptrdiff_t(at), r.out.begin() + std::ptrdiff_t(at + size), frame.rgb.begin());
  }
  return frames;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("video: --video .png is an animated PNG of the frames, looping at --fps, the same for any --threads") {
    const std::string dir = test::ScratchDir("video_apng");
    const int n = 6;
    Render(kScene + "--frames 6 --fps 12 --threads 2 --out " + Q(dir + "/frames") + " --video " + Q(dir + "/turn.png"));
    const std::string bytes = ReadFile(dir + "/turn.png");
    const test::ApngFile apng = test::ReadApng(bytes);
    CHECK(apng.announced_frames == n);
    CHECK(apng.plays == 0);
    REQUIRE(apng.frames.size() == n);
    for (int i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(apng.frames[std::size_t(i)].delay_num == 1);
      CHECK(apng.frames[std::size_t(i)].delay_den == 12);
      const Image8 png = ReadPng(test::FramePath(dir + "/frames", i, n));
      const Image8 decoded = DecodePng(test::FrameAsPng(apng, std::size_t(i)), "frame");
      CHECK(decoded.width == 64);
      CHECK(decoded.height == 48);
      CHECK(decoded.rgb == png.rgb);
    }
    CHECK(ReadPng(test::FramePath(dir + "/frames", 0, n)).rgb != ReadPng(test::FramePath(dir + "/frames", 3, n)).rgb);  // frames differ
    // One thread: the same bytes.
    Render(kScene + "--frames 6 --fps 12 --threads 1 --out " + Q(dir + "/one") + " --video " + Q(dir + "/one.apng"));
    CHECK(ReadFile(dir + "/one.apng") == bytes);
  }

  TEST_CASE("video: a standard decoder (ffmpeg) plays the animated PNG: count, size, rate, every frame" *
            test::NeedsFfmpeg()) {
    const std::string dir = test::ScratchDir("video_apng_ffmpeg");
    const int n = 5;
    Render(kScene + "--frames 5 --fps 25 --out " + Q(dir) + " --video " + Q(dir + "/turn.png"));
    CHECK(Probe(dir + "/turn.png", "stream=codec_name") == "apng");
    CHECK(Probe(dir + "/turn.png", "stream=nb_read_frames") == "5");
    CHECK(Probe(dir + "/turn.png", "stream=width") == "64");
    CHECK(Probe(dir + "/turn.png", "stream=height") == "48");
    CHECK(Probe(dir + "/turn.png", "stream=avg_frame_rate") == "25/1");
    const std::vector<Image8> frames = DecodeWithFfmpeg(dir + "/turn.png", 64, 48);
    REQUIRE(frames.size() == n);
    for (int i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(frames[std::size_t(i)].rgb == ReadPng(test::FramePath(dir, i, n)).rgb);
    }
  }

  TEST_CASE("video: .mp4 is H.264 4:2:0 tagged BT.709, its frames the PNG frames within the codec's loss" *
            test::NeedsFfmpeg()) {
    const std::string dir = test::ScratchDir("video_mp4");
    const int n = 8;
    Render(kScene + "--frames 8 --fps 24 --threads 2 --out " + Q(dir) + " --video " + Q(dir + "/turn.mp4"));
    const std::string mp4 = dir + "/turn.mp4";
    CHECK(Probe(mp4, "stream=codec_name") == "h264");
    CHECK(Probe(mp4, "stream=pix_fmt") == "yuv420p");
    CHECK(Probe(mp4, "stream=color_space") == "bt709");
    CHECK(Probe(mp4, "stream=color_range") == "tv");
    CHECK(Probe(mp4, "stream=nb_read_frames") == "8");
    CHECK(Probe(mp4, "stream=avg_frame_rate") == "24/1");
    const std::vector<Image8> frames = DecodeWithFfmpeg(mp4, 64, 48);
    REQUIRE(frames.size() == n);
    for (int i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(CompareImages(frames[std::size_t(i)], ReadPng(test::FramePath(dir, i, n))).mean_abs < kLossyMeanAbs);
    }
    // The encoder's bytes do not follow prt's threads.
    Render(kScene + "--frames 8 --fps 24 --threads 1 --out " + Q(dir + "/one") + " --video " + Q(dir + "/one/turn.mp4"));
    CHECK(ReadFile(dir + "/one/turn.mp4") == ReadFile(mp4));
  }

  TEST_CASE("video: a flat colour comes back from .mp4 and .webm as the PNG's colour (BT.709 both ways)" *
            test::NeedsFfmpeg()) {
    const std::string dir = test::ScratchDir("video_flat");
    // The camera looks away from the mesh: every pixel is the background.
    const std::string flat = test::QuickScene() + " --quiet --cache none --background 0.6,0.05,0.08 --eye 100,0,0 "
                             "--target 200,0,0 --exposure 0 --size 32x32 --frames 2 --out " + Q(dir);
    for (const std::string ext : {"mp4", "webm"}) {
      CAPTURE(ext);
      Render(flat + " --video " + Q(dir + "/flat." + ext));
      const Image8 png = ReadPng(dir + "/frame_0000.png");
      const std::vector<Image8> frames = DecodeWithFfmpeg(dir + "/flat." + ext, 32, 32);
      REQUIRE(frames.size() == 2);
      const glm::ivec3 back = test::PixelAt(frames[0], 16, 16), expected = test::PixelAt(png, 16, 16);
      for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(std::abs(back[c] - expected[c]) <= kFlatColourAbs);
      }
    }
    CHECK(Probe(dir + "/flat.webm", "stream=codec_name") == "vp9");
    CHECK(Probe(dir + "/flat.webm", "stream=color_space") == "bt709");
  }

  TEST_CASE("video: bad requests are refused before any work, the output folder untouched") {
    const std::string dir = test::ScratchDir("video_refused");
    const std::string out = dir + "/out";
    const auto refused = [&](const std::string& options, int code, const std::string& message,
                             const std::string& prefix = "") {
      CAPTURE(options);
      const auto r = test::RunCommand(prefix + Q(test::PrtBinary()) + " render " + test::QuickScene() + " --out " + Q(out) +
                                      " " + options);
      CHECK(r.exit_code == code);
      CHECK(r.err.find("prt: error: ") == 0);
      CHECK(r.err.find(message) != std::string::npos);
      CAPTURE(r.err);
      CHECK_FALSE(fs::exists(out));
    };
    refused("--video " + Q(dir + "/turn.gif"), 2, "has no video extension");
    refused("--fps 24", 2, "--fps: sets the rate of --video");
    refused("--video " + Q(dir + "/t.png") + " --fps 120", 2, "too fast for an animated PNG");
    refused("--video " + Q(dir + "/t.png") + " --fps 0", 2, "--fps");
    refused("--size 641x480 --video " + Q(dir + "/t.mp4"), 2, "needs an even frame size");
    refused("--video " + Q(out + "/frame_0003.png"), 2, "one of the run's own outputs");
    refused("--video " + Q(out + "/transport.cache") + ".png --cache " + Q(out + "/transport.cache.png"), 2,
            "one of the run's own outputs");
    refused("--video " + Q(dir + "/v.png") + " --vertex-radiance " + Q(dir + "/v.png"), 2, "one of the run's own outputs");
    fs::create_directories(dir + "/folder.png");
    refused("--video " + Q(dir + "/folder.png"), 1, "is a folder");
    // Without ffmpeg on PATH: the package is named.
    refused("--video " + Q(dir + "/t.mp4"), 1, "apt-get install ffmpeg", "PATH=/nonexistent ");
    refused("--video " + Q(dir + "/t.webm"), 1, "apt-get install ffmpeg", "PATH=/nonexistent ");
  }

  TEST_CASE("video: an encoder that fails mid-way or at the end fails the run (exit 1, its message), leaving no video") {
    // Stand-ins for ffmpeg that list the encoder, then give up after part of the first frames
    // (prt then writes into a closed pipe: 12 frames of 64x48 are more than a pipe holds), or
    // read every frame and fail at the end.
    for (const std::string reading : {"head -c 1000 >/dev/null", "cat >/dev/null"}) {
      CAPTURE(reading);
      const std::string dir = test::ScratchDir("video_ffmpeg_fails");
      fs::create_directories(dir + "/bin");
      std::ofstream(dir + "/bin/ffmpeg") << "#!/bin/sh\n"
                                            "case \"$*\" in *-encoders*) echo ' V....D libx264  H.264'; exit 0;; esac\n" +
                                                reading + "\necho 'stand-in encoder: gave up' >&2\nexit 3\n";
      fs::permissions(dir + "/bin/ffmpeg", fs::perms::owner_all);
      const std::string video = dir + "/turn.mp4";
      std::ofstream(video) << "an earlier video";
      const auto r = test::RunCommand("PATH=" + Q(dir + "/bin") + ":\"$PATH\" " + Q(test::PrtBinary()) + " render " +
                                      kScene + "--frames 12 --out " + Q(dir + "/out") + " --video " + Q(video));
      CAPTURE(r.err);
      CHECK(r.exit_code == 1);  // not a signal (SIGPIPE would be 141)
      CHECK(r.err.find("stand-in encoder: gave up") != std::string::npos);
      CHECK(ReadFile(video) == "an earlier video");
      CHECK_FALSE(fs::exists(dir + "/out/frame_0000.png"));
      for (const auto& entry : fs::directory_iterator(dir))
        CHECK_FALSE(AtomicFile::IsTemporaryName(entry.path().filename()));
    }
  }

  TEST_CASE("video: a render killed mid-video leaves the earlier video as it was, beside only a temporary file") {
    const std::string dir = test::ScratchDir("video_killed");
    const std::string video = dir + "/turn.png";
    std::ofstream(video) << "an earlier video";
    const pid_t pid = test::StartLongRender(dir + "/out", "32x24", {"--video", video});
    REQUIRE(pid > 0);
    // Killed once frame 20 is staged: by then frames are in the video.
    REQUIRE(test::KillWhenFileAppears(pid, dir + "/out/" + OutputFolder::kStagingName + "/frame_0020.png"));
    CHECK(ReadFile(video) == "an earlier video");
    int temporary = 0;
    for (const auto& entry : fs::directory_iterator(dir))
      temporary += AtomicFile::IsTemporaryName(entry.path().filename().string());
    CHECK(temporary == 1);  // the killed run's video, under its temporary name
  }

  TEST_CASE("video: inside the output folder it is one of the run's outputs, removed by a run without it") {
    const std::string dir = test::ScratchDir("video_in_folder");
    Render(kScene + "--frames 3 --out " + Q(dir) + " --video " + Q(dir + "/turn.png"));
    CHECK(fs::exists(dir + "/turn.png"));
    CHECK(ReadFile(dir + "/.prt-outputs").find("turn.png") != std::string::npos);
    Render(kScene + "--frames 3 --out " + Q(dir));
    CHECK_FALSE(fs::exists(dir + "/turn.png"));
    CHECK(fs::exists(dir + "/frame_0002.png"));
  }
}

}  // namespace prt
