#include "video/ffmpeg_encoder.h"

#include <cstdio>
#include <cstdlib>

#include "core/error.h"
#include "core/name_table.h"
#include "core/text.h"

namespace prt {
namespace {

/// The encoder's threads: fixed, so that prt's --threads does not reach the file (see the header).
constexpr const char* kEncoderThreads = "4";

/// Where ffmpeg's messages go: a temporary file of this name in $TMPDIR or /tmp (AtomicFile:
/// this process's own name, removed at the end or by a signal, swept by a later run after a
/// SIGKILL).
std::string LogPath() {
  const char* tmp = std::getenv("TMPDIR");
  return std::string(tmp && *tmp ? tmp : "/tmp") + "/prt-ffmpeg.log";
}

constexpr auto kEncoders = MakeNameTable<FfmpegCodec>({
    {FfmpegCodec::kH264Mp4, "libx264"},
    {FfmpegCodec::kVp9Webm, "libvpx-vp9"},
});
static_assert(kEncoders.Distinct());

}  // namespace

const char* FfmpegEncoderName(FfmpegCodec codec) { return kEncoders.Name(codec); }

std::string FindFfmpeg(FfmpegCodec codec, const std::string& what) {
  const auto program = FindProgram("ffmpeg");
  if (!program)
    throw Error(what + ": needs the ffmpeg program, which is not on PATH (expected Debian's package: apt-get install "
                       "ffmpeg; or a .png video, which prt writes itself)");
  // ffmpeg -encoders lists one encoder a line: " V....D libx264  libx264 H.264 / AVC ...".
  const ProgramResult encoders = RunProgram({*program, "-hide_banner", "-encoders"});
  if (encoders.out.find(std::string(" ") + FfmpegEncoderName(codec) + " ") == std::string::npos)
    throw Error(what + ": " + *program + " has no " + FfmpegEncoderName(codec) +
                " encoder (expected Debian's ffmpeg package, which has it)");
  return *program;
}

std::vector<std::string> FfmpegArguments(const std::string& program, FfmpegCodec codec, int width, int height,
                                         double fps, const std::string& path) {
  std::vector<std::string> a = {program, "-hide_banner", "-nostats", "-loglevel", "error", "-y",
                                // input: raw 8-bit sRGB frames on standard input
                                "-f", "rawvideo", "-pix_fmt", "rgb24",
                                "-video_size", std::to_string(width) + "x" + std::to_string(height),
                                "-framerate", Formatted("%.17g", fps), "-i", "pipe:0", "-an",
                                // RGB to limited-range 4:2:0 by the BT.709 matrix, and tagged so
                                "-vf", "scale=out_color_matrix=bt709:out_range=tv,format=yuv420p",
                                "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "bt709",
                                "-color_range", "tv", "-threads", kEncoderThreads};
  a.insert(a.end(), {"-c:v", FfmpegEncoderName(codec)});
  if (codec == FfmpegCodec::kH264Mp4) {
    for (const char* s : {"-preset", "medium", "-crf", "18", "-movflags", "+faststart", "-f", "mp4"}) a.emplace_back(s);
  } else {
    for (const char* s : {"-crf", "30", "-b:v", "0", "-deadline", "good", "-cpu-used", "2", "-row-mt", "1", "-f", "webm"})
      a.emplace_back(s);
  }
  // The same bytes from the same frames: no encoder version string, no random container IDs
  // (WebM's segment UID), no creation time.
  for (const char* s : {"-fflags", "+bitexact", "-flags:v", "+bitexact", "-map_metadata", "-1"}) a.emplace_back(s);
  a.push_back(path);
  return a;
}

FfmpegEncoder::FfmpegEncoder(const std::string& program, FfmpegCodec codec, const std::string& path, std::string name,
                             int width, int height, double fps)
    : name_(std::move(name)), log_file_(LogPath()), width_(width), height_(height) {
  AtomicFile::RemoveStale(LogPath());
  try {
    log_file_.Write({});
    log_ = log_file_.temp_path();
  } catch (const Error&) {
    log_ = "/dev/null";  // no place for a log: a failure is reported without ffmpeg's words
  }
  child_ = std::make_unique<ChildProcess>(FfmpegArguments(program, codec, width, height, fps, path), log_);
}

FfmpegEncoder::~FfmpegEncoder() = default;  // ffmpeg killed if it still runs, then its log removed

void FfmpegEncoder::Fail(const std::string& what) const {
  const std::string said = LastLine(log_);
  throw Error(name_ + ": " + what + (said.empty() ? "" : ": " + said) + " (expected ffmpeg to encode the frames)");
}

void FfmpegEncoder::AddFrame(std::string_view rgb) {
  if (rgb.size() != 3 * std::size_t(width_) * std::size_t(height_))
    throw Error(name_ + ": a frame of another size (internal)");
  if (!child_->Write(rgb)) {
    const int code = child_->Wait();
    Fail("ffmpeg stopped reading frames (exit " + std::to_string(code) + ")");
  }
}

void FfmpegEncoder::Finish() {
  const int code = child_->Wait();
  if (code != 0) Fail("ffmpeg failed (exit " + std::to_string(code) + ")");
}

}  // namespace prt
