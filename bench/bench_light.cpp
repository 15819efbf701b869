// `prt bench light`: projection of a 6 x 512^2 cubemap onto SH at lmax 2, 8 and 16.
// The cubemap is generated in memory (a smooth sky-like gradient), so the benchmark needs no
// file and measures projection alone. Target (issue 2): under 100 ms at lmax 8 on 2 cores.

#include "bench/bench.h"
#include "core/parallel.h"
#include "env/cubemap.h"
#include "precompute/light.h"

namespace prt::bench {

int BenchLight(Args& args) {
  const int runs = args.Int("--runs", 5, 1, 1000);
  const int threads = args.Int("--threads", 0, 1, 1024);
  args.String("--mesh");  // shared with `bench all`; not used here
  args.Finish();
  // A smooth sky-like gradient; the benchmark measures projection alone.
  const auto env = CubemapFromFunction(
      [](const glm::dvec3& d) { return glm::dvec3(0.5 + 0.5 * d.y, 0.6, 1.0 + d.x * d.z); }, 512);
  Print("light_cubemap", "6x512^2");
  Print("light_runs", runs);
  for (int t : {1, threads > 0 ? threads : 0}) {
    SetThreadCount(t);
    const std::string tag = t == 1 ? "1thread" : "allthreads";
    Print("light_threads_" + tag, ThreadCount());
    for (int lmax : {2, 8, 16}) {
      const double s = MedianSeconds(runs, [&] { ProjectLight(*env, lmax); });
      Print("light_lmax" + std::to_string(lmax) + "_" + tag + "_ms", s * 1e3);
      Print("light_lmax" + std::to_string(lmax) + "_" + tag + "_mtexels_per_s", 6.0 * 512 * 512 / s / 1e6);
    }
  }
  SetThreadCount(0);
  return 0;
}

}  // namespace prt::bench
