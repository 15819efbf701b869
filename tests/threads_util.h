#pragma once
/// \file
/// What the threads tier's tests share (tests/README.md, "Tiers"): a stage run on one thread and
/// on more threads than the machine has cores, so that its chunks interleave on any machine and
/// ThreadSanitizer sees them meet. The project promises the same bits for any --threads.

#include <utility>

#include "core/parallel.h"

#include "tests/test_support.h"

namespace prt::test {

/// More threads than the 2-core machines CI runs on.
inline constexpr int kManyThreads = 4;

/// `run()` on one thread, then on kManyThreads: the two results.
template <class F>
auto OneAndMany(F&& run) {
  auto one = WithThreads(1, run);
  auto many = WithThreads(kManyThreads, run);
  return std::make_pair(std::move(one), std::move(many));
}

/// The pool's thread count set for a scope (code that runs ParallelFor inside it, on threads of
/// its own as well), all cores again after it.
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) { SetThreadCount(threads); }
  ~ThreadCountScope() { SetThreadCount(0); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;
};

}  // namespace prt::test
