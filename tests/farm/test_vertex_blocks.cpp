// A mesh's vertices in N blocks (farm/vertex_blocks.h): whole, consecutive, every vertex in one,
// none empty, and balanced by work: each block's work within one vertex's work of W / N.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/error.h"
#include "core/rng.h"
#include "farm/vertex_blocks.h"
#include "tests/test_support.h"

namespace prt {

TEST_SUITE("farm") {
TEST_CASE("vertex blocks: consecutive, covering, none empty; equal work gives counts within one") {
  const std::vector<std::uint64_t> equal(241, 64);
  for (int n : {1, 2, 3, 7, 16, 240, 241}) {
    CAPTURE(n);
    const std::vector<std::size_t> b = BlockBounds(equal, n);
    REQUIRE(b.size() == std::size_t(n) + 1);
    CHECK(b.front() == 0);
    CHECK(b.back() == 241);
    std::size_t least = 241, most = 0;
    for (int i = 0; i < n; ++i) {
      CHECK(b[i] < b[i + 1]);
      least = std::min(least, b[i + 1] - b[i]);
      most = std::max(most, b[i + 1] - b[i]);
    }
    CHECK(most - least <= 1);
    const VertexBlock last = BlockOf(equal, n - 1, n);
    CHECK(last.begin == b[n - 1]);
    CHECK(last.end == 241);
  }
  CHECK(test::ErrorMessage([&] { BlockBounds(equal, 242); }).find("at most one shard per vertex") != std::string::npos);
  CHECK(test::ErrorMessage([&] { BlockBounds(equal, 0); }).find("0 shards") != std::string::npos);
}

TEST_CASE("vertex blocks: balanced by work, not by count: each block's work within one vertex's of W / N") {
  // The first tenth of the vertices cost 16 times the rest (seen vertices casting more rays).
  std::vector<std::uint64_t> work(1000, 64);
  for (std::size_t v = 0; v < 100; ++v) work[v] = 1024;
  Pcg32 rng(7, 1);
  for (std::size_t v = 500; v < 1000; ++v) work[v] = 1 + rng.NextU32() % 200;
  const std::uint64_t total = std::accumulate(work.begin(), work.end(), std::uint64_t(0));
  const std::uint64_t heaviest = *std::max_element(work.begin(), work.end());
  for (int n : {2, 4, 16, 64}) {
    CAPTURE(n);
    const std::vector<std::size_t> b = BlockBounds(work, n);
    for (int i = 0; i < n; ++i) {
      const std::uint64_t w = std::accumulate(work.begin() + std::ptrdiff_t(b[i]), work.begin() + std::ptrdiff_t(b[i + 1]),
                                              std::uint64_t(0));
      CAPTURE(i);
      CHECK(double(w) <= double(total) / n + double(heaviest));
      CHECK(double(w) >= double(total) / n - double(heaviest));
    }
  }
  // By count alone the first of 4 blocks would end at vertex 250, past all 100 heavy ones; by
  // work it ends among them.
  CHECK(BlockBounds(work, 4)[1] < 100);
}

}  // TEST_SUITE

}  // namespace prt
