// `prt bench light`: projection of a 6 x 512^2 cubemap onto SH at lmax 2, 8 and 16.
// The cubemap is generated in memory (a smooth sky-like gradient), so the benchmark needs no
// file and measures projection alone. Target (issue 2): under 100 ms at lmax 8 on 2 cores.

#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "bench/bench.h"
#include "core/parallel.h"
#include "env/cubemap.h"
#include "precompute/light.h"

namespace prt::bench {
namespace {

std::unique_ptr<CubemapEnvironment> SyntheticCubemap(int size) {
  std::array<ImageF, 6> faces;
  const auto& frames = FaceFrames(CubeLayout::kStandard);
  for (int k = 0; k < 6; ++k) {
    faces[k] = ImageF(size, size);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const double s = -1.0 + (col + 0.5) * 2.0 / size, t = -1.0 + (row + 0.5) * 2.0 / size;
        const glm::dvec3 d = glm::normalize(frames[k].n + s * frames[k].u + t * frames[k].v);
        faces[k].at(col, row) = glm::vec3(0.5f + 0.5f * float(d.y), 0.6f, 1.0f + float(d.x * d.z));
      }
  }
  return std::make_unique<CubemapEnvironment>(std::move(faces), CubeLayout::kStandard, "synthetic");
}

}  // namespace

int BenchLight(Args& args) {
  const int runs = args.Int("--runs", 5, 1, 1000);
  const int threads = args.Int("--threads", 0, 1, 1024);
  args.String("--mesh");  // shared with `bench all`; not used here
  args.Finish();
  const auto env = SyntheticCubemap(512);
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
