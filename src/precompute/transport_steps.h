#pragma once
/// \file
/// The two steps of shadowed and interreflected transport (see transport.h for the maths):
/// direct transfer with visibility, then the bounces. Internal to precompute/.

#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/bvh.h"
#include "geometry/mesh.h"
#include "precompute/direction_pool.h"
#include "precompute/transport.h"

namespace prt {

/// Does the ray along `dir` hit the lit (front) side of the surface it hit? Decided by the hit
/// triangle's plane, oriented by the sum of its vertex normals (transport_direct.cpp).
bool FrontSide(const Mesh& mesh, const Hit& hit, const glm::vec3& dir);

/// Adds `scale` times the light a hit point sends out as a diffuse surface, per light
/// coefficient: albedo(h) T(h) for channel c, T barycentric over the hit triangle (u, v) from
/// `transfer` laid out [(vertex * channels + c) * count + k], the albedo barycentric too, or
/// `*albedo` when given (a textured mesh's, HitAlbedo, looked up once for the three channels).
/// The gather of every bounce.
void AddHitLight(const Mesh& mesh, std::uint32_t triangle, float u, float v, const std::vector<double>& transfer,
                 int channels, int count, int c, double scale, double* out, const glm::vec3* albedo = nullptr);

/// A blocked direction of a vertex and what it hit (kept for the bounces).
struct VertexHit {
  std::uint32_t triangle;
  float u, v;          ///< barycentrics of the hit point
  std::uint32_t dir;   ///< index into the vertex's direction set
  bool front;          ///< hit the lit (front) side of the surface
};

/// A textured mesh's albedo at the hit at barycentrics (u, v) of `triangle`, one ray of
/// `directions` from `vertex`: the texture filtered over the patch of surface the ray stands for
/// (geometry/mesh_texture.h, RayFootprint).
glm::vec3 HitAlbedo(const Mesh& mesh, std::size_t vertex, std::uint32_t triangle, float u, float v,
                    std::size_t directions);

struct DirectResult {
  std::vector<double> transfer;                ///< [v * count + k]
  std::vector<std::vector<VertexHit>> hits;    ///< per vertex (only when asked for)
  std::vector<std::uint8_t> sees_sky;          ///< per vertex: some direction above it is open
  std::vector<std::uint8_t> unoccluded;        ///< per vertex: nothing blocked (the closed form)
  std::uint64_t rays = 0;
  /// Directions whose basis was evaluated ((lmax+1)^2 values each): the blocked ones, or a
  /// whole set at once where its table is built.
  std::uint64_t basis_evaluations = 0;
};

/// Shadowed transfer of every vertex (control-variate estimator), each from the set of its pool
/// in `plan`. With `keep_hits`, traces closest hits instead of any-hit rays and records them
/// (VertexHit::dir indexes the vertex's set).
DirectResult ComputeDirect(const Mesh& mesh, const Bvh& bvh, const DirectionPlan& plan, int lmax, bool keep_hits);

struct BounceResult {
  int channels = 1;
  std::vector<double> transfer;  ///< [(v * channels + c) * count + k], direct + all bounces
  /// The same without the last bounce computed (what a glossy receiver gathers from a diffuse
  /// hit point: its light through bounce B - 1); filled only when asked for.
  std::vector<double> before_last;
};

/// The transfer matrices of every vertex into transport.matrices (transfer_matrix.h), from the
/// blocked directions and hits `direct` recorded (null: unshadowed, no pool); `hit_transfer`
/// (BounceResult::before_last, transport.channels channels) with interreflection, else null.
void ComputeTransferMatrices(const Mesh& mesh, const DirectionPlan* plan, const DirectResult* direct, int lmax,
                             const std::vector<double>* hit_transfer, Transport& transport);

/// Adds up to options.bounces bounces to `direct`; records each bounce's share in `report`.
/// None when none of the first `counted` vertices (the output's; the rest only send light,
/// bounce_senders.h) sees a lit surface: their bounces would all be zero.
BounceResult AddBounces(const Mesh& mesh, const DirectionPlan& plan, const DirectResult& direct,
                        const TransportOptions& options, TransportReport& report, bool keep_before_last = false,
                        std::size_t counted = std::numeric_limits<std::size_t>::max());

/// The glossy transfer G of every vertex (transport.h) for options.material seen from
/// options.eye; `hit_transfer` (layout of BounceResult::transfer with `channels`) is what hit
/// points send out with interreflection, null otherwise. Null `bvh`: unshadowed.
std::vector<double> ComputeGlossy(const Mesh& mesh, const Bvh* bvh, const TransportOptions& options,
                                  const std::vector<double>* hit_transfer, int channels, TransportReport& report);

}  // namespace prt
