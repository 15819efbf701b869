#include <sys/resource.h>

#include <map>
#include <set>

#include "app/commands.h"
#include "bench/bench.h"
#include "core/error.h"

namespace prt {

const char* const kBenchHelp =
    "usage: prt bench WHAT [options]\n"
    "  WHAT is one of: light, bvh, raster, transport, all.\n"
    "  Prints key=value lines; comparisons end with ratio_<what>=<x>. Times are medians.\n"
    "  The last line, peak_memory_mib=, is the process's peak resident memory.\n"
    "  --runs N        timed runs per measurement, median reported (default 5; transport 3)\n"
    "  --threads N     threads for the multi-threaded measurements (default: all)\n"
    "  --mesh PATH     (bvh, transport) also measure this OBJ file\n"
    "  --size WxH      (raster) frame size (default 1920x1080)\n"
    "  --samples N     (transport) directions per vertex (default 1024)\n";

namespace {

using BenchFn = int (*)(Args&);

struct Bench {
  BenchFn run;
  std::set<std::string> options;  ///< what it reads, validated before it runs
};

const std::map<std::string, Bench>& Benches() {
  static const std::map<std::string, Bench> benches = {
      {"light", {bench::BenchLight, {"--runs", "--threads", "--quiet"}}},
      {"bvh", {bench::BenchBvh, {"--runs", "--threads", "--mesh", "--quiet"}}},
      {"raster", {bench::BenchRaster, {"--runs", "--threads", "--size", "--quiet"}}},
      {"transport", {bench::BenchTransport, {"--runs", "--threads", "--mesh", "--samples", "--quiet"}}},
  };
  return benches;
}

/// Peak resident memory of this process so far, in MiB (Linux reports ru_maxrss in KiB).
double PeakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

}  // namespace

int RunBench(const std::vector<std::string>& tokens) {
  Args probe("bench", tokens);
  const auto what = probe.TakePositionals();
  if (what.size() != 1) throw UsageError("expected one of light, bvh, raster, transport, all", "bench");
  if (what[0] != "all") {
    const auto it = Benches().find(what[0]);
    if (it == Benches().end())
      throw UsageError("'" + what[0] + "': unknown benchmark (expected light, bvh, raster, transport or all)", "bench");
    probe.RejectUnknown(it->second.options);
    Args args("bench", tokens);
    args.TakePositionals();
    args.Allow(it->second.options);
    const int rc = it->second.run(args);
    bench::Print("peak_memory_mib", PeakMemoryMiB());
    return rc;
  }
  // all: every option must mean something to at least one benchmark; each gets what it reads.
  std::set<std::string> any;
  for (const auto& [name, b] : Benches()) any.insert(b.options.begin(), b.options.end());
  probe.RejectUnknown(any);
  int rc = 0;
  for (const char* name : {"light", "bvh", "raster", "transport"}) {
    Args args("bench", tokens);
    args.TakePositionals();
    args.Allow(any);
    rc |= Benches().at(name).run(args);
  }
  bench::Print("peak_memory_mib", PeakMemoryMiB());
  return rc;
}

}  // namespace prt
