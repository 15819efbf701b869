#include <algorithm>
#include <chrono>
#include <cstdio>

#include "bench/bench.h"

namespace prt::bench {

double MedianSeconds(int runs, const std::function<void()>& fn) {
  fn();  // warm-up: page faults, caches, lazy initialisation
  std::vector<double> seconds;
  for (int i = 0; i < std::max(1, runs); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

void Print(const std::string& key, double value) { std::printf("%s=%.6g\n", key.c_str(), value); }
void Print(const std::string& key, const std::string& value) {
  std::printf("%s=%s\n", key.c_str(), value.c_str());
}

}  // namespace prt::bench
