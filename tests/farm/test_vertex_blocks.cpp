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

TEST_CASE("vertex blocks: each vertex in the block its running sum of work falls in, none empty beside a heavy vertex") {
  // The rule of vertex_blocks.h: vertex v is in block i when i W / N <= (work before v) <
  // (i + 1) W / N, checked exactly with whole numbers (N x sum against i x W), wherever no block
  // can be empty (W / N at least the heaviest vertex). The weights: equal, growing, random.
  Pcg32 rng(11, 2);
  std::vector<std::vector<std::uint64_t>> cases = {std::vector<std::uint64_t>(10, 3), {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}};
  std::vector<std::uint64_t> random(97);
  for (auto& w : random) w = 1 + rng.NextU32() % 1000;
  cases.push_back(random);
  for (const auto& work : cases) {
    const std::uint64_t total = std::accumulate(work.begin(), work.end(), std::uint64_t(0));
    const std::uint64_t heaviest = *std::max_element(work.begin(), work.end());
    for (int n : {2, 3, 5, 7}) {
      CAPTURE(n);
      if (total < std::uint64_t(n) * heaviest) continue;  // a block could be empty: the clamps below
      const std::vector<std::size_t> b = BlockBounds(work, n);
      std::uint64_t before = 0;
      for (int i = 0, v = 0; i < n; ++i)
        for (; std::size_t(v) < b[i + 1]; before += work[v], ++v) {
          CAPTURE(v);
          CHECK(std::uint64_t(n) * before >= std::uint64_t(i) * total);
          CHECK(std::uint64_t(n) * before < std::uint64_t(i + 1) * total);
        }
    }
  }
  // A vertex heavier than a block's share: the rule would leave blocks empty, and each gets one
  // vertex instead, before it and after it.
  for (const auto& work : {std::vector<std::uint64_t>{1000, 1, 1, 1}, std::vector<std::uint64_t>{1, 1, 1, 1000},
                           std::vector<std::uint64_t>{1, 1000, 1, 1, 1}}) {
    for (int n = 1; n <= int(work.size()); ++n) {
      CAPTURE(n);
      const std::vector<std::size_t> b = BlockBounds(work, n);
      REQUIRE(b.size() == std::size_t(n) + 1);
      CHECK(b.front() == 0);
      CHECK(b.back() == work.size());
      for (int i = 0; i < n; ++i) CHECK(b[i] < b[i + 1]);
    }
  }
}
}  // TEST_SUITE

}  // namespace prt
