#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "core/parallel.h"
#include "core/simd.h"
#include "geometry/bvh_kernels.h"

namespace prt::bench {

namespace {
double Seconds(const std::function<void()>& fn) {
  const auto t0 = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}  // namespace

double MedianSeconds(int runs, const std::function<void()>& fn) {
  fn();  // warm-up: page faults, caches, lazy initialisation
  std::vector<double> seconds;
  for (int i = 0; i < std::max(1, runs); ++i) seconds.push_back(Seconds(fn));
  return Median(seconds);
}

SideBySide TimeSideBySide(int runs, const std::function<void()>& ours, const std::function<void()>& theirs) {
  ours();  // warm-up of both
  theirs();
  std::vector<double> o, t, r;
  for (int i = 0; i < std::max(1, runs); ++i) {
    // Alternate which goes first, so neither always runs right after the other's cache use.
    const bool ours_first = i % 2 == 0;
    const double a = ours_first ? Seconds(ours) : Seconds(theirs);
    const double b = ours_first ? Seconds(theirs) : Seconds(ours);
    o.push_back(ours_first ? a : b);
    t.push_back(ours_first ? b : a);
    r.push_back(t.back() / o.back());
  }
  return SideBySide{Median(o), Median(t), Median(r)};
}

std::string CpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

void PrintMachine(int threads) {
  Print("cpu_model", CpuModel());
  // The level every kernel choice uses (light projection, cube-map rows, tone mapping, the BVH).
  std::string level = VectorLevelName(CpuVectorLevel());
  if (CpuLevelCapped())
    level += std::string(" (capped by PRT_CPU_LEVEL; this CPU runs ") + VectorLevelName(CpuMaxVectorLevel()) + ")";
  Print("cpu_vector_level", level);
  Print("isa_bvh", IsaName(ActiveKernels().isa));
  SetThreadCount(threads);
  Print("threads", double(ThreadCount()));
}

void Print(const std::string& key, double value) { std::printf("%s=%.6g\n", key.c_str(), value); }
void Print(const std::string& key, const std::string& value) {
  std::printf("%s=%s\n", key.c_str(), value.c_str());
}

}  // namespace prt::bench
