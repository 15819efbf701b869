#include "view/frame_stream.h"

#include <algorithm>

namespace prt {

FrameStream::FrameStream(FrameRequest request, std::uint64_t input, std::chrono::milliseconds silent_page)
    : wanted_(std::move(request)),
      input_(input),
      since_(std::chrono::steady_clock::now()),
      heard_(since_),
      silent_page_(silent_page) {}

void FrameStream::Want(const FrameRequest& request, std::uint64_t input) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    heard_ = std::chrono::steady_clock::now();
    if (input <= input_) return;
    wanted_ = request;
    input_ = input;
    since_ = std::chrono::steady_clock::now();
  }
  changed_.notify_all();
}

void FrameStream::Shown(std::uint64_t frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    heard_ = std::chrono::steady_clock::now();
    shown_ = std::max(shown_, std::min(frame, sent_));  // a frame not sent yet cannot have been shown
  }
  changed_.notify_all();
}

void FrameStream::Stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
  }
  changed_.notify_all();
}

bool FrameStream::Stopped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stopped_;
}

FrameStream::Step FrameStream::Next(Job& job) {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto give_up = std::chrono::steady_clock::now() + kKeepAliveAfter;
  for (;;) {
    if (stopped_) return Step::kStopped;
    const auto now = std::chrono::steady_clock::now();
    const bool room = sent_ - shown_ < kFramesInFlight;
    const bool fresh = !answered_once_ || answered_ != input_;
    const auto still_at = since_ + kStillDelay;
    const bool still_due = !fresh && !still_drawn_ && now >= still_at;
    if (room && (fresh || still_due)) {
      job.request = wanted_;
      job.request.interactive = fresh;
      job.input = input_;
      job.frame = ++sent_;
      answered_ = input_;
      answered_once_ = true;
      still_drawn_ = !fresh;
      return Step::kDraw;
    }
    if (!room && now >= heard_ + silent_page_) {  // the page has stopped or gone
      stopped_ = true;
      return Step::kStopped;
    }
    if (now >= give_up) return Step::kKeepAlive;
    // Woken by an input, an acknowledgement or Stop; else when the still frame falls due, or
    // when the page's silence would end the stream.
    const bool waiting_for_still = room && !fresh && !still_drawn_;
    auto until = waiting_for_still ? std::min(still_at, give_up) : give_up;
    if (!room) until = std::min(until, heard_ + silent_page_);
    changed_.wait_until(lock, until);
  }
}

}  // namespace prt
