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
#include "farm/shard_id.h"
#include "sh_basis/scene_transport.h"

namespace prt {

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

/// The command line a shard records for the merge: `tokens` without --shard, --bounce-stage,
/// --threads and --quiet (each as `--name VALUE` or `--name=VALUE`), which change nothing in
/// what is written: the tasks of one job may run on machines of any size. The paths of --mesh,
/// --env, --texture, --cache and --out are made absolute, so that the merge runs from any folder
/// and `./scene.obj` is the same command as `scene.obj`.
std::vector<std::string> ShardCommand(const std::vector<std::string>& tokens);

}  // namespace prt
