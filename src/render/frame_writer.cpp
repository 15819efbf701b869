#include "render/frame_writer.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "core/atomic_file.h"
#include "core/error.h"

namespace prt {

FrameWriter::FrameWriter(int workers, VideoWriter* video) : video_(video) {
  workers = std::max(1, workers);
  for (int i = 0; i <= workers; ++i) slots_.push_back(std::make_unique<Slot>());
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { Work(); });
}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void FrameWriter::Work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stop_ || taken_ < submitted_; });
    if (stop_) return;
    Slot& slot = *slots_[static_cast<std::size_t>(taken_++) % slots_.size()];
    lock.unlock();
    std::exception_ptr error;
    try {
      const std::string& png = slot.encoder.Encode(slot.image);
      if (!slot.path.empty()) WriteFileAtomic(slot.path, png);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    slot.error = error;
    slot.done = true;
    changed_.notify_all();
  }
}

void FrameWriter::Retire(Slot& slot, double* waited) {
  const auto t0 = std::chrono::steady_clock::now();
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&slot] { return slot.done; });
  }
  if (waited) *waited += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (slot.index < 0) return;
  const int index = slot.index;
  slot.index = -1;
  if (slot.error) std::rethrow_exception(std::exchange(slot.error, nullptr));
  // The encoder still holds the frame's PNG: the slot is not reused before this returns.
  if (video_) video_->AddFrame(index, slot.image, slot.encoder.last());
}

Image8& FrameWriter::Next(int index, double* waited) {
  if (index != submitted_ || filling_ >= 0) throw Error("frame writer: frame " + std::to_string(index) + " out of order (internal)");
  Slot& slot = *slots_[static_cast<std::size_t>(index) % slots_.size()];
  Retire(slot, waited);
  filling_ = index;
  return slot.image;
}

void FrameWriter::Submit(const std::string& path) {
  if (filling_ < 0) throw Error("frame writer: Submit without Next (internal)");
  Slot& slot = *slots_[static_cast<std::size_t>(filling_) % slots_.size()];
  {
    std::lock_guard<std::mutex> lock(mutex_);
    slot.path = path;
    slot.index = filling_;
    slot.done = false;
    filling_ = -1;
    ++submitted_;
  }
  changed_.notify_all();
}

double FrameWriter::Finish() {
  double waited = 0.0;
  const int slots = static_cast<int>(slots_.size());
  for (int i = std::max(0, submitted_ - slots); i < submitted_; ++i)
    Retire(*slots_[static_cast<std::size_t>(i) % slots_.size()], &waited);
  return waited;
}

}  // namespace prt
