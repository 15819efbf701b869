#pragma once
/// \file
/// Which frame `prt view` draws next when many are asked for at once, and the memory the frames
/// asked for hold. The scene draws one frame at a time on every core; before this queue each
/// connection asking for a frame waited for it holding a server thread, and 50 clients asking
/// for 4096^2 frames kept the page from its own state for 14 s while most of them timed out.
///
///   - one frame is drawn at a time; the page's frames (its stream, Lane kPage) go before every
///     frame asked for by /frame and /frame.png (kRequest), which go in the order they came;
///   - at most `waiting_requests` requested frames wait for their turn: one more is refused at
///     once (Busy: 503 with Retry-After), so a crowd gets its answer instead of a timeout;
///   - a requested frame reserves its bytes from its turn until its response has been sent (the
///     Hold), and its turn waits while the bytes reserved and its own would pass `held_bytes`
///     (unless none are reserved: a frame larger than the budget is drawn alone). The frames a
///     slow client has not read yet cannot fill the memory.
///
/// Stop() ends every wait with Busy: a stopping server draws nothing more.

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace prt {

/// No turn now (503): too many frames wait, or the server is stopping.
struct Busy : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class DrawQueue {
 public:
  DrawQueue(std::size_t waiting_requests, std::size_t held_bytes)
      : waiting_requests_(waiting_requests), held_bytes_(held_bytes) {}

  /// The turn to draw, until destroyed.
  class [[nodiscard]] Turn {
   public:
    explicit Turn(DrawQueue* queue) : queue_(queue) {}
    Turn(Turn&& other) noexcept : queue_(other.queue_) { other.queue_ = nullptr; }
    Turn(const Turn&) = delete;
    Turn& operator=(const Turn&) = delete;
    Turn& operator=(Turn&&) = delete;
    ~Turn() { Release(); }
    /// Gives the turn to the next frame now.
    void Release();

   private:
    DrawQueue* queue_;
  };

  /// Waits for a page frame's turn.
  Turn Page();
  /// Waits for a requested frame's turn, `bytes` reserved from then until `*hold` and every copy
  /// of it is gone; throws Busy when `waiting_requests` wait already, or on Stop.
  Turn Request(std::size_t bytes, std::shared_ptr<void>* hold);
  /// Every wait, now and later, throws Busy.
  void Stop();

  /// Bytes reserved now by requested frames (for tests).
  std::size_t Reserved() const;
  /// Frames waiting for their turn now (for tests).
  struct Waiting {
    std::size_t pages = 0, requests = 0;
  };
  Waiting Waiters() const;

 private:
  /// A requested frame's bytes, reserved until it is destroyed.
  struct Reservation {
    Reservation(DrawQueue* q, std::size_t b) : queue(q), bytes(b) {}
    Reservation(const Reservation&) = delete;
    Reservation& operator=(const Reservation&) = delete;
    ~Reservation() { queue->Unreserve(bytes); }
    DrawQueue* queue;
    std::size_t bytes;
  };

  void EndTurn();
  void Unreserve(std::size_t bytes);

  const std::size_t waiting_requests_, held_bytes_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool drawing_ = false, stopped_ = false;
  std::size_t pages_waiting_ = 0, reserved_ = 0;
  std::uint64_t next_ticket_ = 0, first_ticket_ = 0;  ///< requested frames, first come first drawn
};

}  // namespace prt
