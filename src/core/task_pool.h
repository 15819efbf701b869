#pragma once
/// \file
/// A fixed set of worker threads and a queue: background jobs (`prt view`'s transports and
/// references, each asked for by a request) that must not start a thread per request. Each task
/// runs whole on one worker and hands back its result, or its exception, through a std::future.
/// Not for splitting one computation across cores: that is ParallelFor's (core/parallel.h),
/// which a task may call (the first caller has the loop's threads, a second runs alone).
///
///   TaskPool pool(2);
///   std::future<Reference> r = pool.Submit([&] { return ComputeReference(mesh, env, options); });
///   ... r.get() returns the reference or rethrows what it threw

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace prt {

class TaskPool {
 public:
  /// Starts `workers` threads (at least 1), which wait for tasks.
  explicit TaskPool(int workers);
  /// Waits for the tasks that are running; those still queued are dropped unrun (their futures
  /// throw std::future_error, broken_promise). Then joins the workers.
  ~TaskPool();
  TaskPool(const TaskPool&) = delete;
  TaskPool& operator=(const TaskPool&) = delete;

  /// Queues `task` (callable with no arguments); tasks start in the order submitted, each on the
  /// first free worker. The future gets what it returns or rethrows what it throws.
  template <class F>
  std::future<std::invoke_result_t<F&>> Submit(F task);

  /// The number of worker threads.
  int Workers() const { return static_cast<int>(workers_.size()); }

 private:
  void Push(std::function<void()> job);
  void Work();

  std::mutex mutex_;  ///< guards queue_ and stopping_
  std::condition_variable wake_;
  std::deque<std::function<void()>> queue_;
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

template <class F>
std::future<std::invoke_result_t<F&>> TaskPool::Submit(F task) {
  // packaged_task is move-only and std::function copies: the queue holds a shared pointer.
  auto packaged = std::make_shared<std::packaged_task<std::invoke_result_t<F&>()>>(std::move(task));
  auto result = packaged->get_future();
  Push([packaged] { (*packaged)(); });
  return result;
}

}  // namespace prt
