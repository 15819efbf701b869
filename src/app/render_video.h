#pragma once
/// \file
/// The video of a run (`--video FILE` and `--fps F` of render and demo, read by render_args.h), written beside the PNG frames (video/video_writer.h) and put in place
/// only when the run succeeds, like every output (docs/CLI.md, "Outputs").
///
/// A video inside the output folder is one of the folder's outputs: staged with the frames and
/// listed, so a later run without it removes it. A video elsewhere is written under a temporary
/// name beside it and renamed when complete.

#include <memory>
#include <string>

#include "core/output_folder.h"
#include "render/render_options.h"
#include "video/video_writer.h"

namespace prt {

/// The video of a run: where (empty: none), at what rate, and the ffmpeg program for .mp4 and
/// .webm (found when the options are read).
struct VideoOptions {
  std::string path;
  double fps = 30.0;
  std::string ffmpeg;
};

class RenderVideo {
 public:
  /// The video `video` of the frames `draw` describes into `folder`; nothing when video.path is
  /// empty. Creates the video's folder if missing. Throws Error if it cannot be started.
  RenderVideo(const VideoOptions& video, const RenderOptions& draw, OutputFolder& folder);
  ~RenderVideo();

  /// The writer the frame loop hands each frame to, or null without --video.
  VideoWriter* writer() { return writer_.get(); }

  /// After every frame: completes the video. Returns the run summary's line ("" without --video).
  std::string Finish();
  /// Once the output folder is finished: outside it, renames the video into place (inside it,
  /// the folder's Finish moved it). Until then a failure leaves the earlier video as it was.
  void Commit();

 private:
  std::string path_;                           ///< the user's name
  std::unique_ptr<SingleFileOutput> outside_;  ///< a video outside the folder
  std::unique_ptr<VideoWriter> writer_;
};

}  // namespace prt
