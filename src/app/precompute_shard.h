#pragma once
/// \file
/// `prt precompute` as a farm job's parts: `--shard I/N`, one task, which computes the transport
/// of vertex block I of N (farm/vertex_blocks.h) and writes it as a shard file in the output
/// folder (precompute_io/transport_shard.h; interreflection one stage of its bounces,
/// precompute_io/bounce_shard.h); the command line a shard records; and the precompute that
/// `prt merge DIR` (cmd_merge.cpp) runs with the assembled transport, so that it writes what one
/// `prt precompute` writes there. Many tasks write one folder at once, so a task takes no lock
/// of it and writes nothing else there.

#include <optional>
#include <string>
#include <vector>

#include "app/scene_options.h"
#include "geometry/mesh.h"
#include "precompute/transport_types.h"
#include "farm/shard_id.h"
#include "options/args.h"
#include "sh_basis/scene_transport.h"

namespace prt {

/// A farm task's --shard and --bounce-stage, read and checked.
struct ShardTask {
  ShardId shard;
  std::optional<int> stage;  ///< --bounce-stage
};

/// The table entries of --shard (its file `file`, after which the merge `merged`) and
/// --bounce-stage.
std::vector<OptionSpec> ShardOptions(const std::string& file, const std::string& merged);

/// Reads --shard and --bounce-stage: nullopt without --shard; a usage error for a malformed
/// value, --bounce-stage without --shard or without interreflection or past the last bounce,
/// and --shard with interreflection of a glossy material, or with a basis whose transport does
/// not split into blocks.
std::optional<ShardTask> ReadShardTask(Args& args, const SceneOptions& options);

/// Computes and writes shard `shard` of the transport `options` ask for into `out`; `command`
/// is the precompute's command line without --shard, recorded in the shard for the merge.
/// Interreflection runs the next stage of its bounces (the direct pass first), or `stage` when
/// given (--bounce-stage: prt farm's chain), which succeeds with nothing to do once merged.
/// Returns the exit code.
int RunPrecomputeShard(const SceneOptions& options, const ShardId& shard, const std::string& out,
                       const std::vector<std::string>& command, std::optional<int> stage = std::nullopt);

/// `prt precompute` with the command line `tokens`, its transport `sharded`'s when given (the
/// merge of a farm job's shards) instead of computed. Returns the exit code. `check_only`, with
/// a --shard among `tokens`: the options are checked as a task would check them (a refusal
/// thrown as its task would), nothing loaded or written (`prt farm`, before it submits).
int Precompute(const std::vector<std::string>& tokens, const ShardedTransport& sharded, bool check_only = false);

/// Interreflection's next stage for the block of `shard` (precompute/bounce_stages.h) of the
/// transport `topts` of `mesh`: the direct pass with its hits when no merge has assembled one
/// yet, else the bounce after the last one assembled (the bounce state in `out`), nothing once
/// the bounces have ended; `given` the stage --bounce-stage names. Blocks of equal vertex count.
/// Returns the exit code.
int RunBounceStage(const Mesh& mesh, const TransportOptions& topts, const std::string& cache, const ShardId& shard,
                   const std::string& out, const std::vector<std::string>& command, std::optional<int> given);

/// The command line a shard records for the merge: the command's `name`, then `tokens` without --shard, --bounce-stage,
/// --threads and --quiet (each as `--name VALUE` or `--name=VALUE`), which change nothing in
/// what is written: the tasks of one job may run on machines of any size. The paths of --mesh,
/// --env, --texture, --cache and --out are made absolute, so that the merge runs from any folder
/// and `./scene.obj` is the same command as `scene.obj`.
std::vector<std::string> ShardCommand(const std::string& name, const std::vector<std::string>& tokens);

}  // namespace prt
