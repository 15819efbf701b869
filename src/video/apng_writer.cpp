#include "video/apng_writer.h"

#include <cerrno>
#include <cmath>

#include <fcntl.h>
#include <unistd.h>

#include "core/atomic_file.h"  // WriteAll, WriteProblem
#include "core/error.h"
#include "io/png_chunks.h"

namespace prt {
namespace {

constexpr std::uint32_t kMaxDelayTerm = 65535;
/// Image data is split into chunks of at most this many bytes (a chunk may hold 2^31 - 1).
constexpr std::size_t kMaxChunkData = std::size_t(1) << 30;

void AppendU16(std::string& out, std::uint16_t value) {
  out.push_back(char(value >> 8));
  out.push_back(char(value & 0xff));
}

}  // namespace

ApngDelay ApngDelayOf(double fps) {
  // Every denominator in turn, with its nearest numerator: 65535 candidates, exact search.
  const double target = 1.0 / fps;
  ApngDelay best{1, 1};
  double best_error = std::abs(1.0 - target);
  for (std::uint32_t den = 1; den <= kMaxDelayTerm; ++den) {
    const double num = std::round(target * den);
    if (num < 1.0 || num > kMaxDelayTerm) continue;
    const double error = std::abs(num / den - target);
    if (error < best_error) best_error = error, best = {std::uint16_t(num), std::uint16_t(den)};
  }
  return best;
}

ApngWriter::ApngWriter(const std::string& path, std::string name, int frames, double fps)
    : path_(path), name_(std::move(name)), frames_(frames), delay_(ApngDelayOf(fps)) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error(name_ + ": cannot write (" + WriteProblem(name_, errno) + ")");
}

ApngWriter::~ApngWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void ApngWriter::Write(const std::string& bytes) {
  if (const int error = WriteAll(fd_, bytes)) throw Error(name_ + ": cannot write (" + WriteProblem(name_, error) + ")");
}

void ApngWriter::AddFrame(std::string_view png) {
  if (added_ >= frames_)
    throw Error(name_ + ": frame " + std::to_string(added_) + " is one too many (expected " + std::to_string(frames_) + ")");
  const PngImageData image = ExtractPngImageData(png, name_ + " frame " + std::to_string(added_));
  std::string out;
  if (added_ == 0) {
    // Signature, IHDR, then acTL before any image data.
    ihdr_ = image.ihdr;
    out.append(kPngSignatureBytes, 8);
    AppendPngChunk(out, "IHDR", ihdr_);
    std::string actl;
    AppendU32(actl, static_cast<std::uint32_t>(frames_));
    AppendU32(actl, 0);  // plays: 0 = for ever
    AppendPngChunk(out, "acTL", actl);
  } else if (image.ihdr != ihdr_) {
    throw Error(name_ + ": frame " + std::to_string(added_) + " differs from frame 0 in size or pixel format (expected " +
                std::to_string(ReadU32(ihdr_.data())) + "x" + std::to_string(ReadU32(ihdr_.data() + 4)) + ")");
  }
  // fcTL: the frame covers the whole image, shows for the delay, and replaces what was there.
  std::string fctl;
  AppendU32(fctl, sequence_++);
  AppendU32(fctl, image.width);
  AppendU32(fctl, image.height);
  AppendU32(fctl, 0);  // x offset
  AppendU32(fctl, 0);  // y offset
  AppendU16(fctl, delay_.num);
  AppendU16(fctl, delay_.den);
  fctl.push_back(0);  // dispose_op NONE: the next frame covers everything anyway
  fctl.push_back(0);  // blend_op SOURCE: replace, no alpha compositing
  AppendPngChunk(out, "fcTL", fctl);
  // The zlib stream: IDAT for frame 0 (the default image), fdAT with a sequence number after.
  for (std::size_t at = 0; at < image.idat.size(); at += kMaxChunkData) {
    const std::string_view piece = std::string_view(image.idat).substr(at, kMaxChunkData);
    if (added_ == 0) {
      AppendPngChunk(out, "IDAT", piece);
    } else {
      std::string fdat;
      AppendU32(fdat, sequence_++);
      fdat.append(piece);
      AppendPngChunk(out, "fdAT", fdat);
    }
  }
  Write(out);
  ++added_;
}

void ApngWriter::Finish() {
  if (added_ != frames_)
    throw Error(name_ + ": " + std::to_string(added_) + " frames written (expected " + std::to_string(frames_) + ")");
  std::string out;
  AppendPngChunk(out, "IEND", {});
  Write(out);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw Error(name_ + ": cannot write (" + WriteProblem(name_, errno) + ")");
}

}  // namespace prt
