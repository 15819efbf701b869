// prt reference and prt report: the stability cases, the plot, and the files the commands write.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "core/atomic_file.h"
#include "env/procedural.h"
#include "raster/plot.h"
#include "report/report_auto_lmax.h"
#include "report/stability.h"
#include "tests/readme_commands.h"
#include "tests/test_support.h"

namespace {

using prt::test::Q;

/// Count of pixels that are not pure white.
std::size_t Inked(const prt::Image8& im) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < im.rgb.size(); i += 3) n += (im.rgb[i] != 255 || im.rgb[i + 1] != 255 || im.rgb[i + 2] != 255);
  return n;
}

/// The stability suite's wavelet cases on a smaller scene, for the runs under a sanitizer.
const prt::StabilityOptions kSanitizedStability{48, 6, 10};

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("stability: the README's prt report --stability writes every stiff and extreme case, each within this test's own limit" * prt::test::WholeStudy()) {
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
        // exact: near 0 would mean the wavelets were compared with themselves). Measured 1.40%
        // and 1.66%.
        {"wavelet_sun_shadowed", {0.005, 0.015}},
        {"wavelet_sun_one_bounce", {0.005, 0.020}},
    };
    // Scaled under a sanitizer (tests/README.md): the cases run in-process, the wavelet ones on
    // a knot of 48 x 6 over a 10 x 10 ground (409 vertices) instead of 5,521 (their figures there,
    // 1.08% and 1.60%, meet the same limits), and the same CSV is read; the command's own files
    // are checked by the unsanitized run.
    const std::string dir = prt::test::ScratchDir("stability");
    std::string text;
    if (prt::test::kSanitized) {
      const auto cases = prt::RunStabilityCases(kSanitizedStability);
      text = prt::StabilityCsv(cases);
      CHECK(prt::StabilityMarkdown(cases).find("| rotation_36000_frames |") != std::string::npos);
    } else {
      // The README's command writes into out/stability of a fresh clone's layout.
      const std::string command = prt::test::ReadmeCommandWith("prt report --stability");
      REQUIRE(command.find("--out out/stability") != std::string::npos);
      const std::string clone = prt::test::MakeReadmeClone("stability_readme");
      REQUIRE(prt::test::RunInClone(clone, command) == 0);
      CHECK(std::filesystem::exists(clone + "/out/stability/report.md"));
      text = prt::ReadFile(clone + "/out/stability/stability.csv");
    }
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
      // The wavelet cases ran on the scene asked for, ground and knot alike: 48 x 6 + 11^2 = 409
      // vertices under a sanitizer (kSanitizedStability), 192 x 20 + 41^2 = 5,521 otherwise.
      if (name.rfind("wavelet_sun_", 0) == 0)
        CHECK(f[5].find(prt::test::kSanitized ? "on a 10 x 10 ground under sky (2-degree sun), 409 vertices,"
                                              : "on a 40 x 40 ground under sky (2-degree sun), 5521 vertices,") !=
              std::string::npos);
    }
    CHECK(seen.size() == limits.size());  // every case ran
    CHECK(seen.count("rotation_36000_frames") == 1);
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

  TEST_CASE("stability: the wavelet cases run on the scene StabilityOptions asks for") {
    // A knot of 16 x 3 over a 2 x 2 ground: 48 + 3^2 = 57 vertices, named with its ground in each
    // wavelet case's checks; the cases with fixed inputs left out. The wavelet cases' figures on
    // a scene this coarse are not the measured ones, so only that they are numbers is checked.
    const auto cases = prt::RunStabilityCases(prt::StabilityOptions{16, 3, 2, false});
    CHECK(cases.size() == 2);
    int wavelet = 0;
    for (const auto& c : cases) {
      if (c.name.rfind("wavelet_sun_", 0) != 0) continue;
      CAPTURE(c.checks);
      CHECK(c.checks.find("on a 2 x 2 ground under sky (2-degree sun), 57 vertices,") != std::string::npos);
      CHECK(std::isfinite(c.figure));
      ++wavelet;
    }
    CHECK(wavelet == 2);
  }

  TEST_CASE("--lmax auto: the smallest band count whose irradiance error is within the tolerance") {
    const auto furnace = prt::MakeFurnace(1.0);
    CHECK(prt::ChooseLmax(*furnace, 1e-6, 64).lmax == 0);  // constant light: band 0 is all of it
    const auto sky = prt::MakeSky(prt::SkyParams{});
    const prt::AutoLmax loose = prt::ChooseLmax(*sky, 0.1, 64), tight = prt::ChooseLmax(*sky, 0.01, 64);
    CHECK(loose.error <= 0.1);
    CHECK(tight.error <= 0.01);
    CHECK(tight.lmax > loose.lmax);
    CHECK(prt::ChooseLmax(*sky, 0.01, tight.lmax - 1).error > 0.01);  // one band fewer is not enough
  }

  TEST_CASE("plot: axes, lines and legend are drawn, points that log axes cannot show are skipped") {
    // Series a is y = 1e-4 / x: a straight falling line on log-log axes. Series b has one point
    // a log axis can show (x = 0 and y < 0 are skipped): no line, only its legend entry.
    prt::PlotSeries a, b;
    a.label = "a", a.x = {1e-3, 1e-2, 1e-1}, a.y = {1e-1, 1e-2, 1e-3}, a.color = prt::PlotColor(0);
    b.label = "b", b.x = {0.0, 1e-2, 1.0}, b.y = {1.0, -1.0, 1e-2}, b.color = prt::PlotColor(1), b.dashed = true;
    prt::PlotOptions o;
    o.title = "t", o.x_label = "x", o.y_label = "y";
    const prt::Image8 im = prt::DrawLogLogPlot({a, b}, o);
    REQUIRE(im.width == o.width);
    REQUIRE(im.height == o.height);
    const auto pixels_of = [](const prt::Image8& image, const glm::vec3& colour) {
      std::vector<std::pair<int, int>> at;
      const glm::ivec3 c = glm::ivec3(glm::round(colour * 255.0f));
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
          if (prt::test::PixelAt(image, x, y) == c) at.emplace_back(x, y);
      return at;
    };
    const auto line_a = pixels_of(im, a.color), line_b = pixels_of(im, b.color);
    CAPTURE(line_a.size());
    CAPTURE(line_b.size());
    REQUIRE(line_a.size() > 200);
    CHECK(line_b.size() > 0);               // b's legend entry
    CHECK(line_b.size() < line_a.size() / 2);  // but no line of its own
    // a's pixels (its legend swatch, a short horizontal line, aside) fall on one straight line
    // going down to the right: pixel y grows linearly with pixel x.
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, n = 0;
    for (const auto& [x, y] : line_a) {
      if (x > im.width * 3 / 4) continue;  // the legend is on the right
      sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y, sxy += double(x) * y, ++n;
    }
    const double correlation = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
    CHECK(correlation > 0.99);
    CHECK(Inked(im) > 2000);
    const prt::Image8 empty = prt::DrawLogLogPlot({}, o);
    CHECK(Inked(empty) > 0);  // axes even without data
    CHECK(pixels_of(empty, a.color).empty());
  }

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
}
