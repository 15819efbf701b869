// BackgroundJobs: the limit on jobs in flight, errors, and waiting for everything.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "core/background_jobs.h"

TEST_SUITE("core") {
  TEST_CASE("BackgroundJobs never runs more than its limit at once, and runs every job") {
    for (int limit : {1, 3}) {
      std::atomic<int> running{0}, most{0}, done{0};
      {
        prt::BackgroundJobs jobs(limit);
        for (int i = 0; i < 12; ++i)
          jobs.Submit([&] {
            const int now = ++running;
            int seen = most.load();
            while (now > seen && !most.compare_exchange_weak(seen, now)) {}
            std::this_thread::sleep_for(std::chrono::milliseconds(5));  // lets jobs overlap
            --running;
            ++done;
          });
        jobs.Wait();
        CHECK(done == 12);
      }
      CHECK(most.load() <= limit);
      CHECK(most.load() >= 1);
    }
  }

  TEST_CASE("BackgroundJobs rethrows a job's error from Submit or Wait") {
    prt::BackgroundJobs one(1);
    one.Submit([] { throw std::runtime_error("disk full"); });
    CHECK_THROWS_WITH(one.Submit([] {}), "disk full");  // waits for the failed job first
    one.Wait();
    prt::BackgroundJobs two(2);
    two.Submit([] {});
    two.Submit([] { throw std::runtime_error("late"); });
    CHECK_THROWS_WITH(two.Wait(), "late");
  }
}
