#pragma once
/// \file
/// Animated PNG (APNG 1.0, the extension every current browser plays; W3C PNG 3rd edition,
/// sections 11.3.6 acTL, fcTL and fdAT), written frame by frame as the frames are rendered.
///
/// An APNG is a PNG whose first image is also the first frame, so a viewer without APNG
/// support still shows frame 0. After IHDR come
///     acTL  number of frames, number of plays (0: loop for ever)
///     fcTL  frame 0: sequence number, size, offset (0, 0), delay, dispose NONE, blend SOURCE
///     IDAT  frame 0's image data, exactly as in a PNG
///     fcTL, fdAT ...  each later frame: its fdAT holds a sequence number, then the image data
///     IEND
/// with the fcTL and fdAT chunks numbered 0, 1, 2, ... in file order. Every frame covers the
/// whole image and replaces it (no blending), so each frame of the file is one rendered frame.
///
/// The image data of a frame is the zlib stream of its PNG file: the writer takes the PNG that
/// io/png_io.h encoded for frame_NNNN.png and moves its IDAT data into the animation, with no
/// second compression. Decoded, each frame of the animation is therefore the PNG file's pixels.

#include <cstdint>
#include <string>
#include <string_view>

namespace prt {

/// A frame's display time as the APNG stores it, num / den seconds, each term 1..65535.
struct ApngDelay {
  std::uint16_t num = 1, den = 30;
};

/// The delay of one frame at `fps` frames per second: the fraction num / den closest to 1 / fps
/// with both terms in 1..65535 (the smallest den among equally close ones). Exact for every
/// fps whose inverse has such a fraction: 30 -> 1/30, 29.97 -> 100/2997, 0.5 -> 2/1.
ApngDelay ApngDelayOf(double fps);

/// The highest frame rate of an animated PNG. Browsers are documented to play frames of 10 ms
/// or less as if they lasted 100 ms (a rule inherited from GIF; not measured here), so at
/// 100 fps and above an animation would play ten times too slowly; 90 keeps frames at 11 ms or
/// more.
constexpr double kApngMaxFps = 90.0;

class ApngWriter {
 public:
  /// Opens `path` for writing (a temporary or staged name; `name` is the file the user named,
  /// for messages) for `frames` frames shown at `fps`. Throws Error if it cannot be created.
  ApngWriter(const std::string& path, std::string name, int frames, double fps);
  ~ApngWriter();
  ApngWriter(const ApngWriter&) = delete;
  ApngWriter& operator=(const ApngWriter&) = delete;

  /// Appends the next frame, given as a complete PNG file (io/png_io.h's EncodePng); every frame
  /// must have the first one's IHDR (size and pixel format). Throws Error on a write error, on
  /// a PNG that does not parse, a frame unlike the first, or one frame too many.
  void AddFrame(std::string_view png);

  /// Writes IEND and closes the file. Throws Error on a write error or if fewer frames than
  /// announced were added.
  void Finish();

 private:
  void Write(const std::string& bytes);

  std::string path_, name_;
  int frames_ = 0, added_ = 0;
  ApngDelay delay_;
  std::uint32_t sequence_ = 0;  ///< the next fcTL / fdAT sequence number
  std::string ihdr_;            ///< the first frame's IHDR data
  int fd_ = -1;
};

}  // namespace prt
