#include "core/progress.h"

#include <cstdio>

#include <unistd.h>

#include "core/log.h"

namespace prt {

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), enabled_(!IsQuiet() && ::isatty(2) && total > 0),
      last_(std::chrono::steady_clock::now()), start_(last_) {}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\r\033[K");
}

void Progress::Advance(std::size_t n) {
  const std::size_t done = done_ += n;
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_ < std::chrono::milliseconds(100)) return;
  if (now - start_ < std::chrono::seconds(1)) return;  // short work shows no bar
  last_ = now;
  Draw(done);
}

void Progress::Draw(std::size_t done) {
  const double f = total_ ? double(done) / double(total_) : 1.0;
  const int width = 30, filled = static_cast<int>(f * width);
  std::string bar(filled, '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "\r%s [%s] %3.0f%%", label_.c_str(), bar.c_str(), 100.0 * f);
  std::fflush(stderr);
}

}  // namespace prt
