#pragma once
/// \file
/// Work handed to other threads while the caller goes on, at most `limit` jobs at a time: the
/// render loop encodes and writes frame i's PNG while it draws frame i + 1, and with several
/// frames in flight the encoding (a single-threaded zlib stream per frame) keeps up with a
/// drawing that uses every core.
///
/// Each job owns its inputs and writes its own output (one file per frame), so the bytes
/// written never depend on how many jobs ran at once.

#include <cstddef>
#include <deque>
#include <functional>
#include <future>

namespace prt {

class BackgroundJobs {
 public:
  /// At most `limit` jobs in flight (at least 1).
  explicit BackgroundJobs(int limit);
  /// Waits for every job; an error of a job not collected by Wait is dropped here.
  ~BackgroundJobs();

  /// Starts `job` on its own thread, first waiting for the oldest job while `limit` are in
  /// flight; rethrows that job's exception. Returns the seconds spent waiting.
  double Submit(std::function<void()> job);
  /// Waits for every job in submission order; rethrows the first exception. Returns the seconds
  /// spent waiting.
  double Wait();

 private:
  std::size_t limit_;
  std::deque<std::future<void>> in_flight_;
};

}  // namespace prt
