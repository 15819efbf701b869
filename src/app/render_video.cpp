#include "app/render_video.h"

#include <chrono>
#include <filesystem>

#include "core/error.h"
#include "core/log.h"  // SecondsSince
#include "core/text.h"
#include "video/apng_writer.h"
#include "video/ffmpeg_encoder.h"

namespace prt {
namespace fs = std::filesystem;
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
