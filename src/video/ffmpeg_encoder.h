#pragma once
/// \file
/// MP4 (H.264) and WebM (VP9) through Debian's `ffmpeg` program: prt starts it as a child
/// process (core/child_process.h) and pipes it the tone-mapped 8-bit sRGB frames, in order, as
/// raw RGB. prt links no codec library; without the program, --video .mp4/.webm is refused
/// before any work with the package's name.
///
/// The encoding is the one slides and web pages play everywhere: 4:2:0 chroma (yuv420p), limited
/// range, the BT.709 matrix (the conversion from RGB uses it and the file says so; players
/// assume 709 for HD and would shift colours if the file were converted by BT.601 instead),
/// H.264 at CRF 18 with the index at the front of the file (+faststart), or VP9 at CRF 30.
/// H.264 4:2:0 needs even sizes, so an odd --size is refused for .mp4. The encoder runs with a
/// fixed thread count, not one taken from prt's --threads; an .mp4 made with --threads 1 and 2
/// is the same file (tests/app/test_video_cli.cpp, on one machine). Other machines and ffmpeg
/// versions were not compared: the PNG frames stay the reference.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/atomic_file.h"
#include "core/child_process.h"

namespace prt {

enum class FfmpegCodec { kH264Mp4, kVp9Webm };

/// The ffmpeg encoder each codec needs (libx264, libvpx-vp9).
const char* FfmpegEncoderName(FfmpegCodec codec);

/// The ffmpeg program to use for `codec`: found on $PATH, and listing its encoder. Throws Error
/// starting with `what` (the option and file) when it is missing, naming the Debian package,
/// or lacks the encoder.
std::string FindFfmpeg(FfmpegCodec codec, const std::string& what);

/// ffmpeg's command line: raw RGB frames of `width` x `height` at `fps` from standard input,
/// encoded as `codec` into `path`.
std::vector<std::string> FfmpegArguments(const std::string& program, FfmpegCodec codec, int width, int height,
                                         double fps, const std::string& path);

class FfmpegEncoder {
 public:
  /// Starts ffmpeg writing `path` (a temporary or staged name; `name` is the user's, for
  /// messages). Throws Error if it cannot start.
  FfmpegEncoder(const std::string& program, FfmpegCodec codec, const std::string& path, std::string name,
                int width, int height, double fps);
  /// Stops ffmpeg if Finish() was not called (a failed run).
  ~FfmpegEncoder();
  FfmpegEncoder(const FfmpegEncoder&) = delete;
  FfmpegEncoder& operator=(const FfmpegEncoder&) = delete;

  /// Pipes the next frame: width x height 8-bit RGB, row by row. Throws Error with ffmpeg's last
  /// message if it stopped.
  void AddFrame(std::string_view rgb);
  /// Ends the input and waits for ffmpeg. Throws Error with its last message unless it exits 0.
  void Finish();

 private:
  [[noreturn]] void Fail(const std::string& what) const;

  std::string name_;
  AtomicFile log_file_;  ///< ffmpeg's messages, never committed: removed at the end or by a signal
  std::string log_;      ///< log_file_'s temporary name, or /dev/null
  int width_, height_;
  std::unique_ptr<ChildProcess> child_;  ///< last: destroyed (ffmpeg killed) before its log
};

}  // namespace prt
