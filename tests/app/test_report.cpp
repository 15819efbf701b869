// prt reference and prt report: the stability cases, the plot, and the files the commands write.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "app/report_auto_lmax.h"
#include "app/stability.h"
#include "env/procedural.h"
#include "core/atomic_file.h"
#include "raster/plot.h"
#include "tests/test_support.h"

namespace {

using prt::test::Q;

/// Count of pixels that are not pure white.
std::size_t Inked(const prt::Image8& im) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < im.rgb.size(); i += 3) n += (im.rgb[i] != 255 || im.rgb[i + 1] != 255 || im.rgb[i + 2] != 255);
  return n;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("stability: every stiff and extreme case passes and states its figure") {
    const auto cases = prt::RunStabilityCases();
    CHECK(cases.size() >= 16);
    for (const auto& c : cases) {
      INFO(c.name << ": " << c.figure << " (" << c.note << ")");
      CHECK(c.pass);
      CHECK(!c.checks.empty());
    }
    const std::string csv = prt::StabilityCsv(cases);
    CHECK(csv.find("rotation_36000_frames") != std::string::npos);
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
    prt::PlotSeries a{"a", {1e-3, 1e-2, 1e-1}, {1e-1, 1e-2, 1e-3}, prt::PlotColor(0), false};
    prt::PlotSeries b{"b", {0.0, 1e-2, 1.0}, {1.0, -1.0, 1e-2}, prt::PlotColor(1), true};
    prt::PlotOptions o;
    o.title = "t", o.x_label = "x", o.y_label = "y";
    const prt::Image8 im = prt::DrawLogLogPlot({a, b}, o);
    CHECK(im.width == o.width);
    CHECK(Inked(im) > 2000);
    const prt::Image8 empty = prt::DrawLogLogPlot({}, o);
    CHECK(Inked(empty) > 0);  // axes even without data
  }

  TEST_CASE("prt reference and prt report --stability write their files") {
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
    const auto stab = prt::test::RunPrt("report --stability --quiet --out " + Q(dir + "/stab"));
    CHECK(stab.exit_code == 0);
    CHECK(prt::ReadFile(dir + "/stab/stability.csv").find(",pass,") != std::string::npos);
    const auto bad = prt::test::RunPrt("report --quick");
    CHECK(bad.exit_code == 2);  // --out is required
  }
}
