#pragma once
/// \file
/// The frames of a render as one video file (`--video FILE`): an animated PNG that prt writes
/// itself (video/apng_writer.h), or MP4 / WebM through ffmpeg (video/ffmpeg_encoder.h), chosen
/// by the file's extension.
///
/// Frames are encoded on several threads and finish in any order; the writer takes each one as
/// it finishes and appends them to the file strictly in frame order, holding a finished frame
/// (only the bytes its encoder takes: the PNG file, or the raw RGB for ffmpeg) until the frames
/// before it have arrived, so at most one per frame in flight. The file's bytes therefore
/// depend on the frames alone, not on --threads.

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "core/image.h"

namespace prt {

enum class VideoFormat { kApng, kMp4, kWebm };

/// The format the file name asks for by its extension, in any case: .png or .apng, .mp4, .webm;
/// empty for any other name.
std::optional<VideoFormat> VideoFormatOf(const std::string& path);

/// How the run summary names the format ("animated PNG", "H.264 MP4 (ffmpeg)", ...).
const char* VideoFormatName(VideoFormat format);

/// What to write: the format, the frames' size and count, and their rate.
struct VideoSpec {
  VideoFormat format = VideoFormat::kApng;
  int width = 0, height = 0, frames = 0;
  double fps = 30.0;
  std::string ffmpeg;  ///< the program, for kMp4 and kWebm (FindFfmpeg)
};

class ApngWriter;
class FfmpegEncoder;

class VideoWriter {
 public:
  /// Starts the video at `path` (a temporary or staged name; `name` is the user's, for
  /// messages). Throws Error if it cannot be created or ffmpeg cannot start.
  VideoWriter(const VideoSpec& spec, const std::string& path, std::string name);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Frame `index` (0-based; from any thread, in any order, each once): the tone-mapped image
  /// and its PNG file (EncodePng). Appended once every earlier frame has been. Throws Error if
  /// appending fails; the writer then refuses every later frame with the same error.
  void AddFrame(int index, const Image8& image, const std::string& png);

  /// After the last frame: completes the file. Throws Error if a frame is missing or the encoder
  /// failed.
  void Finish();

  const VideoSpec& spec() const { return spec_; }

 private:
  /// The bytes of `image` the encoder takes: its PNG file for an animated PNG, else raw RGB.
  std::string_view EncoderInput(const Image8& image, const std::string& png) const;
  /// Hands the next frame's encoder input to the encoder.
  void Append(std::string_view input);

  VideoSpec spec_;
  std::string name_;
  std::unique_ptr<ApngWriter> apng_;
  std::unique_ptr<FfmpegEncoder> ffmpeg_;
  std::mutex mutex_;
  int next_ = 0;  ///< the next frame to append
  /// Finished frames waiting for an earlier one: their encoder input.
  std::map<int, std::string> waiting_;
  std::string failed_;  ///< the first append's error, once one failed
};

}  // namespace prt
