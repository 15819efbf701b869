// The README's `prt report --stability`, run as written on a fresh clone's layout (the readme
// tier: the README test, tests/app/test_readme.cpp, leaves this command to this test): its files,
// and every stiff and extreme case's figure as stability.csv gives it against this test's limits.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>


#include "core/atomic_file.h"
#include "tests/readme_commands.h"
#include "tests/test_process.h"

namespace {

using prt::test::Q;

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("stability: the README's prt report --stability writes every stiff and extreme case, each within this test's own limit") {
    // One run of the command, as the README writes it (the suite's slowest work, so it runs once:
    // the README test leaves it to this one): its files, and every case's figure as stability.csv
    // gives it (6 significant digits) against the test's limits.
    // The limits are the test's, not the report's: a case whose figure drifts, or whose limit or
    // pass flag is loosened in the code, fails here. Each limit is the promise its case makes,
    // with the figure measured on this machine for scale.
    struct Limit {
      double lo, hi;  // figure must lie in [lo, hi]
    };
    const double inf = std::numeric_limits<double>::infinity();
    const std::map<std::string, Limit> limits = {
        {"orthonormality_lmax32", {0, 1e-12}},           // measured 1.7e-14
        {"orthonormality_lmax64", {0, 1e-12}},           // 3.6e-14
        {"rotation_equivariance_lmax32", {0, 1e-12}},    // 1.0e-14
        {"rotation_equivariance_lmax64", {0, 1e-11}},    // 2.3e-14
        {"rotation_equivariance_lmax100", {0, 1e-11}},   // 5.0e-14
        {"rotation_equivariance_lmax200", {0, 1e-11}},   // 1.0e-13
        {"rotation_orthogonality_lmax32", {0, 1e-12}},   // 8.9e-16
        {"rotation_orthogonality_lmax64", {0, 1e-12}},   // 1.1e-15
        {"rotation_orthogonality_lmax100", {0, 1e-12}},  // 1.2e-15
        {"rotation_orthogonality_lmax200", {0, 1e-12}},  // 2.6e-15
        {"basis_finite_lmax200", {1, 1}},                // 1 = finite everywhere
        {"hdr_sun_peak_over_mean", {1e4, inf}},          // 4.3e4: the case is as stiff as it says
        {"sun_1e5_peak_over_mean", {1e5, inf}},          // 2.1e5
        {"ringing_lmax8_none", {-1e-3, 0}},              // -2.3e-4: unwindowed, the sun rings
        {"ringing_lmax8_hann", {-1e-3, 1}},              // -1.4e-5
        {"ringing_lmax8_lanczos", {-1e-3, 1}},           // -3.2e-5
        // --window auto: nowhere negative, and not far above zero either (a window stronger than
        // needed would lift the minimum): figures 1.7e-7 .. 7e-9 of the peak.
        {"window_auto_lmax2", {0, 1e-5}},
        {"window_auto_lmax4", {0, 1e-5}},
        {"window_auto_lmax8", {0, 1e-5}},
        {"window_auto_lmax16", {0, 1e-5}},
        {"window_auto_sun1e5_lmax8", {0, 1e-5}},
        {"window_auto_sun1e5_lmax64", {0, 1e-5}},
        {"convex_scale_0.0001", {0, 0}},                 // shadowed == unshadowed exactly
        {"convex_scale_10000", {0, 0}},
        {"rotation_36000_frames", {0, 1e-12}},           // 3.4e-15
        {"sum_1e6_compensated", {0, 1e-12}},             // 0
        {"extreme_mesh_shadowed", {0, 0}},               // no NaN, no bound broken
        {"extreme_mesh_interreflection", {0, 0}},
        {"deep_well_albedo_0.99_64_bounces", {0.5, 1.01}},  // 0.95: energy neither created nor lost
        {"bad_texels", {0, 0}},                          // no non-finite coefficient
        // No value not finite, no vertex below the bound its bands imply beyond the noise allowance,
        // and lmax 2 keeps too little of the lobe (0.9%) for no warning.
        {"glossy_n1000_lmax2", {0, 0}},
        // Wavelets at the default budget against the reference on the knot and 40 x 40 ground: at
        // most the report's limits, and not near 0 either (512 of 6144 coefficients cannot be
        // exact: near 0 would mean the wavelets were compared with themselves). Measured 1.31%
        // and 1.68%.
        {"wavelet_sun_shadowed", {0.005, 0.015}},
        {"wavelet_sun_one_bounce", {0.005, 0.020}},
    };
    // The README's command writes into out/stability of a fresh clone's layout.
    const std::string command = prt::test::ReadmeCommandWith("prt report --stability");
    REQUIRE(command.find("--out out/stability") != std::string::npos);
    const std::string clone = prt::test::MakeReadmeClone("stability_readme");
    REQUIRE(prt::test::RunInClone(clone, command) == 0);
    CHECK(std::filesystem::exists(clone + "/out/stability/report.md"));
    CHECK(prt::ReadFile(clone + "/out/stability/report.md").find("| rotation_36000_frames |") != std::string::npos);
    const std::string text = prt::ReadFile(clone + "/out/stability/stability.csv");
    std::istringstream csv(text);
    std::string line;
    std::getline(csv, line);
    REQUIRE(line == "case,figure,limit,comparison,pass,checks,note");
    std::set<std::string> seen;
    while (std::getline(csv, line)) {
      const auto f = prt::test::CsvFields(line);
      REQUIRE(f.size() == 7);
      const std::string& name = f[0];
      const double figure = std::stod(f[1]), limit = std::stod(f[2]);
      INFO(name << ": " << figure << " (" << f[6] << ")");
      CHECK(seen.insert(name).second);  // each case once
      const auto range = limits.find(name);
      REQUIRE_MESSAGE(range != limits.end(), "a case this test has no limit for: add one");
      CHECK(std::isfinite(figure));
      CHECK(figure >= range->second.lo);
      CHECK(figure <= range->second.hi);
      // The report's own verdict agrees with its figure and limit.
      REQUIRE((f[3] == "<=" || f[3] == ">="));
      CHECK(f[4] == ((f[3] == ">=" ? figure >= limit : figure <= limit) ? "pass" : "FAIL"));
      CHECK(!f[5].empty());
      // The wavelet cases ran on the scene asked for, ground and knot alike: 192 x 20 + 41^2 = 5,521
      // vertices.
      if (name.rfind("wavelet_sun_", 0) == 0)
        CHECK(f[5].find("on a 40 x 40 ground under sky (2-degree sun), 5521 vertices,") != std::string::npos);
    }
    CHECK(seen.size() == limits.size());  // every case ran
    CHECK(seen.count("rotation_36000_frames") == 1);
  }
}
