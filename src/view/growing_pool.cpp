#include "view/growing_pool.h"

#include <system_error>
#include <utility>

namespace prt {

void GrowingPool::enqueue(std::function<void()> fn) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (stopping_) {  // no thread left to run it: a connection is still closed by its job
    lock.unlock();
    fn();
    return;
  }
  jobs_.push_back(std::move(fn));
  // Every idle thread may already be woken for an earlier job: a new one for each job beyond.
  if (jobs_.size() > idle_ && threads_.size() < max_threads_) {
    try {
      threads_.emplace_back([this] { Work(); });
    } catch (const std::system_error&) {
      // No thread to be had (a limit of the system): the job waits for one of those there are,
      // or, with none, runs here and now (its connection answered and closed).
      if (threads_.empty()) {
        std::function<void()> job = std::move(jobs_.back());
        jobs_.pop_back();
        lock.unlock();
        job();
        return;
      }
    }
  }
  wake_.notify_one();
}

void GrowingPool::shutdown() {
  std::vector<std::thread> threads;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    threads.swap(threads_);
  }
  wake_.notify_all();
  for (std::thread& t : threads) t.join();
}

std::size_t GrowingPool::Threads() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return threads_.size();
}

void GrowingPool::Work() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ++idle_;
      wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
      --idle_;
      if (jobs_.empty()) return;  // stopping, and nothing left to run
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    job();
  }
}

}  // namespace prt
