#pragma once
/// \file
/// Which shard of a farm job this run computes: `--shard I/N` (0-based I of N), or `--shard auto`
/// read from the scheduler's environment, as a task of a job array finds it:
///
///   Slurm job arrays    SLURM_ARRAY_TASK_ID, with SLURM_ARRAY_TASK_COUNT, or the array's
///                       SLURM_ARRAY_TASK_MIN and _MAX (index = ID - MIN, count = MAX - MIN + 1;
///                       an array with a step, 0-15:2, has no count that fits and is refused)
///   Kubernetes Indexed  JOB_COMPLETION_INDEX, with the count given: `--shard auto/N`
///   Jobs
///
/// `auto/N` takes the index from either and the count from N (refused when Slurm's own count
/// says otherwise). The result says where it came from, for the run summary.

#include <functional>
#include <string>

namespace prt {

struct ShardId {
  int index = 0;
  int count = 1;
  std::string source;  ///< how it was found, e.g. "--shard 2/5" or "SLURM_ARRAY_TASK_ID=2 of ..."
};

/// The most shards a job may have: their file names hold the index and count in five digits
/// (precompute_io/transport_shard.h).
inline constexpr int kMaxShards = 99999;

/// The environment as the parser reads it (std::getenv by default; tests give their own).
using EnvLookup = std::function<const char*(const char*)>;

/// Reads `--shard`'s value; throws Error naming the option or variable and what was expected.
ShardId ParseShard(const std::string& value, const EnvLookup& env);
ShardId ParseShard(const std::string& value);

}  // namespace prt
