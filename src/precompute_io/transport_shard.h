#pragma once
/// \file
/// One shard of a farm job's transport (farm/): the rows of one block of whole vertices, with
/// what a merge needs to know they belong together. Layout, little-endian:
///
///   header   "PRTSHARD", version, lmax, channels, parts (1 glossy, 2 matrices), index, count,
///            the whole mesh's vertex count, the block's first and end vertex, the whole run's
///            cache key (precompute_io/transport_cache.h, TransportKey), the length of the
///            command line, and an FNV-1a checksum of the whole file (the header with this
///            field 0, then the rest)
///   command  the command line that made it, its words separated by NUL, without --shard
///   rows     coeffs, then glossy, then matrices: the block's rows of each, laid out as in
///            Transport (precompute/transport_types.h)
///
/// Written to a temporary name and renamed when whole (core/atomic_file.h): a task killed while
/// writing leaves no file by the shard's name. The name says which shard it is,
/// `<cache name>.shard-00003-of-00016`, so that two tasks given the same index write one file.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "precompute/transport_types.h"

namespace prt {

struct TransportShard {
  int index = 0;
  int count = 1;
  std::uint64_t key = 0;            ///< the whole run's TransportKey
  std::vector<std::string> command;  ///< the words of the command that made it, without --shard
  VertexBlock block;
  /// lmax, channels, material, and `vertices` the whole mesh's count; coeffs, glossy and matrices
  /// hold the block's rows only.
  Transport rows;
};

/// `<cache_name>.shard-IIIII-of-NNNNN`.
std::string ShardFileName(const std::string& cache_name, int index, int count);
/// True when `name` is a shard file name of `cache_name` (index and count then set).
bool IsShardFileName(const std::string& name, const std::string& cache_name, int& index, int& count);

/// A shard's command line as stored: its words separated by NUL, and back.
std::string JoinShardCommand(const std::vector<std::string>& words);
std::vector<std::string> SplitShardCommand(const std::string& joined);

/// The block's rows of `whole` (a transport computed for `block`, every other row 0).
Transport BlockRows(const Transport& whole, const VertexBlock& block);

void WriteTransportShard(const std::string& path, const TransportShard& shard);

/// The shard at `path`, or nullopt with `why` (truncated, corrupted, not a shard, ...).
std::optional<TransportShard> ReadTransportShard(const std::string& path, std::string& why);

}  // namespace prt
