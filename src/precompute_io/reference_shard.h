#pragma once
/// \file
/// One shard of a farm job's reference (`prt reference --shard I/N`): the per-vertex radiance
/// and own error (precompute/reference.h) of one block of whole vertices, in doubles, the bits
/// one run computes. Layout, little-endian:
///
///   header   "PRTREFSH", version, index, count, the whole mesh's vertex count, the block's
///            first and end vertex, the whole run's key (app/reference_shard.h: the mesh, the
///            environment's texels and the reference's options), the rays traced, the length of
///            the command line, and an FNV-1a checksum of the whole file (the header with this
///            field 0, then the rest)
///   command  the command line that made it, its words separated by NUL, without --shard
///   rows     per vertex of the block: radiance R G B, then error R G B
///
/// Named `reference.shard-IIIII-of-NNNNN` (ShardFileName) and written to a temporary name
/// renamed when whole (core/atomic_file.h), as transport shards are.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "precompute/transport_types.h"

namespace prt {

/// The name the shard files share before `.shard-IIIII-of-NNNNN`.
inline constexpr const char* kReferenceShardBase = "reference";

struct ReferenceShard {
  int index = 0;
  int count = 1;
  std::uint64_t key = 0;
  std::vector<std::string> command;  ///< the words of the command that made it, without --shard
  VertexBlock block;
  std::size_t vertices = 0;          ///< the whole mesh's
  std::uint64_t rays = 0;            ///< traced for the block
  std::vector<glm::dvec3> radiance;  ///< the block's vertices only
  std::vector<glm::dvec3> error;
};

void WriteReferenceShard(const std::string& path, const ReferenceShard& shard);

/// The shard at `path`, or nullopt with `why` (truncated, corrupted, not a reference shard, ...).
std::optional<ReferenceShard> ReadReferenceShard(const std::string& path, std::string& why);

}  // namespace prt
