// A render's shards are balanced by work (app/render_shard.h): a vertex the frames show weighs
// --samples, a hidden one --hidden-samples, and with unshadowed transport every vertex the same;
// the blocks cut from these weights give the seen vertices smaller blocks.
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "app/render_shard.h"
#include "farm/vertex_blocks.h"

namespace prt {

TEST_SUITE("app") {
TEST_CASE("render shard work: seen vertices weigh --samples, hidden ones --hidden-samples, unshadowed all one") {
  TransportOptions o;
  o.mode = TransportMode::kShadowed;
  o.samples = 1024;
  o.hidden_samples = 64;
  o.seen = {1, 0, 0, 1};
  CHECK(RenderVertexWork(o, 4) == std::vector<std::uint64_t>{1024, 64, 64, 1024});
  // No camera split (every vertex seen, or no hidden count): every vertex --samples.
  o.seen.clear();
  CHECK(RenderVertexWork(o, 3) == std::vector<std::uint64_t>{1024, 1024, 1024});
  o.seen = {0, 1};
  o.hidden_samples = 0;
  CHECK(RenderVertexWork(o, 2) == std::vector<std::uint64_t>{1024, 1024});
  o.mode = TransportMode::kUnshadowed;  // the closed form: no rays
  o.hidden_samples = 64;
  CHECK(RenderVertexWork(o, 2) == std::vector<std::uint64_t>{1, 1});
  // Eight seen vertices then eight hidden ones, in two blocks of equal work: the first block
  // ends early among the seen (8 x 1024 + 8 x 64 = 8704; half of it, 4352, is 4.25 seen vertices).
  o.mode = TransportMode::kShadowed;
  o.seen = std::vector<std::uint8_t>(16, 0);
  for (int v = 0; v < 8; ++v) o.seen[v] = 1;
  const VertexBlock first = BlockOf(RenderVertexWork(o, 16), 0, 2);
  CHECK(first.begin == 0);
  CHECK(first.end == 5);
}
}  // TEST_SUITE

}  // namespace prt
