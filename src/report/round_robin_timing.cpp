#include "report/round_robin_timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace prt {

SecondsClock SteadySeconds() {
  return [] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  };
}

double Quantile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double at = std::clamp(p, 0.0, 1.0) * double(v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(at);
  return i + 1 < v.size() ? v[i] + (at - double(i)) * (v[i + 1] - v[i]) : v[i];
}

double Median(std::vector<double> v) { return Quantile(std::move(v), 0.5); }

std::vector<TimingStats> TimeRoundRobin(const std::vector<std::function<void()>>& runs, const RoundRobinPlan& plan,
                                        const SecondsClock& clock) {
  const std::size_t n = runs.size();
  std::vector<TimingStats> stats(n);
  std::vector<std::vector<double>> samples(n);
  // The untimed first run of each: warm-up, and the batch that makes a sample long enough.
  for (std::size_t i = 0; i < n; ++i) {
    const double t0 = clock();
    runs[i]();
    const double once = clock() - t0;
    const double need = plan.min_sample_seconds / std::max(once, 1e-9);
    stats[i].batch = std::clamp(static_cast<int>(std::ceil(need)), 1, std::max(1, plan.max_batch));
  }
  const auto round = [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const double t0 = clock();
      for (int k = 0; k < stats[i].batch; ++k) runs[i]();
      samples[i].push_back((clock() - t0) / stats[i].batch);
    }
  };
  const auto summarise = [&] {
    for (std::size_t i = 0; i < n; ++i) {
      const auto [lo, hi] = std::minmax_element(samples[i].begin(), samples[i].end());
      stats[i].median = Median(samples[i]);
      stats[i].min = *lo, stats[i].max = *hi;
      stats[i].lower_quartile = Quantile(samples[i], 0.25), stats[i].upper_quartile = Quantile(samples[i], 0.75);
      stats[i].samples = static_cast<int>(samples[i].size());
    }
  };
  if (n == 0) return stats;
  const double start = clock();
  int rounds = 0;
  for (; rounds < std::max(1, plan.min_rounds); ++rounds) round();
  const double first = clock() - start;
  summarise();
  const auto noisy = [&] {
    return std::any_of(stats.begin(), stats.end(), [&](const TimingStats& s) { return s.Spread() > plan.spread_limit; });
  };
  const double extra_start = clock();
  while (rounds < plan.max_rounds && noisy() && clock() - extra_start < plan.extra_budget * first) {
    round();
    ++rounds;
    summarise();
  }
  return stats;
}

std::vector<OrderViolation> CheckWorkOrder(const std::vector<TimedWork>& items) {
  std::vector<OrderViolation> found;
  for (const TimedWork& less : items)
    for (const TimedWork& more : items)
      if (&less != &more && less.group == more.group && less.work > 0 && more.work >= 2.0 * less.work &&
          more.time.max < less.time.min)
        found.push_back({less.group, less.label, more.label, less.time.min, more.time.max});
  return found;
}

}  // namespace prt
