#pragma once
/// \file
/// Deterministic data parallelism. Work is split into fixed chunks whose boundaries depend only
/// on the problem size, never on the thread count; any reduction combines chunk results in chunk
/// order. That is what makes every output identical for any `--threads`.

#include <cstddef>
#include <functional>

namespace prt {

/// Threads used by ParallelFor; 0 means all hardware threads. Set once from `--threads`.
void SetThreadCount(int threads);
int ThreadCount();

/// Calls body(begin, end) for consecutive chunks [begin, end) of [0, count) of at most `grain`
/// items, on up to ThreadCount() threads: the caller and threads kept for the next call. A call
/// made while another has the threads (from inside a body, or from another thread) runs its
/// chunks on the calling thread alone. The first exception thrown by a body is rethrown.
void ParallelFor(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t begin, std::size_t end)>& body);

/// Number of chunks ParallelFor makes for (count, grain): chunk c covers
/// [c * grain, min(count, (c + 1) * grain)).
inline std::size_t ChunkCount(std::size_t count, std::size_t grain) {
  return grain == 0 ? 0 : (count + grain - 1) / grain;
}

}  // namespace prt
