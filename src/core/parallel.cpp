#include "core/parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace prt {
namespace {

std::atomic<int> g_threads{0};

// Worker threads kept between calls: starting and joining threads for every ParallelFor cost
// 130-190 us a call on the 2-core machine (measured), about a millisecond per frame for the
// rasterizer's six calls. One call at a time uses the pool; a call made while it is busy (a
// ParallelFor inside a body, or one from another thread) runs its chunks on its own thread,
// which gives the same result, because chunks never depend on the thread that runs them.
class Pool {
 public:
  ~Pool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }

  // Claims the pool; false if another call has it.
  bool TryClaim() {
    bool expected = false;
    return busy_.compare_exchange_strong(expected, true);
  }
  void Release() { busy_ = false; }

  // Runs `work` on the calling thread and on `helpers` pool threads; returns when all are done.
  // Precondition: claimed.
  void Run(std::size_t helpers, const std::function<void()>& work) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (threads_.size() < helpers) threads_.emplace_back([this] { Loop(); });
      work_ = &work;
      wanted_ = helpers;
      taken_ = 0;
      running_ = helpers;
      ++generation_;
    }
    wake_.notify_all();
    work();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return running_ == 0; });
    work_ = nullptr;
  }

 private:
  void Loop() {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      if (taken_ >= wanted_) continue;  // this call needs fewer helpers
      ++taken_;
      const std::function<void()>* work = work_;
      lock.unlock();
      (*work)();
      lock.lock();
      if (--running_ == 0) done_.notify_all();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_;
  const std::function<void()>* work_ = nullptr;
  std::size_t wanted_ = 0, taken_ = 0, running_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
  std::atomic<bool> busy_{false};
};

Pool& ThePool() {
  static Pool pool;
  return pool;
}

}  // namespace

void SetThreadCount(int threads) { g_threads = std::max(0, threads); }

int ThreadCount() {
  int t = g_threads;
  if (t > 0) return t;
  return std::max(1u, std::thread::hardware_concurrency());
}

void ParallelFor(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t, std::size_t)>& body) {
  if (count == 0) return;
  grain = std::max<std::size_t>(1, grain);
  const std::size_t chunks = ChunkCount(count, grain);
  const std::size_t workers = std::min<std::size_t>(ThreadCount(), chunks);

  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const std::function<void()> work = [&] {
    for (;;) {
      const std::size_t c = next.fetch_add(1);
      if (c >= chunks) return;
      try {
        body(c * grain, std::min(count, (c + 1) * grain));
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = chunks;  // stop handing out work
      }
    }
  };

  Pool& pool = ThePool();
  if (workers > 1 && pool.TryClaim()) {
    pool.Run(workers - 1, work);
    pool.Release();
  } else {
    work();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace prt
