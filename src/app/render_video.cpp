#include "app/render_video.h"

#include <chrono>
#include <filesystem>

#include "app/render_args.h"
#include "core/error.h"
#include "core/log.h"  // SecondsSince
#include "core/text.h"
#include "video/apng_writer.h"
#include "video/ffmpeg_encoder.h"

namespace prt {
namespace fs = std::filesystem;
namespace {

/// True if `file` names an output the run writes itself: a frame or a file of prt's own in the
/// output folder, the transport cache, the --vertex-radiance file.
bool IsRunOutputName(const std::string& file, const RenderJobOptions& o) {
  return IsFolderOwnName(file, o) ||
         (!o.vertex_radiance.empty() && ResolvedPath(file) == ResolvedPath(o.vertex_radiance));
}

}  // namespace

void ReadVideoOptions(Args& args, RenderJobOptions& job, const RenderJobOptions& job_defaults) {
  VideoOptions& o = job.video;
  const VideoOptions& d = job_defaults.video;
  const RenderOptions& draw = job.draw;
  if (!args.Accepts("--video")) return;
  const bool has_video = args.Has("--video");
  if (args.Has("--fps") && !has_video) args.Fail("--fps: sets the rate of --video, which is not given (expected --video FILE)");
  if (!has_video) return;
  o.path = args.String("--video", d.path);
  const std::string& v = o.path;
  if (HasControlCharacter(v))
    args.Fail("--video: the name has a control character (a newline, a tab) (expected a plain file name)");
  const auto format = VideoFormatOf(v);
  if (!format)
    args.Fail("--video: '" + v + "' has no video extension (expected .png or .apng for an animated PNG, .mp4 or .webm "
              "through ffmpeg)");
  o.fps = args.Double("--fps", d.fps, 0.1, 240.0);
  if (*format == VideoFormat::kApng && o.fps > kApngMaxFps)
    args.Fail("--fps: " + Formatted("%g", o.fps) + " is too fast for an animated PNG (expected at most " +
              Formatted("%g", kApngMaxFps) + ": browsers play frames of 10 ms or less at 10 frames per second)");
  if (*format == VideoFormat::kMp4 && (draw.width % 2 != 0 || draw.height % 2 != 0))
    args.Fail("--video: H.264 in '" + v + "' needs an even frame size, not " + std::to_string(draw.width) + "x" +
              std::to_string(draw.height) + " (expected even --size values, or a .png or .webm video)");
  if (IsRunOutputName(v, job))
    args.Fail("--video: '" + v + "' is the name of one of the run's own outputs (a frame, the transport cache or the "
              "--vertex-radiance file; expected another name, such as turn.png)");
  std::error_code ec;
  if (fs::is_directory(v, ec)) throw Error(v + ": is a folder (expected a file name for --video)");
  if (*format != VideoFormat::kApng)
    o.ffmpeg = FindFfmpeg(*format == VideoFormat::kMp4 ? FfmpegCodec::kH264Mp4 : FfmpegCodec::kVp9Webm, "--video " + v);
}

RenderVideo::RenderVideo(const VideoOptions& o, const RenderOptions& draw, OutputFolder& folder) : path_(o.path) {
  if (o.path.empty()) return;
  VideoSpec spec;
  spec.format = *VideoFormatOf(o.path);
  spec.width = draw.width, spec.height = draw.height, spec.frames = draw.frames, spec.fps = o.fps;
  spec.ffmpeg = o.ffmpeg;
  std::string write_path;
  if (LiesIn(o.path, folder.dir())) {
    write_path = folder.Output(fs::path(o.path).filename().string());
  } else {
    outside_ = std::make_unique<SingleFileOutput>(o.path);
    write_path = outside_->temp_path();
  }
  writer_ = std::make_unique<VideoWriter>(spec, write_path, o.path);
}

RenderVideo::~RenderVideo() = default;

void RenderVideo::Commit() {
  if (outside_) outside_->Commit();
}

std::string RenderVideo::Finish() {
  if (!writer_) return "";
  const auto t0 = std::chrono::steady_clock::now();
  writer_->Finish();
  const VideoSpec& s = writer_->spec();
  const double seconds = SecondsSince(t0);
  return Formatted("video: %s, %s of %d frames of %dx%d at %g fps (%.2f s%s) [%.3f s after the last frame]",
                   path_.c_str(), VideoFormatName(s.format), s.frames, s.width, s.height, s.fps, s.frames / s.fps,
                   s.format == VideoFormat::kApng ? ", looping" : "", seconds);
}

}  // namespace prt
