// How report.md, report.csv and error_vs_time.png carry the sweep's times
// (report/report_time_plot.h, report/report_write.h): trusted times give slopes against seconds
// and a seconds axis; a work-order violation or a wide spread puts a warning at the top, leaves
// the slopes out and plots rays instead. Made-up rows, so every figure is known.
#include <doctest/doctest.h>

#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/output_folder.h"
#include "report/report_time_plot.h"
#include "report/report_write.h"
#include "tests/test_support.h"

namespace prt {
namespace {

/// Samples whose middle half spans `spread` of the median (TimingStats::Spread) and whose
/// range spans twice that.
TimingStats Time(double median, double spread) {
  TimingStats t;
  t.median = median, t.samples = 5;
  t.lower_quartile = median * (1 - spread / 2), t.upper_quartile = median * (1 + spread / 2);
  t.min = median * (1 - spread), t.max = median * (1 + spread);
  return t;
}

/// Shadowed, two samplers, 16..64 directions, lmax 1..2, timed at lmax 2: time proportional to
/// the directions, 10% spread (20% range); error falling as 1/sqrt(directions).
ReportData Sweep() {
  ReportData d;
  d.scene = "synthetic", d.environment = "sky", d.vertices = 100, d.max_lmax = 2;
  d.timed_configurations = 6;
  for (const char* sampler : {"uniform", "fibonacci"})
    for (int n : {16, 32, 64})
      for (int lmax : {1, 2}) {
        SweepRow r;
        r.mode = "shadowed", r.sampler = sampler, r.samples = r.directions = n, r.lmax = lmax, r.timed_lmax = 2;
        r.time = Time(1e-3 * n, 0.1);
        r.rays = 50u * n;
        r.basis_evaluations = 7u * n;
        r.sampling = {0.1, 0.2, 0.5 / std::sqrt(double(n))};
        r.total = {0.1, 0.2, 0.05 + 0.5 / std::sqrt(double(n))};
        d.rows.push_back(r);
      }
  ModeBaseline b;
  b.mode = "shadowed", b.converged_samples = 4096, b.converged_self_error = 1e-4;
  d.baselines.push_back(b);
  return d;
}

std::string WrittenMarkdown(const ReportData& d, const std::string& name, std::string* csv = nullptr) {
  const std::string dir = test::ScratchDir(name);
  {
    OutputFolder folder(dir, OutputPlan{"report", {"report.md", "report.csv", "error_vs_time.png"}, false});
    WriteReport(folder, d);
    folder.Finish();
  }
  if (csv) *csv = ReadFile(dir + "/report.csv");
  return ReadFile(dir + "/report.md");
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("report timing: trusted times give slopes against seconds and a seconds axis with ranges") {
    const ReportData d = Sweep();
    REQUIRE(TimesTrusted(d));
    std::string csv;
    const std::string md = WrittenMarkdown(d, "timing_trusted", &csv);
    CHECK(md.find("not trustworthy") == std::string::npos);
    CHECK(md.find("## Timing") != std::string::npos);
    CHECK(md.find("left out") == std::string::npos);
    // Time proportional to the directions, error ~ directions^-1/2 (the sampling error): slope
    // -0.5 against both.
    CHECK(md.find("| shadowed | fibonacci | -0.50 | -0.50 |") != std::string::npos);
    // The median and its range, as TimeWithRange writes them.
    CHECK(TimeWithRange(Time(0.016, 0.1)) == "0.016 s (0.0144-0.0176)");

    const auto series = ErrorVsTimeSeries(d, "shadowed", TimesTrusted(d));
    REQUIRE(series.size() == 4);  // 2 samplers x 2 lmax
    std::set<int> markers;
    for (const PlotSeries& s : series) {
      CAPTURE(s.label);
      const bool lmax1 = s.label.find("lmax 1") != std::string::npos;
      CHECK(s.hollow == lmax1);  // lmax 1's time is the lmax 2 run's
      markers.insert(int(s.marker));
      REQUIRE(s.x.size() == 3);
      REQUIRE(s.x_min.size() == 3);
      CHECK(s.x[2] == doctest::Approx(0.064));
      CHECK(s.x_min[2] == doctest::Approx(0.064 * 0.9));
      CHECK(s.x_max[2] == doctest::Approx(0.064 * 1.1));
    }
    CHECK(markers.size() == 2);                       // the samplers' shapes differ
    CHECK(series[0].color != series[1].color);        // and the lmax's colours

    // Interreflection too: one panel per sampled mode, stacked.
    const Image8 one = ErrorVsTimePlot(d);
    ReportData both = d;
    for (SweepRow r : d.rows) {
      r.mode = "interreflection";
      both.rows.push_back(r);
    }
    const Image8 two = ErrorVsTimePlot(both);
    CHECK(two.width == one.width);
    CHECK(two.height == 2 * one.height);
    CHECK(ErrorVsTimeSeries(both, "interreflection", true).size() == 4);

    // report.csv: the timing columns last, with the run's own figures, on every sweep row.
    std::istringstream lines(csv);
    std::string header, row;
    std::getline(lines, header);
    std::getline(lines, row);
    const auto names = test::CsvFields(header), values = test::CsvFields(row);
    REQUIRE(names.size() == values.size());
    const auto at = [&](const std::string& name) {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return values[i];
      FAIL("no column " << name);
      return std::string();
    };
    CHECK(std::stod(at("seconds")) == doctest::Approx(0.016));
    CHECK(std::stod(at("seconds_min")) == doctest::Approx(0.0144));
    CHECK(std::stod(at("seconds_max")) == doctest::Approx(0.0176));
    CHECK(at("timing_samples") == "5");
    CHECK(at("timed_lmax") == "2");
    CHECK(at("rays") == "800");
    CHECK(at("basis_evaluations") == "112");
  }

  TEST_CASE("report timing: twice the work faster beyond the spread: a warning at the top, no slopes, rays plotted") {
    ReportData d = Sweep();
    // 64 fibonacci directions measured at a third of 32's time, ranges apart: a busy machine.
    std::vector<TimedWork> order;
    for (SweepRow& r : d.rows) {
      if (r.sampler == std::string("fibonacci") && r.directions == 64) r.time = Time(0.010, 0.1);
      if (r.lmax == r.timed_lmax)
        order.push_back({r.mode + " " + r.sampler, std::to_string(r.directions), double(r.rays), r.time});
    }
    d.order_violations = CheckWorkOrder(order);
    REQUIRE(d.order_violations.size() == 2);  // 64 against 16 (0.016 s) and against 32
    CHECK(!TimesTrusted(d));
    const std::string md = WrittenMarkdown(d, "timing_order");
    const auto warning = md.find("**The times of this run are not trustworthy**");
    REQUIRE(warning != std::string::npos);
    CHECK(warning < md.find("## Timing"));  // at the top
    CHECK(md.find("**2 pairs out of order**") != std::string::npos);
    CHECK(md.find("| shadowed | fibonacci | left out (times untrusted) | -0.50 |") != std::string::npos);
    CHECK(md.find("| shadowed | uniform | left out (times untrusted) |") != std::string::npos);
    const auto series = ErrorVsTimeSeries(d, "shadowed", TimesTrusted(d));
    REQUIRE(!series.empty());
    CHECK(series[0].x == std::vector<double>{800, 1600, 3200});  // rays, not seconds
    CHECK(series[0].x_min.empty());
  }

  TEST_CASE("report timing: a spread above the trusted limit also withdraws the slopes, and is named") {
    ReportData d = Sweep();
    for (SweepRow& r : d.rows)
      if (r.sampler == std::string("uniform") && r.directions == 32) r.time = Time(0.032, kTrustedSpread + 0.1);
    CHECK(d.order_violations.empty());
    CHECK(!TimesTrusted(d));
    const auto [spread, whose] = LargestSpread(d);
    CHECK(spread == doctest::Approx(kTrustedSpread + 0.1));
    CHECK(whose == "shadowed uniform 32 directions");
    const std::string md = WrittenMarkdown(d, "timing_spread");
    CHECK(md.find("not trustworthy") != std::string::npos);
    CHECK(md.find("shadowed uniform 32 directions") != std::string::npos);
    CHECK(md.find("left out (times untrusted)") != std::string::npos);
  }

}

}  // namespace prt
