// The time left a progress bar shows: elapsed * (1 - f) / f, rounded up, in the units a person
// reads, and nothing before the rate means anything or once the work is done.
#include <doctest/doctest.h>

#include <limits>

#include "core/progress.h"

TEST_SUITE("core") {
  TEST_CASE("TimeLeft extrapolates the average rate and rounds up") {
    CHECK(prt::TimeLeft(0.5, 10.0) == "10 s left");
    CHECK(prt::TimeLeft(0.25, 10.0) == "30 s left");
    CHECK(prt::TimeLeft(0.9, 0.01) == "1 s left");  // 0.0011 s: never "0 s" before the end
    CHECK(prt::TimeLeft(0.1, 10.0) == "1 min 30 s left");
    CHECK(prt::TimeLeft(0.05, 600.0) == "3 h 10 min left");  // 11400 s
  }

  TEST_CASE("TimeLeft says nothing too early, when done, or for nonsense") {
    CHECK(prt::TimeLeft(0.0, 5.0).empty());
    CHECK(prt::TimeLeft(0.5 * prt::kTimeLeftFraction, 5.0).empty());
    CHECK_FALSE(prt::TimeLeft(prt::kTimeLeftFraction, 5.0).empty());
    CHECK(prt::TimeLeft(1.0, 5.0).empty());
    CHECK(prt::TimeLeft(std::numeric_limits<double>::quiet_NaN(), 5.0).empty());
    CHECK(prt::TimeLeft(0.5, -1.0).empty());
  }

  TEST_CASE("LatestProgress: the newest bar's label and fraction, whether drawn or not, until it ends") {
    {
      prt::Progress outer("outer work", 4);
      outer.Advance(1);
      prt::ProgressReading r = prt::LatestProgress();
      CHECK(r.active);
      CHECK(r.label == "outer work");
      CHECK(r.fraction == 0.25);
      {
        prt::Progress inner("inner work", 10);
        inner.Advance(3);
        outer.Advance(1);  // an older bar does not take the reading back
        r = prt::LatestProgress();
        CHECK(r.label == "inner work");
        CHECK(r.fraction == doctest::Approx(0.3).epsilon(1e-12));
        inner.Advance(20);
        CHECK(prt::LatestProgress().fraction == 1.0);  // never past the whole
      }
      CHECK_FALSE(prt::LatestProgress().active);  // the newest ended
    }
    CHECK_FALSE(prt::LatestProgress().active);
    prt::Progress last("last", 8);
    last.Advance(8);
    CHECK(prt::LatestProgress().fraction == 1.0);
    CHECK(prt::LatestProgress().active);
  }
}
