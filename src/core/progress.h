#pragma once
/// \file
/// A progress bar on stderr for long work: shown only when stderr is a terminal and the run is
/// not quiet, after a second of work (ProgressDelay), updated at most ten times a second, safe
/// to advance from any thread.
///
///     rendering [#############.................]  45%  12 s left
///
/// The time left assumes the rest goes at the average rate so far: elapsed * (1 - f) / f for a
/// fraction f done. It is shown once kTimeLeftFraction of the work is done, when the rate has
/// settled enough to mean something.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace prt {

/// Fraction of the work done before the time left is shown.
inline constexpr double kTimeLeftFraction = 0.03;

/// Seconds of work before a bar appears, so that short work shows none.
inline constexpr double kProgressDelaySeconds = 1.0;

/// The delay in use: the environment variable PRT_PROGRESS_DELAY (seconds, 0..3600) when set
/// to such a number, else kProgressDelaySeconds (with a warning when it is set to anything
/// else). Read once, when a bar is first drawn. (Tests set 0 to see bars of short work on a
/// pseudo-terminal.)
std::chrono::duration<double> ProgressDelay();

/// "12 s left", "3 min 20 s left", "2 h 5 min left" for `fraction` of the work done in
/// `elapsed_s` seconds; empty before kTimeLeftFraction or when done.
std::string TimeLeft(double fraction, double elapsed_s);

/// The newest bar's label and the fraction of its work done, whether or not it is drawn (prt
/// view shows it on its page while a transport is computed); `active` is false once it ended.
struct ProgressReading {
  std::string label;
  double fraction = 0.0;
  bool active = false;
};
ProgressReading LatestProgress();

/// A progress bar over `total` items (see the file comment).
class Progress {
 public:
  /// A bar labelled `label` for `total` items; nothing is shown before ProgressDelay().
  Progress(std::string label, std::size_t total);
  ~Progress();  ///< clears the bar
  Progress(const Progress&) = delete;  ///< one bar, one owner
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
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;  ///< of the last draw
};

}  // namespace prt
