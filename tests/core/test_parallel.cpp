#include <doctest/doctest.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "core/parallel.h"

TEST_SUITE("core") {
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

  TEST_CASE("ChunkCount matches the chunks ParallelFor makes") {
    CHECK(prt::ChunkCount(0, 8) == 0);
    CHECK(prt::ChunkCount(8, 8) == 1);
    CHECK(prt::ChunkCount(9, 8) == 2);
  }
}
