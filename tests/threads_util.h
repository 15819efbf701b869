#pragma once
/// \file
/// What the threads tier's tests share (tests/README.md, "Tiers"): a stage run on one thread and
/// on more threads than the machine has cores, so that its chunks interleave on any machine and
/// ThreadSanitizer sees them meet. The project promises the same bits for any --threads.

#include <thread>
#include <utility>
#include <vector>

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

/// Runs `work(t)` on `count` threads of its own, t = 0..count - 1, at once, and joins them.
template <class F>
void OnThreads(int count, F&& work) {
  std::vector<std::thread> threads;
  for (int t = 0; t < count; ++t) threads.emplace_back([&work, t] { work(t); });
  for (auto& thread : threads) thread.join();
}

}  // namespace prt::test
