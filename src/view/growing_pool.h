#pragma once
/// \file
/// The threads that serve `prt view`'s connections: a task queue for the HTTP library that runs
/// each connection on an idle thread, or on a new one while fewer than `max_threads` exist
/// (then it waits for one). The library's own pool has a fixed number of threads, each held by
/// one connection for as long as it lasts: clients that wait (a request trickling in before its
/// deadline, view/deadline_server.h; a frame waiting its turn to be drawn, view/draw_queue.h)
/// would keep the page's own requests waiting for a thread. Threads, once made, stay until
/// shutdown: their number is the most connections served at once, at most `max_threads`.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include <httplib.h>

namespace prt {

class GrowingPool final : public httplib::TaskQueue {
 public:
  explicit GrowingPool(std::size_t max_threads) : max_threads_(max_threads) {}
  ~GrowingPool() override { shutdown(); }
  GrowingPool(const GrowingPool&) = delete;
  GrowingPool& operator=(const GrowingPool&) = delete;

  void enqueue(std::function<void()> fn) override;
  /// Runs what is queued, then joins every thread.
  void shutdown() override;

  /// Threads made so far.
  std::size_t Threads() const;

 private:
  void Work();

  const std::size_t max_threads_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> threads_;
  std::size_t idle_ = 0;  ///< threads waiting for a job
  bool stopping_ = false;
};

}  // namespace prt
