#include "core/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include "core/log.h"

namespace prt {
namespace {

constexpr std::chrono::milliseconds kRedraw(100);  // at most ten draws a second

/// The newest bar, for LatestProgress: its label and total under the mutex, its count atomic.
struct Latest {
  std::mutex mutex;
  std::atomic<const void*> owner{nullptr};
  std::string label;
  std::size_t total = 0;
  std::atomic<std::size_t> done{0};
};

Latest& TheLatest() {
  static Latest* latest = new Latest;  // never destroyed: bars may end after main's statics
  return *latest;
}

}  // namespace

ProgressReading LatestProgress() {
  Latest& l = TheLatest();
  std::lock_guard<std::mutex> lock(l.mutex);
  const std::size_t done = l.done;
  return {l.label, l.total ? std::min(1.0, double(done) / double(l.total)) : 0.0, l.owner != nullptr};
}

std::string TimeLeft(double fraction, double elapsed_s) {
  if (!(fraction >= kTimeLeftFraction) || fraction >= 1.0 || !(elapsed_s >= 0.0)) return {};
  const double left = elapsed_s * (1.0 - fraction) / fraction;
  const long s = static_cast<long>(std::ceil(left));  // "1 s left" until the end, never "0 s"
  char text[64];
  if (s < 60) std::snprintf(text, sizeof text, "%ld s left", s);
  else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %ld s left", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld h %ld min left", s / 3600, s / 60 % 60);
  return text;
}

std::chrono::duration<double> ProgressDelay() {
  static const double seconds = [] {
    const char* text = std::getenv("PRT_PROGRESS_DELAY");
    if (!text) return kProgressDelaySeconds;
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end != text && *end == '\0' && v >= 0.0 && v <= 3600.0) return v;
    Warn(std::string("PRT_PROGRESS_DELAY='") + text + "' is not a number of seconds from 0 to 3600; waiting " +
         std::to_string(static_cast<int>(kProgressDelaySeconds)) + " s before showing progress");
    return kProgressDelaySeconds;
  }();
  return std::chrono::duration<double>(seconds);
}

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), enabled_(!IsQuiet() && ::isatty(2) && total > 0),
      start_(std::chrono::steady_clock::now()), last_(start_ - kRedraw) {  // the first draw waits for the delay only
  Latest& l = TheLatest();
  std::lock_guard<std::mutex> lock(l.mutex);
  l.owner = this;
  l.label = label_;
  l.total = total_;
  l.done = 0;
}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\r\033[K");
  Latest& l = TheLatest();
  std::lock_guard<std::mutex> lock(l.mutex);
  if (l.owner == this) l.owner = nullptr;
}

void Progress::Advance(std::size_t n) {
  const std::size_t done = done_ += n;
  // A newer bar may have taken its place. Threads finish their Advance in any order: the count
  // read from the bar only grows (the largest one stored wins), so a reader never sees it go back.
  if (Latest& latest = TheLatest(); latest.owner == this) {
    std::size_t stored = latest.done.load();
    while (stored < done && !latest.done.compare_exchange_weak(stored, done)) {
    }
  }
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_ < kRedraw) return;
  if (now - start_ < ProgressDelay()) return;  // short work shows no bar
  last_ = now;
  Draw(done);
}

void Progress::Draw(std::size_t done) {
  const double f = total_ ? double(done) / double(total_) : 1.0;
  const int width = 30, filled = static_cast<int>(f * width);
  std::string bar(filled, '#');
  bar.resize(width, '.');
  const double elapsed = SecondsSince(start_);
  const std::string left = TimeLeft(f, elapsed);
  std::fprintf(stderr, "\r%s [%s] %3.0f%%%s%s\033[K", label_.c_str(), bar.c_str(), 100.0 * f, left.empty() ? "" : "  ",
               left.c_str());
  std::fflush(stderr);
}

}  // namespace prt
