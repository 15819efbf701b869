#pragma once
/// \file
/// The frames of a render loop handed to encoder threads, in slots the writer owns and reuses:
/// after the first frames no stage allocates, so no frame touches fresh memory (on a virtual
/// machine each fresh 4 KiB page costs a fault of microseconds, and a 1080p frame's buffers are
/// thousands of pages).
///
/// There are `workers` persistent threads and workers + 1 slots, each an 8-bit image that the
/// loop tone maps into and a PngEncoder (io/png_encoder.h) with its buffers. Frame i goes to
/// slot i mod (workers + 1); Next(i) first waits for the frame that slot held, i - workers - 1,
/// to be written, and only then hands it to the video. Frames therefore reach the video in
/// order on the loop's thread, each only once its PNG exists, and the files' bytes never depend
/// on how many frames were in flight. Encoding frame i overlaps drawing the next ones.

#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/image.h"
#include "io/png_encoder.h"
#include "video/video_writer.h"

namespace prt {

class FrameWriter {
 public:
  /// `workers` encoder threads (at least 1); `video` (may be null) gets every frame in order.
  FrameWriter(int workers, VideoWriter* video);
  /// Stops the threads once their current frame is done; errors not collected are dropped.
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  /// The image to fill for frame `index` (0, 1, 2, ... in order). Waits for the frame its slot
  /// held to be written, adding the seconds to `*waited`, hands that frame to the video and
  /// rethrows its error.
  Image8& Next(int index, double* waited = nullptr);
  /// Encodes the image filled since Next on a worker thread and writes it to `path` atomically
  /// (core/atomic_file.h); an empty path only encodes (benchmarks).
  void Submit(const std::string& path);
  /// Waits for every frame, hands the rest to the video in order and rethrows the first error.
  /// Returns the seconds spent waiting.
  double Finish();

 private:
  struct Slot {
    Image8 image;
    PngEncoder encoder;
    std::string path;
    int index = -1;      // the frame it holds; -1: none yet
    bool done = true;    // encoded and written (or failed)
    std::exception_ptr error;
  };
  void Work();
  // Waits for `slot`'s frame, hands it to the video, rethrows its error; adds to *waited.
  void Retire(Slot& slot, double* waited);

  VideoWriter* video_;
  std::vector<std::unique_ptr<Slot>> slots_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int submitted_ = 0;  // frames handed to the workers
  int taken_ = 0;      // frames a worker has started
  int filling_ = -1;   // the frame between Next and Submit
  bool stop_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace prt
