#pragma once
/// \file
/// Timing that holds on a shared machine: the run times behind `prt report`.
///
/// Timing one configuration after another lets a burst of other work (a compiler, a browser,
/// CI's neighbours) land on a few configurations only: on 2 busy cores the quick report once
/// timed 64 directions at 0.047 s between 32 at 0.124 s and 128 at 0.121 s. Here every
/// configuration is timed in rounds, one sample of each per round (round robin [1]), so a burst
/// slows a round of all of them rather than some of them, and each configuration's samples are
/// summarised by their median and their range:
///   - a configuration runs once untimed first (warm caches and thread pool), and that run gives
///     its batch size: runs shorter than `min_sample_seconds` are repeated k times per sample
///     and the sample is the batch's time / k, so the clock's resolution plays no part;
///   - at least `min_rounds` rounds; then more, up to `max_rounds`, while some configuration's
///     spread (interquartile range / median) exceeds `spread_limit` and the extra rounds have
///     not yet cost `extra_budget` times what the first rounds took;
///   - the median is unmoved by a burst that hits fewer than half the rounds; the range
///     (min - max) is printed and plotted beside it, its minimum being the least disturbed
///     sample, since other work only ever adds time [2].
/// The clock is a parameter so tests can drive it with a fake one.
///
/// `CheckWorkOrder` then checks what must hold whatever the machine does: a configuration with
/// at least twice the work of another never takes less time beyond the spread, i.e. its
/// slowest sample is not below the other's fastest. When it fails, the times are not
/// trustworthy and the report says so instead of fitting slopes to them.
///
/// References
/// [1] Kalibera and Jones, "Rigorous Benchmarking in Reasonable Time", ISMM 2013 (repetition
///     across executions, randomised or interleaved order against drift and interference).
/// [2] Chen and Revels, "Robust benchmarking in noisy environments", HPEC 2016 (timing noise
///     from the environment is positive: it adds time, never removes it).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace prt {

/// Seconds from an arbitrary origin, increasing: the steady clock unless a test injects one.
using SecondsClock = std::function<double()>;
SecondsClock SteadySeconds();

struct RoundRobinPlan {
  int min_rounds = 5;
  int max_rounds = 9;
  double min_sample_seconds = 0.02;  ///< a shorter run is batched up to this
  int max_batch = 100000;            ///< at most this many runs per sample (microsecond runs need thousands)
  double spread_limit = 0.1;         ///< TimingStats::Spread above which more rounds help
  double extra_budget = 1.0;         ///< extra rounds may cost this times the first rounds
};

/// One configuration's summary: seconds per run.
struct TimingStats {
  double median = 0, min = 0, max = 0;
  double lower_quartile = 0, upper_quartile = 0;
  int samples = 0;  ///< rounds it was timed in
  int batch = 1;    ///< runs per sample
  /// (upper quartile - lower quartile) / median: how far the middle half of the samples spreads,
  /// 0 for identical samples. Not min - max, which one slow sample of an idle machine sets (a
  /// 2-core machine's idle quick report had min - max spreads of 8 to 55 %, nearly all from one
  /// sample each); the range printed and drawn is still min - max.
  double Spread() const { return median > 0 ? (upper_quartile - lower_quartile) / median : 0.0; }
};

/// The p-quantile (0..1) of `v`, interpolated between the neighbouring order statistics
/// (Hyndman and Fan's definition 7, R's default); 0 for none.
double Quantile(std::vector<double> v, double p);

/// Median of `v`: Quantile(v, 0.5), the mean of the middle two for an even count; 0 for none.
double Median(std::vector<double> v);

/// Times each of `runs` in round robin as above. `runs[i]` is one run of configuration i.
std::vector<TimingStats> TimeRoundRobin(const std::vector<std::function<void()>>& runs, const RoundRobinPlan& plan,
                                        const SecondsClock& clock = SteadySeconds());

/// A configuration in the work-order check: its group (only configurations of one group are
/// compared, e.g. one transport mode and sampler), its work and its timing.
struct TimedWork {
  std::string group, label;
  double work = 0;  ///< e.g. rays traced, or texels projected
  TimingStats time;
};

/// A pair that broke the order: `more` has at least twice the work of `less` yet its slowest
/// sample is faster than `less`'s fastest.
struct OrderViolation {
  std::string group, less, more;
  double less_min = 0, more_max = 0;
};

/// Every violating pair of `items` (none: the times follow the work).
std::vector<OrderViolation> CheckWorkOrder(const std::vector<TimedWork>& items);

}  // namespace prt
