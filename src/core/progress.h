#pragma once
/// \file
/// A progress bar on stderr for long work: shown only when stderr is a terminal and the run is
/// not quiet, updated at most ten times a second, safe to advance from any thread.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace prt {

class Progress {
 public:
  Progress(std::string label, std::size_t total);
  ~Progress();  ///< clears the bar
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Adds `n` finished items.
  void Advance(std::size_t n);

 private:
  void Draw(std::size_t done);

  std::string label_;
  std::size_t total_;
  bool enabled_;
  std::atomic<std::size_t> done_{0};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace prt
