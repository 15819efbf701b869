#pragma once
/// \file
/// Interreflected transport in stages, for a farm job whose tasks each hold one block of the
/// vertices (farm/): stage 0 is the direct pass of a block, with the hits it records; stage k
/// is bounce k of a block, gathered from bounce k - 1 of every vertex, which a merge assembled.
/// Each stage runs the code of the one-machine run (transport.h, transport_bounce.h) on the same
/// mesh (the senders split as bounce_senders.h splits them) and the same direction plan, so a
/// block's rows are that run's to the bit. What needs every vertex (bounce 0 for all of them,
/// the energies that stop the bounces early) is the merge's, in the same order as that run.

#include <cstdint>
#include <vector>

#include "geometry/mesh.h"
#include "precompute/direction_pool.h"
#include "precompute/transport_direct.h"
#include "precompute/transport_types.h"

namespace prt {

/// The mesh the bounces run on and its directions, as the one-machine run makes them.
struct BounceScene {
  Mesh mesh;                  ///< the senders split (bounce_senders.h), or the mesh as given
  std::size_t own = 0;        ///< the given mesh's vertices, first in `mesh`: the output's
  TransportOptions options;   ///< the options, `seen` sized for `mesh`
  DirectionPlan plan;
  int channels = 1;           ///< 3 with coloured albedo (transport_types.h, TransportChannels)
  int count = 1;              ///< coefficients a vector
};

/// The bounce scene of `mesh` and `options` (mode interreflection, diffuse).
BounceScene MakeBounceScene(const Mesh& mesh, const TransportOptions& options);

/// Stage 0: the direct transfer of `block`'s vertices of the scene's mesh, with their hits.
DirectResult DirectStage(const BounceScene& scene, const VertexBlock& block);

}  // namespace prt
