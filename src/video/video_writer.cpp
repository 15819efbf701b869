#include "video/video_writer.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/name_table.h"
#include "video/apng_writer.h"
#include "video/ffmpeg_encoder.h"

namespace prt {
namespace {

/// The extensions of each format, in any case (VideoFormatOf lowers them first).
constexpr auto kExtensions = MakeNameTable<VideoFormat>({
    {VideoFormat::kApng, "png"},
    {VideoFormat::kApng, "apng"},
    {VideoFormat::kMp4, "mp4"},
    {VideoFormat::kWebm, "webm"},
});
static_assert(kExtensions.Distinct());

/// How the run summary names each format.
constexpr auto kFormatNames = MakeNameTable<VideoFormat>({
    {VideoFormat::kApng, "animated PNG"},
    {VideoFormat::kMp4, "H.264 MP4 (ffmpeg)"},
    {VideoFormat::kWebm, "VP9 WebM (ffmpeg)"},
});
static_assert(kFormatNames.Distinct());

}  // namespace

std::optional<VideoFormat> VideoFormatOf(const std::string& path) {
  const auto dot = path.rfind('.');
  const auto slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return kExtensions.Find(ext);
}

const char* VideoFormatName(VideoFormat format) { return kFormatNames.Name(format); }

VideoWriter::VideoWriter(const VideoSpec& spec, const std::string& path, std::string name)
    : spec_(spec), name_(std::move(name)) {
  if (spec.format == VideoFormat::kApng) {
    apng_ = std::make_unique<ApngWriter>(path, name_, spec.frames, spec.fps);
  } else {
    const FfmpegCodec codec = spec.format == VideoFormat::kMp4 ? FfmpegCodec::kH264Mp4 : FfmpegCodec::kVp9Webm;
    ffmpeg_ = std::make_unique<FfmpegEncoder>(spec.ffmpeg, codec, path, name_, spec.width, spec.height, spec.fps);
  }
}

VideoWriter::~VideoWriter() = default;

std::string_view VideoWriter::EncoderInput(const Image8& image, const std::string& png) const {
  if (apng_) return png;
  return {reinterpret_cast<const char*>(image.rgb.data()), image.rgb.size()};
}

void VideoWriter::Append(std::string_view input) {
  if (apng_) apng_->AddFrame(input);
  else ffmpeg_->AddFrame(input);
  ++next_;
}

void VideoWriter::AddFrame(int index, const Image8& image, const std::string& png) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!failed_.empty()) throw Error(failed_);
  if (index < next_ || waiting_.count(index)) throw Error(name_ + ": frame " + std::to_string(index) + " given twice (internal)");
  try {
    if (index != next_) {
      // An earlier frame is still being encoded.
      waiting_.emplace(index, EncoderInput(image, png));
      return;
    }
    Append(EncoderInput(image, png));
    // Then every waiting frame that now follows on.
    for (auto w = waiting_.find(next_); w != waiting_.end(); w = waiting_.find(next_)) {
      Append(w->second);
      waiting_.erase(w);
    }
  } catch (const Error& e) {
    failed_ = e.what();
    throw;
  }
}

void VideoWriter::Finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!failed_.empty()) throw Error(failed_);
  if (next_ != spec_.frames)
    throw Error(name_ + ": " + std::to_string(next_) + " of " + std::to_string(spec_.frames) + " frames arrived (internal)");
  if (apng_) apng_->Finish();
  else ffmpeg_->Finish();
}

}  // namespace prt
