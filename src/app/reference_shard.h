#pragma once
/// \file
/// `prt reference` as a farm job's parts: `--shard I/N`, one task, which computes the reference
/// (precompute/reference.h) of vertex block I of N and writes it as a shard file in the output
/// folder (precompute_io/reference_shard.h); and the reference that `prt merge DIR` runs with
/// the assembled shards (farm/assemble_reference.h), which writes reference.txt and
/// reference.png as one run does. Every vertex of a reference traces the same number of paths,
/// so the blocks are of equal count (farm/vertex_blocks.h). Each vertex's random streams depend
/// on its index alone, so a block's numbers are the whole run's to the bit.

#include <cstdint>
#include <string>
#include <vector>

#include "env/environment.h"
#include "farm/assemble_reference.h"
#include "geometry/mesh.h"
#include "precompute/reference.h"

namespace prt {

/// What a reference depends on, hashed: the mesh (as the transport cache's key hashes it), the
/// environment's texels (env/environment_hash.h) and every option of `options` but its block.
/// The shards of one job share it; the merge checks it against what it loads.
std::uint64_t ReferenceKey(const Mesh& mesh, const Environment& env, const ReferenceOptions& options);

/// `prt reference` with the command line `tokens`; with `assembled` (the merge of a farm job's
/// shards) its numbers in place of computing them. `check_only`: the options are checked as a
/// task checks them, nothing loaded or written (`prt farm`). Returns the exit code.
int ReferenceCommand(const std::vector<std::string>& tokens, const AssembledReference* assembled,
                     bool check_only = false);

}  // namespace prt
