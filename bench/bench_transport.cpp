// `prt bench transport`: the transport precompute on the demo scene (or --mesh): shadowed and
// interreflected (2 bounces), lmax 2 and 4, 1024 directions per vertex, 1 thread and all
// threads: seconds and million rays per second (rays actually traced, none below the horizon).
// Then the glossy measurements of bench_glossy.cpp (demo scene, lmax 4, all threads), and its lobe
// rays traced as fans and as single rays (bench_lobe_rays.cpp).

#include <algorithm>
#include <chrono>

#include "bench/bench.h"
#include "app/render_args.h"
#include "core/parallel.h"
#include "geometry/procedural.h"
#include "io/obj_loader.h"
#include "material/material.h"
#include "precompute/transport.h"

namespace prt::bench {

int BenchTransport(Args& args) {
  const int runs = args.Int("--runs", 3, 1, 1000);
  const int threads = args.Int("--threads", 0, 1, 1024);
  const auto mesh_path = args.String("--mesh");
  const int samples = args.Int("--samples", 1024, 1, 1 << 20);
  const Mesh mesh = mesh_path ? LoadObj(*mesh_path).mesh : MakeDemoScene();
  Print("transport_mesh", mesh_path ? *mesh_path : std::string("demo scene"));
  Print("transport_vertices", double(mesh.vertex_count()));
  Print("transport_triangles", double(mesh.triangle_count()));
  Print("transport_samples", samples);
  for (TransportMode mode : {TransportMode::kShadowed, TransportMode::kInterreflection}) {
    for (int lmax : {2, 4}) {
      for (int t : {1, threads}) {
        SetThreadCount(t);
        TransportOptions o;
        o.mode = mode;
        o.lmax = lmax;
        o.samples = samples;
        o.bounces = 2;
        o.bounce_tolerance = 0.0;
        TransportReport report;
        const double s = MedianSeconds(runs, [&] { ComputeTransport(mesh, o, &report); });
        const std::string key = std::string("transport_") + TransportModeName(mode) + "_lmax" + std::to_string(lmax) +
                                (t == 1 ? "_1thread" : "_allthreads");
        Print(key + "_s", s);
        Print(key + "_mrays_per_s", double(report.rays) / s / 1e6);
      }
    }
  }
  SetThreadCount(0);
  BenchGlossy(runs, threads, samples, 4);
  SetThreadCount(threads);
  BenchLobeRays(MakeDemoScene(), ParseMaterial("phong:50,0.4"), *WithDemoCamera({}).eye, LobeSamplesOf(samples),
                std::max(runs, 5));
  SetThreadCount(0);
  return 0;
}

}  // namespace prt::bench
