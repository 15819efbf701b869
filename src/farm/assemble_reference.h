#pragma once
/// \file
/// The shards of one farm job's reference (precompute_io/reference_shard.h) checked and put
/// together as one run computes the reference: the same rules as a transport's
/// (farm/assemble_shards.h: every shard whole, made by the same command with the same key, of
/// one count N, each index 0..N-1 once, their blocks covering the mesh's vertices in order), a
/// refusal naming the file and its fault (Error) before anything is assembled.

#include <cstdint>
#include <string>
#include <vector>

#include "precompute/reference.h"

namespace prt {

struct AssembledReference {
  std::vector<std::string> command;  ///< the command every shard was made by, without --shard
  std::uint64_t key = 0;
  int count = 0;
  std::vector<std::string> files;  ///< the shard files, in index order
  Reference reference;             ///< every vertex's radiance and error, the rays, the RMS figures
};

/// Assembles the reference shards in `dir`; Error when there are none or any is refused.
AssembledReference AssembleReference(const std::string& dir);

}  // namespace prt
