#pragma once
/// \file
/// The SH transport of a scene as the commands use it: from its cache (precompute_io/
/// transport_cache.h) when it was made from the same mesh and options, else computed
/// (precompute/transport.h) and cached, said on the run summary; the memory its transfer
/// matrices would take, checked before any work; and those matrices compressed by clustered PCA.

#include <cstdint>
#include <vector>

#include "basis/cache_plan.h"
#include "cpca/cpca_transfer.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "raster/camera.h"

namespace prt {

/// The options ComputeSceneTransport computes with: `options` with the eye of `camera` for a
/// glossy fixed view, or the transfer matrices for a glossy moving one (`matrices`).
TransportOptions SceneTransportOptions(const TransportOptions& options, const Camera* camera, bool matrices);

/// The transport of `mesh` for `options` in the basis `sh` (sh_basis.h): read from the cache when that file was made from the
/// same mesh and options, else computed (and written there when the plan allows; a failed write
/// is a warning). Warns when most vertices see no light at all (an inside-out or enclosed mesh).
/// A glossy material gets its view-dependent transfer toward `camera`'s eye (required then).
/// With `matrices`, a glossy material gets transfer matrices instead (any view). `options.seen`
/// marks the vertices the camera sees in some frame (render/seen_vertices.h; empty: all): they
/// take --samples directions, the others --hidden-samples. `samples_from_rule`: the direction
/// count is the sample rule's default, which the summary line says. With `sharded`, the
/// transport is the one its shards assembled (Error when they were made from another mesh or
/// options than `mesh` and `options`), taken and cached as a computed one.
Transport ComputeSceneTransport(const Basis& sh, const Mesh& mesh, const TransportOptions& options, bool samples_from_rule,
                                const CachePlan& cache, const Camera* camera = nullptr, bool matrices = false,
                                const ShardedTransport& sharded = {});

/// Says on the run summary what the transfer matrices of `mesh` at `lmax` will take, and throws
/// Error, naming the largest lmax that fits, when that is more than the memory available allows.
void CheckMatrixMemory(const Mesh& mesh, TransportMode mode, int lmax);

/// `transport`'s matrices compressed by clustered PCA into `clusters` clusters of `terms` terms
/// (cpca/cpca_transfer.h; fewer clusters where the mesh has fewer than clusters x (terms + 1)
/// matrices, so that the model stays smaller than them), said on the run summary with the
/// memory, the relative error measured on this mesh and the time; the full matrices are then
/// released from `transport`.
CpcaTransfer CompressSceneMatrices(Transport& transport, int clusters, int terms);

}  // namespace prt
