#pragma once
/// \file
/// Benchmarks behind `prt bench WHAT`. Each prints `key=value` lines to stdout and ends every
/// comparison with `ratio_<what>=<x>`. Times are medians of several runs; comparisons are
/// measured side by side in the same run, because the machine is shared and noisy.

#include <functional>
#include <string>
#include <vector>

#include "options/args.h"
#include "geometry/mesh.h"
#include "material/material.h"
#include "raster/rasterizer.h"

namespace prt::bench {

/// Draws `mesh` with per-vertex `colors` as render's default frame does (640x480, 2x2
/// supersampling, the demo camera): what a render loop adds to a frame's shading.
class DemoFrameDrawer {
 public:
  DemoFrameDrawer();
  void Draw(const Mesh& mesh, const std::vector<glm::vec3>& colors);

 private:
  Camera camera_;
  RasterOptions raster_;
  int width_, height_;
  Rasterizer rasterizer_;
};

/// Median wall-clock seconds of `runs` calls of `fn` (after one warm-up call).
double MedianSeconds(int runs, const std::function<void()>& fn);

/// Two workloads timed in alternation, `runs` pairs after one warm-up of each: the median
/// seconds of each, and the median over pairs of theirs / ours. A slow spell of the shared
/// machine then slows both halves of a pair, and the ratio stays steady where two medians
/// taken a minute apart would not.
struct SideBySide {
  double ours = 0.0, theirs = 0.0, ratio = 0.0;
};
SideBySide TimeSideBySide(int runs, const std::function<void()>& ours, const std::function<void()>& theirs);

/// Prints `key=value` with enough digits for a spreadsheet.
void Print(const std::string& key, double value);
void Print(const std::string& key, const std::string& value);

/// The processor's model name (/proc/cpuinfo), "unknown" where it cannot be read.
std::string CpuModel();

/// Prints what the numbers below depend on: the CPU model, the instruction-set level the
/// kernels use (the widest the CPU runs, or PRT_CPU_LEVEL's cap, which the line then names),
/// the BVH traversal's instruction set, and `threads` (0: all cores).
void PrintMachine(int threads);

int BenchLight(Args& args);
int BenchBvh(Args& args);
int BenchRaster(Args& args);
int BenchTransport(Args& args);
int BenchWavelet(Args& args);
/// The glossy measurements of `prt bench transport` (bench_glossy.cpp): `threads` 0 = all cores.
void BenchGlossy(int runs, int threads, int samples, int lmax);
/// The glossy precompute's lobe rays (`lobe_rays` per vertex toward `eye`) traced as fans and as
/// single rays, side by side (bench_lobe_rays.cpp).
void BenchLobeRays(const Mesh& mesh, const Material& material, const glm::dvec3& eye, int lobe_rays, int runs);

}  // namespace prt::bench
