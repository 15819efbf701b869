// prt reference and prt report as commands: the files reference writes, report's required
// --out, and the options report --stability refuses.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace {

using prt::test::Q;

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("prt reference writes its files, and prt report needs --out") {
    const std::string dir = prt::test::ScratchDir("report_cli");
    const auto ref = prt::test::RunPrt("reference --env furnace:0.5 --transport unshadowed --reference-samples 16 "
                                       "--size 64x48 --quiet --out " + Q(dir + "/ref"));
    CHECK(ref.exit_code == 0);
    CHECK(std::filesystem::exists(dir + "/ref/reference.png"));
    // The vertex count (the demo scene's), then R G B per vertex. Unshadowed under a constant
    // light C each vertex reflects albedo * C * (its estimate of the cosine integral, 1): the
    // channels keep the albedo's ratios exactly (0.7 grey ground, 0.80/0.38/0.20 knot), and the
    // estimates average to C. Measured: mean 0.49969, standard error 0.00024 (16 samples).
    std::istringstream text(prt::ReadFile(dir + "/ref/reference.txt"));
    std::size_t count = 0;
    text >> count;
    CHECK(count == 33985);
    std::size_t rows = 0, other = 0;
    double sum = 0.0;
    constexpr double kRatio = 1e-6;  // the file's 9 significant digits, with room
    for (double r, g, b; text >> r >> g >> b; ++rows) {
      if (std::abs(r - g) <= kRatio * r && std::abs(g - b) <= kRatio * r) sum += r / 0.7;
      else if (std::abs(r / 0.80 - g / 0.38) <= kRatio * r && std::abs(r / 0.80 - b / 0.20) <= kRatio * r) sum += r / 0.80;
      else ++other;
    }
    CHECK(rows == count);
    CHECK(other == 0);
    CHECK(std::abs(sum / double(rows) - 0.5) < 0.002);  // 8 standard errors
    const auto bad = prt::test::RunPrt("report --quick");
    CHECK(bad.exit_code == 2);  // --out is required
  }

  TEST_CASE("prt report --stability refuses an option it would ignore, before any work") {
    const std::string dir = prt::test::ScratchDir("stability_refused");
    // --stability runs fixed cases: an option it would ignore is a usage error, before any work
    // and before the folder is made.
    for (const char* ignored : {"--material phong:10,0.1", "--quick", "--max-lmax 3", "--env furnace", "--basis wavelet"}) {
      CAPTURE(ignored);
      const auto refused = prt::test::RunPrt(std::string("report --stability ") + ignored + " --out " +
                                             Q(dir + "/refused"));
      CHECK(refused.exit_code == 2);
      CHECK(refused.err.find("not used by report --stability") != std::string::npos);
      CHECK(!std::filesystem::exists(dir + "/refused"));
    }
  }
}
