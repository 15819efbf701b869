// A real quick sweep of `prt report` on the small scene: its work counted (rays, basis
// evaluations) and every run timed with a median and a range. (How report.md, report.csv and
// error_vs_time.png carry made-up times: test_report_timing.cpp.)
#include <doctest/doctest.h>

#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "report/round_robin_timing.h"
#include "tests/test_process.h"

namespace prt {

TEST_SUITE("report") {
  TEST_CASE("report timing: a real quick sweep counts its work and times every run with a median and a range") {
    const std::string dir = test::ScratchDir("timing_sweep");
    const auto r = test::RunPrt("report --quick --max-lmax 3 --max-samples 32 --quiet" +
                                test::SmallSceneOption("timing_sweep_scene") + " --out " + test::Q(dir));
    REQUIRE(r.exit_code == 0);
    const std::string md = ReadFile(dir + "/report.md");
    CHECK(md.find("## Timing") != std::string::npos);
    // The closed form's odd bands above 1 are zero: lmax 2 and 3 the same, and said why.
    CHECK(md.find("Unshadowed, lmax 2 and 3 (and 4 and 5, 6 and 7) have the same error") != std::string::npos);
    std::istringstream lines(ReadFile(dir + "/report.csv"));
    std::string line;
    std::getline(lines, line);
    const auto names = test::CsvFields(line);
    std::map<std::string, std::size_t> col;
    for (std::size_t i = 0; i < names.size(); ++i) col[names[i]] = i;
    for (const char* name : {"mode", "sampler", "directions", "lmax", "total_relative", "seconds", "seconds_min",
                             "seconds_max", "timing_samples", "timed_lmax", "rays", "basis_evaluations"})
      REQUIRE_MESSAGE(col.count(name), name);
    std::map<std::pair<std::string, int>, std::uint64_t> rays;  // (sampler, directions) at lmax 3
    std::map<int, double> unshadowed;                            // lmax -> total error
    int rows = 0;
    while (std::getline(lines, line)) {
      const auto f = test::CsvFields(line);
      REQUIRE(f.size() == names.size());
      const std::string mode = f[col["mode"]], sampler = f[col["sampler"]];
      const int lmax = std::stoi(f[col["lmax"]]);
      CAPTURE(line);
      ++rows;
      CHECK(std::stoi(f[col["timed_lmax"]]) == 3);
      CHECK(std::stoi(f[col["timing_samples"]]) >= RoundRobinPlan{}.min_rounds);
      const double t = std::stod(f[col["seconds"]]), lo = std::stod(f[col["seconds_min"]]),
                   hi = std::stod(f[col["seconds_max"]]);
      CHECK(lo > 0);
      CHECK(lo <= t);
      CHECK(t <= hi);
      if (mode == "unshadowed") {
        CHECK(f[col["rays"]] == "0");
        unshadowed[lmax] = std::stod(f[col["total_relative"]]);
        continue;
      }
      const std::uint64_t n = std::stoull(f[col["rays"]]);
      CHECK(n > 0);
      CHECK(std::stoull(f[col["basis_evaluations"]]) > 0);
      if (lmax == 3) rays[{sampler, std::stoi(f[col["directions"]])}] = n;
    }
    CHECK(rows == 3 * (1 + 3 * 2));  // lmax 1..3 x (closed form + 3 samplers x 16, 32 directions)
    // About half the directions lie above a vertex's horizon whatever their number: twice the
    // directions, about twice the rays (fibonacci's spiral, the same in every vertex's frame).
    const double ratio = double(rays[{"fibonacci", 32}]) / double(rays[{"fibonacci", 16}]);
    CHECK(ratio == doctest::Approx(2.0).epsilon(0.1));
    REQUIRE(unshadowed.count(3));
    CHECK(unshadowed[2] == doctest::Approx(unshadowed[3]).epsilon(1e-9));
    CHECK(unshadowed[1] > unshadowed[2]);
  }
}

}  // namespace prt
