#include "core/task_pool.h"

#include <algorithm>

namespace prt {

TaskPool::TaskPool(int workers) {
  for (int w = 0; w < std::max(workers, 1); ++w) workers_.emplace_back([this] { Work(); });
}

TaskPool::~TaskPool() {
  std::deque<std::function<void()>> dropped;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    dropped.swap(queue_);
  }
  wake_.notify_all();
  // Destroying a packaged_task never run breaks its promise: its future throws, never hangs.
  dropped.clear();
  for (std::thread& worker : workers_) worker.join();
}

void TaskPool::Push(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(job));
  }
  wake_.notify_one();
}

void TaskPool::Work() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    job();  // a packaged_task: what the task throws goes to its future
  }
}

}  // namespace prt
