// The report's timing (report/round_robin_timing.h) driven by a fake clock: each "run" only
// moves the clock on by the seconds the test scripts for it, so every figure is exact.
#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <vector>

#include "report/round_robin_timing.h"

namespace prt {
namespace {

/// A clock that only the runs move, and a record of which configuration ran when.
struct FakeMachine {
  double now = 0.0;
  std::vector<int> calls;  ///< configuration index of each run, in order
  /// Extra seconds added to every run made while the round counter is in [burst_from, burst_to):
  /// other work on the machine.
  double burst = 0.0;
  int burst_from = -1, burst_to = -1;
  int runs_seen = 0;
  /// Extra seconds of run k (counted over all configurations, warm-ups included), if listed.
  std::vector<double> extra;

  SecondsClock Clock() {
    return [this] { return now; };
  }
  /// Configuration i: each run takes `seconds[i]`, plus the burst while it lasts.
  std::vector<std::function<void()>> Runs(const std::vector<double>& seconds) {
    std::vector<std::function<void()>> runs;
    for (std::size_t i = 0; i < seconds.size(); ++i)
      runs.push_back([this, i, s = seconds[i]] {
        calls.push_back(static_cast<int>(i));
        const bool loaded = runs_seen >= burst_from && runs_seen < burst_to;
        now += s + (loaded ? burst : 0.0) + (std::size_t(runs_seen) < extra.size() ? extra[runs_seen] : 0.0);
        ++runs_seen;
      });
    return runs;
  }
};

TimingStats Stats(double median, double lo, double hi) {
  TimingStats t;
  t.median = median, t.min = lo, t.max = hi, t.samples = 5;
  return t;
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("round robin: configurations are interleaved, one sample each per round, after one untimed run each") {
    FakeMachine m;
    RoundRobinPlan plan;
    plan.min_sample_seconds = 0.0;  // no batching here
    const auto stats = TimeRoundRobin(m.Runs({0.5, 1.0, 2.0}), plan, m.Clock());
    // Warm-up 0 1 2, then rounds 0 1 2 | 0 1 2 ...: never two samples of one configuration in a row.
    REQUIRE(m.calls.size() == 3u * (1 + plan.min_rounds));
    for (std::size_t k = 0; k < m.calls.size(); ++k) CHECK(m.calls[k] == int(k % 3));
    // Identical runs: no spread, so no extra rounds.
    for (std::size_t i = 0; i < 3; ++i) {
      CHECK(stats[i].samples == plan.min_rounds);
      CHECK(stats[i].Spread() == 0.0);
    }
    CHECK(stats[0].median == 0.5);
    CHECK(stats[1].median == 1.0);
    CHECK(stats[2].median == 2.0);
  }

  TEST_CASE("round robin: a run shorter than the minimum sample is batched, and the sample is per run") {
    FakeMachine m;
    RoundRobinPlan plan;
    plan.min_sample_seconds = 0.02;
    const auto stats = TimeRoundRobin(m.Runs({0.004, 0.05}), plan, m.Clock());
    CHECK(stats[0].batch == 5);  // 5 x 4 ms reach 20 ms
    CHECK(stats[1].batch == 1);
    CHECK(stats[0].median == doctest::Approx(0.004));
    CHECK(stats[1].median == doctest::Approx(0.05));
    // Warm-up (1 + 1) and 5 rounds of (5 + 1) runs.
    CHECK(m.calls.size() == 2u + 5u * 6u);
  }

  TEST_CASE("round robin: a burst of other work moves the median of no configuration and shows in the range") {
    // The burst adds 1 s to every run of round 2 (runs 6..8 after the 3 warm-ups): all three
    // configurations get one slow sample, none is ranked out of order.
    FakeMachine m;
    m.burst = 1.0, m.burst_from = 3 + 2 * 3, m.burst_to = 3 + 3 * 3;
    RoundRobinPlan plan;
    plan.min_sample_seconds = 0.0;
    plan.max_rounds = plan.min_rounds;  // no extra rounds: the range must show the burst
    const auto stats = TimeRoundRobin(m.Runs({0.1, 0.2, 0.4}), plan, m.Clock());
    const double base[3] = {0.1, 0.2, 0.4};
    for (int i = 0; i < 3; ++i) {
      CAPTURE(i);
      CHECK(stats[i].median == doctest::Approx(base[i]));
      CHECK(stats[i].min == doctest::Approx(base[i]));
      CHECK(stats[i].max == doctest::Approx(base[i] + 1.0));
    }
  }

  TEST_CASE("round robin: a large spread earns extra rounds, within the budget") {
    FakeMachine m;
    m.burst = 1.0, m.burst_from = 2, m.burst_to = 6;  // runs 2..5: rounds 0 and 1 of both (after 2 warm-ups)
    RoundRobinPlan plan;
    plan.min_sample_seconds = 0.0;
    plan.min_rounds = 5, plan.max_rounds = 9;
    plan.extra_budget = 100.0;  // budget never binds here
    const auto stats = TimeRoundRobin(m.Runs({0.1, 0.1}), plan, m.Clock());
    // Two slow samples of five: the spread stays above the limit whatever follows, so every
    // allowed extra round is taken, and the median is the unloaded time.
    CHECK(stats[0].samples == plan.max_rounds);
    CHECK(stats[0].median == doctest::Approx(0.1));
    // With no budget for extra rounds, the first rounds are all.
    FakeMachine tight;
    tight.burst = 1.0, tight.burst_from = 2, tight.burst_to = 6;
    plan.extra_budget = 0.0;
    CHECK(TimeRoundRobin(tight.Runs({0.1, 0.1}), plan, tight.Clock())[0].samples == plan.min_rounds);
  }

  TEST_CASE("round robin: a configuration's time is the median of its samples, its range their min and max") {
    // One configuration, one warm-up, five samples of 0.1 s plus 0, 0.2, 0.1, 0.4, 0.1:
    // 0.1, 0.3, 0.2, 0.5, 0.2 -> median 0.2 (the mean would be 0.26, the fastest 0.1).
    FakeMachine m;
    m.extra = {0.0, 0.0, 0.2, 0.1, 0.4, 0.1};
    RoundRobinPlan plan;
    plan.min_sample_seconds = 0.0;
    plan.max_rounds = plan.min_rounds;
    const TimingStats t = TimeRoundRobin(m.Runs({0.1}), plan, m.Clock())[0];
    CHECK(t.samples == 5);
    CHECK(t.median == doctest::Approx(0.2));
    CHECK(t.min == doctest::Approx(0.1));
    CHECK(t.max == doctest::Approx(0.5));
    // The middle half: quartiles 0.2 and 0.3 (interpolated order statistics), so a spread of
    // (0.3 - 0.2) / 0.2, where one slow sample alone would make min - max 2.
    CHECK(t.lower_quartile == doctest::Approx(0.2));
    CHECK(t.upper_quartile == doctest::Approx(0.3));
    CHECK(t.Spread() == doctest::Approx(0.5));
  }

  TEST_CASE("median and quantiles: odd and even counts, interpolated between order statistics") {
    CHECK(Quantile({4.0, 1.0, 3.0, 2.0}, 0.25) == doctest::Approx(1.75));
    CHECK(Quantile({4.0, 1.0, 3.0, 2.0}, 0.75) == doctest::Approx(3.25));
    CHECK(Quantile({5.0}, 0.75) == 5.0);
    CHECK(Median({3.0, 1.0, 2.0}) == 2.0);
    CHECK(Median({4.0, 1.0, 3.0, 2.0}) == 2.5);
    CHECK(Median({}) == 0.0);
  }

  TEST_CASE("work order: twice the work faster beyond the spread is flagged, within the spread it is not") {
    // 32 directions at 0.124 s and 64 at 0.047 s (what a busy machine once printed) do not
    // overlap: flagged. 64 at 0.10-0.13 overlaps 32's 0.12-0.13: only noise, not flagged.
    const std::vector<TimedWork> busy = {{"shadowed fibonacci", "32", 32, Stats(0.124, 0.12, 0.13)},
                                         {"shadowed fibonacci", "64", 64, Stats(0.047, 0.045, 0.05)},
                                         {"shadowed fibonacci", "128", 128, Stats(0.121, 0.12, 0.125)}};
    const auto found = CheckWorkOrder(busy);
    REQUIRE(found.size() == 1);
    CHECK(found[0].less == "32");
    CHECK(found[0].more == "64");
    const std::vector<TimedWork> noisy = {{"g", "32", 32, Stats(0.124, 0.12, 0.13)},
                                          {"g", "64", 64, Stats(0.118, 0.10, 0.13)}};
    CHECK(CheckWorkOrder(noisy).empty());
    // Less than twice the work, or another group: never compared.
    CHECK(CheckWorkOrder({{"g", "32", 32, Stats(0.2, 0.2, 0.2)}, {"g", "48", 48, Stats(0.1, 0.1, 0.1)}}).empty());
    CHECK(CheckWorkOrder({{"a", "32", 32, Stats(0.2, 0.2, 0.2)}, {"b", "64", 64, Stats(0.1, 0.1, 0.1)}}).empty());
  }
}

}  // namespace prt
