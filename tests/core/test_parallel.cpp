#include <doctest/doctest.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel.h"
#include "tests/test_support.h"

TEST_SUITE("core") {
  TEST_CASE("WithThreads and ThreadCountScope set the pool's threads for their scope, and give all cores back after it, after a throw too") {
    prt::SetThreadCount(0);
    const int all = prt::ThreadCount();
    // Counts other than all cores, so that a scope that gave nothing back would show.
    const int some = all + 1, more = all + 2;
    CHECK(prt::test::WithThreads(some, [] { return prt::ThreadCount(); }) == some);
    CHECK(prt::ThreadCount() == all);
    CHECK_THROWS_AS(prt::test::WithThreads(more, []() -> int { throw std::runtime_error("thrown inside"); }),
                    std::runtime_error);
    CHECK(prt::ThreadCount() == all);
    {
      const prt::test::ThreadCountScope scope(more);
      CHECK(prt::ThreadCount() == more);
    }
    CHECK(prt::ThreadCount() == all);
  }

  TEST_CASE("ParallelFor visits every index exactly once, for any thread count") {
    for (int threads : {1, 2, 7}) {
      prt::SetThreadCount(threads);
      std::vector<std::atomic<int>> hits(1013);
      prt::ParallelFor(hits.size(), 10, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) hits[i]++;
      });
      for (auto& h : hits) CHECK(h.load() == 1);
    }
    prt::SetThreadCount(0);
  }

  TEST_CASE("ParallelFor rethrows the first exception of a body") {
    prt::SetThreadCount(2);
    CHECK_THROWS_AS(prt::ParallelFor(100, 1,
                                     [](std::size_t b, std::size_t) {
                                       if (b == 50) throw std::runtime_error("boom");
                                     }),
                    std::runtime_error);
    prt::SetThreadCount(0);
  }

  TEST_CASE("ParallelFor inside a body, and from two threads at once, still visits every index once") {
    // The kept threads serve one call at a time; nested and concurrent calls must neither
    // deadlock nor lose chunks. Repeated, so that calls meet the threads in every state.
    prt::SetThreadCount(3);
    for (int round = 0; round < 50; ++round) {
      std::vector<std::atomic<int>> hits(40 * 37);
      prt::ParallelFor(40, 1, [&](std::size_t b, std::size_t) {
        prt::ParallelFor(37, 5, [&](std::size_t ib, std::size_t ie) {
          for (std::size_t i = ib; i < ie; ++i) hits[b * 37 + i]++;
        });
      });
      std::vector<std::atomic<int>> a(997), c(991);
      const auto count = [](std::vector<std::atomic<int>>& v) {
        prt::ParallelFor(v.size(), 7, [&](std::size_t b, std::size_t e) {
          for (std::size_t i = b; i < e; ++i) v[i]++;
        });
      };
      std::thread other([&] { count(a); });
      count(c);
      other.join();
      int wrong = 0;
      for (auto* v : {&hits, &a, &c})
        for (auto& h : *v) wrong += h.load() != 1;
      REQUIRE(wrong == 0);
    }
    prt::SetThreadCount(0);
  }

  TEST_CASE("ChunkCount matches the chunks ParallelFor makes") {
    CHECK(prt::ChunkCount(0, 8) == 0);
    CHECK(prt::ChunkCount(8, 8) == 1);
    CHECK(prt::ChunkCount(9, 8) == 2);
  }
}
