#pragma once
/// \file
/// Interreflection as a farm job (precompute/bounce_stages.h): the shards of one stage checked
/// and assembled as farm/assemble_shards.h does a transport's, and merged into the bounce state
/// the way the one-machine run adds its bounces (precompute/transport_bounce.h, AddBounces):
/// stage 0 makes bounce 0 of every vertex from their direct transfer, stage k adds bounce k, and
/// the bounces end after --bounces of them, or early when one adds less than the tolerance's
/// share of the direct energy, or at once when no vertex of the output sees a lit surface.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "precompute/transport_types.h"
#include "precompute_io/bounce_shard.h"

namespace prt {

/// One stage's shards, checked and put together: the first shard's description with every
/// block's rows in order.
struct AssembledStage {
  BounceShard first;               ///< shard 0, its rows and hits dropped
  std::vector<double> rows;        ///< every vertex's rows
  std::uint64_t front_hits = 0;    ///< stage 0: summed over the shards
  std::vector<std::string> files;  ///< the shard files, in index order
};

/// Assembles stage `stage` of the cache `cache_name` in `dir`; Error naming the file and its
/// fault when a shard is missing, damaged, renamed or of another job or stage.
AssembledStage AssembleStage(const std::string& dir, const std::string& cache_name, int stage);

/// The state once `stage` is merged into `before` (nullopt at stage 0): Error when the stage is
/// not the one after `before`'s, or of another job.
BounceState MergeStage(const std::optional<BounceState>& before, const AssembledStage& stage);

/// The transport of the output's vertices from a finished state, as the one-machine run returns
/// it (floats, the mesh's own vertices).
Transport BouncedTransport(const BounceState& state, int lmax);

}  // namespace prt
