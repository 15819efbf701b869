// The sample rule as users meet it (precompute/sample_rule.h): without --samples a high lmax
// casts the rule's count, an explicit --samples below the rule's minimum is one warning naming
// both numbers and the option (said before any work, the run still done), and `prt report`
// tabulates the rule's evidence.
#include <doctest/doctest.h>

#include <cmath>

#include <regex>
#include <string>

#include "core/atomic_file.h"
#include "precompute/sample_rule.h"
#include "tests/test_process.h"

namespace prt {
namespace {

using test::Q;

/// A small run of `prt render` at `lmax` with `extra` options: one frame of a quad.
test::RunResult RenderAt(const std::string& name, int lmax, const std::string& extra) {
  const std::string dir = test::ScratchDir(name);
  return test::RunPrt("render --mesh " + Q(test::Fixture("obj/quad.obj")) + " --env furnace --lmax " +
                      std::to_string(lmax) + " --frames 1 --size 16x16 --cache none --out " + Q(dir + "/out") + " " +
                      extra);
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("sample rule: without --samples a high lmax casts the rule's count, not 1024") {
    const int lmax = 12;
    const int expected = DefaultSamples(lmax, Sampler::kFibonacci);
    REQUIRE(expected > 1024);  // otherwise this test could not tell the rule from the old default
    const auto r = RenderAt("rule_default", lmax, "");
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find(std::to_string(expected) + " fibonacci directions per vertex") != std::string::npos);
    CHECK(r.err.find("prt: warning: --samples") == std::string::npos);
    // The sampler enters the rule: stratified asks more at the same lmax.
    const auto s = RenderAt("rule_default_stratified", lmax, "--sampler stratified");
    const int stratified = DefaultSamples(lmax, Sampler::kStratified);
    REQUIRE(stratified != expected);
    const int side = static_cast<int>(std::sqrt(double(stratified)));  // the grid uses floor(sqrt(N))^2
    CHECK(s.err.find(std::to_string(side * side) + " stratified directions per vertex") != std::string::npos);
  }

  TEST_CASE("sample rule: precompute has no camera: one count at every vertex, said without one") {
    // With interreflection the bounce pass adds sender vertices that no camera sees (a large
    // triangle's subdivision, bounce_senders.h): their own count must not make the line speak
    // of a camera, as it did ("for each of the 4 vertices the camera sees, 4096 for the 0 it does
    // not").
    const int lmax = 12;
    const int expected = DefaultSamples(lmax, Sampler::kFibonacci);
    for (const char* transport : {"shadowed", "interreflection"}) {
      CAPTURE(transport);
      const std::string dir = test::ScratchDir(std::string("rule_precompute_") + transport);
      const auto r = test::RunPrt("precompute --mesh " + Q(test::Fixture("obj/quad.obj")) + " --env furnace --lmax " +
                                  std::to_string(lmax) + " --transport " + transport + " --cache none --out " +
                                  Q(dir + "/out"));
      CAPTURE(r.err);
      REQUIRE(r.exit_code == 0);
      const std::size_t at = r.err.find("transport: ");
      REQUIRE(at != std::string::npos);
      const std::string line = r.err.substr(at, r.err.find('\n', at) - at);
      CHECK(line.find(std::to_string(expected) + " fibonacci directions per vertex") != std::string::npos);
      CHECK(line.find("the camera sees") == std::string::npos);
      CHECK(line.find("it does not") == std::string::npos);
      // The rule in the words of a run without a camera: every vertex takes the same count.
      CHECK(line.find("every vertex takes") != std::string::npos);
      CHECK(line.find("for those it sees") == std::string::npos);
    }
    // The rule's words give the count: at lmax 16, the first above the floor, its multiplier
    // times the minimum is what every vertex took.
    {
      const int high = 16, count = DefaultSamples(high, Sampler::kFibonacci);
      REQUIRE(count > kDefaultFloor);
      const auto r = test::RunPrt("precompute --mesh " + Q(test::Fixture("obj/quad.obj")) + " --env furnace --lmax " +
                                  std::to_string(high) + " --transport shadowed --cache none --out " + Q(test::ScratchDir("rule_precompute_16")));
      REQUIRE(r.exit_code == 0);
      std::smatch m;
      REQUIRE(std::regex_search(r.err, m, std::regex("every vertex takes ([0-9]+) times that, at least ([0-9]+)")));
      CHECK(std::stoi(m[1]) * MinimumSamples(high, Sampler::kFibonacci) == count);
      CHECK(std::stoi(m[2]) == kDefaultFloor);
      CHECK(r.err.find(std::to_string(count) + " fibonacci directions per vertex") != std::string::npos);
    }
    // A render whose camera sees every vertex of the quad: one count too, in the rule's words
    // for a camera.
    const auto render = RenderAt("rule_all_seen", lmax, "--transport interreflection");
    REQUIRE(render.exit_code == 0);
    CHECK(render.err.find(std::to_string(expected) + " fibonacci directions per vertex") != std::string::npos);
    CHECK(render.err.find("it does not") == std::string::npos);
    CHECK(render.err.find("for those it sees") != std::string::npos);
  }

  TEST_CASE("sample rule: an explicit --samples below the minimum warns once, naming both counts") {
    const int lmax = 12;
    const int minimum = MinimumSamples(lmax, Sampler::kFibonacci);
    const auto low = RenderAt("rule_low", lmax, "--samples " + std::to_string(minimum / 2));
    CAPTURE(low.err);
    CHECK(low.exit_code == 0);  // a warning, not a refusal
    CHECK(Count(low.err, "prt: warning: --samples " + std::to_string(minimum / 2) + " is below the " +
                             std::to_string(minimum)) == 1);
    CHECK(low.err.find("prt: warning: --samples") < low.err.find("transport: "));  // before the work
    CHECK(low.err.find(std::to_string(minimum / 2) + " fibonacci directions per vertex") != std::string::npos);
    // Enough directions, or a transport without rays: no warning.
    CHECK(RenderAt("rule_enough", lmax, "--samples " + std::to_string(minimum)).err.find("prt: warning") ==
          std::string::npos);
    CHECK(RenderAt("rule_unshadowed", lmax, "--transport unshadowed --samples 16").err.find("prt: warning") ==
          std::string::npos);
  }
}

// A test of `prt report`, in its suite.
TEST_SUITE("report") {
  TEST_CASE("sample rule: prt report tabulates the sampling error against the truncation error and the rule") {
    const std::string dir = test::ScratchDir("rule_report");
    const auto r = test::RunPrt("report --quick --max-lmax 3 --max-samples 64 --quiet" + test::SmallSceneOption("rule_report_scene") +
                                " --out " + Q(dir));
    REQUIRE(r.exit_code == 0);
    const std::string md = ReadFile(dir + "/report.md");
    const auto section = md.find("## Directions needed for the bands: the sample rule");
    REQUIRE(section != std::string::npos);
    CHECK(md.find("How to read the tables", section) != std::string::npos);
    CHECK(md.find("| lmax | truncation | 16 | 32 | 64 | measured need | rule min | rule default |", section) !=
          std::string::npos);
    // One row per lmax of the sweep, with the rule's values for it, for each sampler.
    for (const char* sampler : {"fibonacci", "stratified", "uniform"}) {
      CAPTURE(sampler);
      const auto table = md.find(std::string("shadowed, ") + sampler + " (rule: ", section);
      REQUIRE(table != std::string::npos);
      const Sampler s = SamplerFromName(sampler);
      const std::string row3 = " | " + std::to_string(MinimumSamples(3, s)) + " | " +
                               std::to_string(DefaultSamples(3, s)) + " |\n";
      CHECK(md.find("\n| 3 | ", table) != std::string::npos);
      CHECK(md.find(row3, table) != std::string::npos);
    }
  }
}

}  // namespace prt
