#include <sys/resource.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bench/cmd_bench.h"
#include "bench/bench.h"
#include "core/memory.h"

namespace prt {

CommandSpec BenchSpec() {
  return {"prt bench WHAT [options]",
          "WHAT is one of: machine (the machine lines alone), light, bvh, raster, transport, wavelet (a frame in the wavelet basis beside SH lmax 4 and 16), all. Prints key=value lines; comparisons end with "
          "ratio_<what>=<x>. Times are medians. The last lines, page_faults= and peak_memory_mib=, are the "
          "process's minor page faults (first touches of fresh memory) and its peak resident memory.",
          {{"options",
            {{"--runs", "N", "timed runs per measurement, median reported", "5; bvh and transport 3; wavelet 9"},
             {"--threads", "N", "threads for the multi-threaded measurements", "all cores"},
             {"--mesh", "PATH", "(bvh, transport) also measure this OBJ file", "none"},
             {"--size", "WxH", "(raster) frame size", "1920x1080"},
             {"--samples", "N", "(transport) directions per vertex", "1024"},
             QuietOption()}}}};
}

namespace {

using BenchFn = int (*)(Args&);

/// `prt bench machine`: the machine lines that start every benchmark's output, and nothing
/// timed (what a script asks before it trusts a figure: the CPU and the kernels chosen on it).
int NoMeasurement(Args&) { return 0; }

struct Bench {
  BenchFn run;
  std::set<std::string> options;  ///< what it reads, validated before it runs
};

/// The benchmarks in the order `all` runs them.
const std::vector<std::pair<std::string, Bench>>& Benches() {
  static const std::vector<std::pair<std::string, Bench>> benches = {
      {"machine", {NoMeasurement, {"--threads", "--quiet"}}},
      {"light", {bench::BenchLight, {"--runs", "--threads", "--quiet"}}},
      {"bvh", {bench::BenchBvh, {"--runs", "--threads", "--mesh", "--quiet"}}},
      {"raster", {bench::BenchRaster, {"--runs", "--threads", "--size", "--quiet"}}},
      {"transport", {bench::BenchTransport, {"--runs", "--threads", "--mesh", "--samples", "--quiet"}}},
      {"wavelet", {bench::BenchWavelet, {"--runs", "--threads", "--quiet"}}},
  };
  return benches;
}

/// What WHAT may be: every benchmark's name, then `all`.
std::vector<std::string> BenchNames() {
  std::vector<std::string> names;
  for (const auto& b : Benches()) names.push_back(b.first);
  names.push_back("all");
  return names;
}

/// "machine, light, bvh, raster, transport, wavelet or all".
std::string NameList() {
  const std::vector<std::string> names = BenchNames();
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return list;
}

/// Peak resident memory of this process so far, in MiB (Linux reports ru_maxrss in KiB).
double PeakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

}  // namespace

int RunBench(const std::vector<std::string>& tokens) {
  Args probe("bench", tokens, BenchSpec());
  const auto what = probe.TakePositionals();
  if (what.size() != 1) probe.Fail("expected one benchmark: " + NameList());
  if (what[0] != "all") {
    const auto it = std::find_if(Benches().begin(), Benches().end(), [&](const auto& b) { return b.first == what[0]; });
    if (it == Benches().end()) {
      const std::string near = NearestName(what[0], BenchNames());
      probe.Fail("'" + what[0] + "': unknown benchmark (" +
                 (near.empty() ? "expected " + NameList() : "did you mean " + near + "?") + ")");
    }
    probe.RejectOutside(it->second.options, "not used by prt bench " + what[0]);
    Args args("bench", tokens, BenchSpec());
    args.TakePositionals();
    args.Allow(it->second.options);
    bench::PrintMachine(args.Int("--threads", 0, 0, 1024));
    const int rc = it->second.run(args);
    bench::Print("page_faults", double(MinorPageFaults()));
    bench::Print("peak_memory_mib", PeakMemoryMiB());
    return rc;
  }
  // all: every option must mean something to at least one benchmark; each gets what it reads.
  std::set<std::string> any;
  for (const auto& [name, b] : Benches()) any.insert(b.options.begin(), b.options.end());
  int rc = 0;
  {
    Args args("bench", tokens, BenchSpec());
    args.TakePositionals();
    args.Allow(any);
    bench::PrintMachine(args.Int("--threads", 0, 0, 1024));
  }
  for (const auto& [name, b] : Benches()) {
    Args args("bench", tokens, BenchSpec());
    args.TakePositionals();
    args.Allow(any);
    rc |= b.run(args);
  }
  bench::Print("page_faults", double(MinorPageFaults()));
  bench::Print("peak_memory_mib", PeakMemoryMiB());
  return rc;
}

}  // namespace prt
