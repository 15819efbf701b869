#pragma once
/// \file
/// One page's stream of frames, as remote renderers push them (VNC's framebuffer updates,
/// ParaViewWeb's image delivery): the page says what it wants to see (an input, numbered), and
/// the stream's thread draws the newest input and pushes the frame on one persistent response,
/// drawing the next while the last travels and is painted. What decides each step:
///
///   draw      the newest input when no frame has answered it yet: at interactive quality
///             (FrameRequest::interactive), what a moving light or camera needs fast;
///   still     once the input has stayed the same kStillDelay, its frame at still quality, the
///             bytes `prt render` writes; drawn once, and not when a newer input came meanwhile;
///   window    at most kFramesInFlight frames sent and not yet shown by the page (it says which
///             it has shown): a page that paints slower than the server draws gets the newest
///             input's frame next, never a queue of old ones, and one that stops reading stops
///             the drawing for it, not for anyone else;
///   silence   a page that has said nothing (no input, no frame shown) for kSilentPage while its
///             window is full has stopped or gone (a frozen tab, a machine that vanished without
///             closing): its stream ends, freeing its thread and its place among kMaxStreams,
///             even when its frames are small enough to wait in the sockets' buffers;
///   order     frames are numbered in the order drawn and sent on one connection: they arrive
///             in that order.
///
/// The drawing and the sending happen on the thread serving the stream (FrameStream::Next);
/// inputs and acknowledgements come from the threads serving the page's POSTs.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>

#include "view/frame_request.h"

namespace prt {

/// How long an input stays unchanged before its still frame is drawn: longer than the gaps
/// between a drag's moves (16 ms at a display's rate), short enough to feel at once.
inline constexpr std::chrono::milliseconds kStillDelay{120};
/// Frames sent and not yet shown: one travelling or being painted while the next is drawn.
inline constexpr std::uint64_t kFramesInFlight = 2;
/// The longest a stream stays silent: then it sends a keep-alive record, so that a page that has
/// gone is noticed (the write fails) and its thread freed.
inline constexpr std::chrono::milliseconds kKeepAliveAfter{2000};
/// How long a page may leave its full window unacknowledged before its stream ends.
inline constexpr std::chrono::milliseconds kSilentPage{30000};

class FrameStream {
 public:
  /// A frame to draw: the request and the input it answers.
  struct Job {
    FrameRequest request;
    std::uint64_t input = 0;
    std::uint64_t frame = 0;  ///< this frame's number in the stream, from 1
  };
  /// What Next found: a job, nothing for kKeepAliveAfter (send a keep-alive), or the stream stopped.
  enum class Step { kDraw, kKeepAlive, kStopped };

  /// The stream starts with `request` as input number `input`; `silent_page` is kSilentPage but
  /// for tests.
  FrameStream(FrameRequest request, std::uint64_t input, std::chrono::milliseconds silent_page = kSilentPage);

  /// The page's newest input; an input numbered no higher than the newest seen is ignored (a POST
  /// overtaken by a later one).
  void Want(const FrameRequest& request, std::uint64_t input);
  /// The page has shown frame `frame` (and every frame before it).
  void Shown(std::uint64_t frame);
  /// Ends the stream: Next returns kStopped at once, now and later.
  void Stop();
  bool Stopped() const;

  /// Waits until there is a frame to draw (into `job`), kKeepAliveAfter has passed, or the stream is
  /// stopped (by Stop, or by the page's silence). The job's frame counts as sent.
  Step Next(Job& job);

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  FrameRequest wanted_;
  std::uint64_t input_ = 0;               ///< the newest input's number
  std::chrono::steady_clock::time_point since_;  ///< when it came
  std::chrono::steady_clock::time_point heard_;  ///< when the page last said anything
  std::chrono::milliseconds silent_page_;
  std::uint64_t answered_ = 0;            ///< the input the last frame drawn answers
  bool answered_once_ = false;
  bool still_drawn_ = false;              ///< the last frame drawn was input_'s still frame
  std::uint64_t sent_ = 0, shown_ = 0;    ///< frames numbered from 1
  bool stopped_ = false;
};

}  // namespace prt
