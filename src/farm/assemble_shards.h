#pragma once
/// \file
/// The shards of one farm job (precompute_io/transport_shard.h) checked and assembled into the
/// transport one run on one machine computes: every shard file of the basis's cache in a folder
/// must be whole, made by the same command for the same mesh and options (the same cache key),
/// and of one count N, with each index 0..N-1 present exactly once and their blocks covering
/// the mesh's vertices in order. A missing, damaged, renamed or foreign shard is refused with
/// its name and reason (Error) before anything is assembled.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "precompute/transport_types.h"

namespace prt {

struct AssembledShards {
  std::vector<std::string> command;  ///< the command every shard was made by, without --shard
  std::uint64_t key = 0;             ///< the whole run's cache key
  int count = 0;
  std::vector<std::string> files;    ///< the shard files, in index order
  Transport transport;               ///< every vertex's rows, as one run computes them
};

/// The shard files of `cache_name` in `dir` by index: every one of a count N present once (Error
/// naming the folder and what is missing, or a second job's count, otherwise).
std::map<int, std::string> ShardFiles(const std::string& dir, const std::string& cache_name);

/// Assembles the shards of the cache `cache_name` in `dir`; Error when there are none or any
/// is refused.
AssembledShards AssembleShards(const std::string& dir, const std::string& cache_name);

}  // namespace prt
