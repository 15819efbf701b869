#pragma once
/// \file
/// `prt render` as a farm job's parts: `--shard I/N`, one task, which computes vertex block I of
/// N of the transport the render would compute (its camera's seen vertices, its glossy view or
/// transfer matrices: the basis's ComputeBlock, basis/basis.h) and writes it as a shard file in
/// the output folder (precompute_io/transport_shard.h; interreflection one stage of its bounces,
/// app/precompute_shard.h); and the render that `prt merge DIR` runs with the assembled
/// transport, which writes what one `prt render` writes there. The blocks are balanced by work:
/// a vertex the frames show casts --samples directions, one they do not --hidden-samples (the
/// closed form of unshadowed transport costs each vertex the same). Like a precompute's, a
/// render's task takes no lock of the folder and writes nothing else there.

#include <string>
#include <vector>

#include "app/render_args.h"
#include "app/scene_options.h"
#include "farm/shard_id.h"
#include "precompute/transport_types.h"

namespace prt {

/// Computes and writes shard `shard` of the transport `scene` and `job` ask for into job.out;
/// `command` (ShardCommand) is recorded for the merge; `stage` as RunBounceStage's. Returns the
/// exit code.
int RunRenderShard(const SceneOptions& scene, const RenderJobOptions& job, const ShardId& shard,
                   const std::vector<std::string>& command, std::optional<int> stage);

/// Each vertex's work in a render's transport (the blocks' balance): `samples` for the vertices
/// `topts.seen` marks (all when it is empty), `hidden_samples` (or `samples` when 0) for the
/// others; 1 each for unshadowed transport.
std::vector<std::uint64_t> RenderVertexWork(const TransportOptions& topts, std::size_t vertices);

/// `prt render` with the command line `tokens`, its transport `sharded`'s when given (the merge
/// of a farm job's shards). `check_only`, with a --shard among `tokens`: the options are checked
/// as a task would check them, nothing loaded or written (`prt farm`, before it submits).
/// Returns the exit code.
int Render(const std::vector<std::string>& tokens, const ShardedTransport& sharded, bool check_only = false);

}  // namespace prt
