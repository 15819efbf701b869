#include "app/commands.h"
#include "bench/bench.h"
#include "core/error.h"

namespace prt {

const char* const kBenchHelp =
    "usage: prt bench WHAT [options]\n"
    "  WHAT is one of: light, bvh, raster, transport, all.\n"
    "  Prints key=value lines; comparisons end with ratio_<what>=<x>.\n"
    "  --runs N        timed runs per measurement, median reported (default 5)\n"
    "  --threads N     threads for the multi-threaded measurements (default: all)\n"
    "  --mesh PATH     (bvh, transport) also measure this OBJ file\n";

int RunBench(const std::vector<std::string>& tokens) {
  Args args("bench", tokens);
  const auto what = args.TakePositionals();
  if (what.size() != 1) throw UsageError("expected one of light, bvh, raster, transport, all", "bench");
  const std::string& w = what[0];
  if (w == "light") return bench::BenchLight(args);
  if (w == "bvh") return bench::BenchBvh(args);
  if (w == "raster") return bench::BenchRaster(args);
  if (w == "transport") return bench::BenchTransport(args);
  if (w == "all") {
    int rc = bench::BenchLight(args);
    for (auto* f : {bench::BenchBvh, bench::BenchRaster, bench::BenchTransport}) {
      try {
        rc |= f(args);
      } catch (const Error& e) {
        bench::Print("skipped", e.what());
      }
    }
    return rc;
  }
  throw UsageError("'" + w + "': unknown benchmark (expected light, bvh, raster, transport or all)", "bench");
}

}  // namespace prt
