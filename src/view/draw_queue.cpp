#include "view/draw_queue.h"

#include <string>

namespace prt {

void DrawQueue::Turn::Release() {
  if (queue_ != nullptr) queue_->EndTurn();
  queue_ = nullptr;
}

DrawQueue::Turn DrawQueue::Page() {
  std::unique_lock<std::mutex> lock(mutex_);
  ++pages_waiting_;
  changed_.wait(lock, [this] { return stopped_ || !drawing_; });
  --pages_waiting_;
  if (stopped_) throw Busy("busy: the server is stopping");
  drawing_ = true;
  return Turn(this);
}

DrawQueue::Turn DrawQueue::Request(std::size_t bytes, std::shared_ptr<void>* hold) {
  // Made before the turn is taken, handed over after the lock is left: nothing can throw with
  // the turn taken, and a reservation `*hold` held already is released outside the lock.
  auto reservation = std::make_shared<Reservation>(this, 0);
  std::unique_lock<std::mutex> lock(mutex_);
  if (stopped_) throw Busy("busy: the server is stopping");
  if (next_ticket_ - first_ticket_ >= waiting_requests_)
    throw Busy("busy: " + std::to_string(next_ticket_ - first_ticket_) +
               " frames are waiting to be drawn (ask again in a moment)");
  const std::uint64_t ticket = next_ticket_++;
  changed_.wait(lock, [&] {
    return stopped_ || (ticket == first_ticket_ && !drawing_ && pages_waiting_ == 0 &&
                        (reserved_ == 0 || reserved_ + bytes <= held_bytes_));
  });
  if (stopped_) throw Busy("busy: the server is stopping");
  ++first_ticket_;
  drawing_ = true;
  reserved_ += bytes;
  reservation->bytes = bytes;
  lock.unlock();
  Turn turn(this);
  *hold = std::move(reservation);
  return turn;
}

void DrawQueue::Stop() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
  }
  changed_.notify_all();
}

DrawQueue::Waiting DrawQueue::Waiters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return {pages_waiting_, static_cast<std::size_t>(next_ticket_ - first_ticket_)};
}

std::size_t DrawQueue::Reserved() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return reserved_;
}

void DrawQueue::EndTurn() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    drawing_ = false;
  }
  changed_.notify_all();
}

void DrawQueue::Unreserve(std::size_t bytes) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    reserved_ -= bytes;
  }
  changed_.notify_all();
}

}  // namespace prt
