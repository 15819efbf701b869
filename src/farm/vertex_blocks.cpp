#include "farm/vertex_blocks.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace prt {

std::vector<std::size_t> BlockBounds(const std::vector<std::uint64_t>& work, int count) {
  const std::size_t n = work.size();
  if (count < 1 || std::size_t(count) > n)
    throw Error("--shard: " + std::to_string(count) + " shards for " + std::to_string(n) +
                " vertices (expected at most one shard per vertex)");
  std::vector<std::uint64_t> prefix(n + 1, 0);  // prefix[v]: the work of the vertices before v
  for (std::size_t v = 0; v < n; ++v) prefix[v + 1] = prefix[v] + work[v];
  const std::uint64_t total = prefix[n];
  std::vector<std::size_t> bounds(std::size_t(count) + 1, 0);
  bounds[std::size_t(count)] = n;
  for (int i = 1; i < count; ++i) {
    // The first vertex whose work starts at or past i W / N: ceil(i W / N), with W = q N + r, as
    // q i + ceil(r i / N), so that no product outgrows 64 bits (r i < N^2 < 10^10).
    const std::uint64_t shares = std::uint64_t(count), q = total / shares, r = total % shares;
    const std::uint64_t target = q * std::uint64_t(i) + (r * std::uint64_t(i) + shares - 1) / shares;
    std::size_t b = static_cast<std::size_t>(std::lower_bound(prefix.begin(), prefix.end(), target) - prefix.begin());
    // Every block at least one vertex, and room left for the blocks after it.
    b = std::max(b, bounds[std::size_t(i) - 1] + 1);
    b = std::min(b, n - std::size_t(count - i));
    bounds[std::size_t(i)] = b;
  }
  return bounds;
}

VertexBlock BlockOf(const std::vector<std::uint64_t>& work, int index, int count) {
  const std::vector<std::size_t> bounds = BlockBounds(work, count);
  VertexBlock block;
  block.begin = bounds.at(std::size_t(index));
  block.end = bounds.at(std::size_t(index) + 1);
  return block;
}

}  // namespace prt
