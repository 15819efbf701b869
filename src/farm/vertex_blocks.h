#pragma once
/// \file
/// A mesh's vertices cut into N blocks of whole, consecutive vertices, balanced by work: block i
/// holds the vertices whose running sum of work lies in [i W / N, (i + 1) W / N), W the total,
/// each block at least one vertex (where a vertex outweighs a block's share, its neighbours get
/// blocks of one). The caller gives each vertex's work in any whole unit: `prt precompute
/// --shard` gives every vertex 1, as every vertex casts the same directions there. The same
/// inputs give the same blocks on every machine (no floating point: whole numbers throughout).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "precompute/transport_types.h"

namespace prt {

/// The N + 1 bounds of the blocks: block i is [bounds[i], bounds[i + 1]); bounds[0] = 0,
/// bounds[N] = work.size(). Requires 1 <= count <= work.size() (Error otherwise).
std::vector<std::size_t> BlockBounds(const std::vector<std::uint64_t>& work, int count);

/// Block `index` of `count` as a VertexBlock.
VertexBlock BlockOf(const std::vector<std::uint64_t>& work, int index, int count);

}  // namespace prt
