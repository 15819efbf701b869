#pragma once
/// \file
/// Bounding volume hierarchy over the triangles of a mesh: a binary tree of axis-aligned boxes
/// stored as two flat arrays, 32-byte nodes and triangle indices (madmann91/bvh, tinybvh style).
///
/// Build: binned surface area heuristic [1, 2]. A split of a node into children L and R is
/// worth its expected cost  C_trav + (A(L) N(L) + A(R) N(R)) / A(node) * C_isect  (A = box
/// surface area, the probability that a ray through the node also crosses the child, N the
/// triangle count rounded up to whole blocks of eight, which traversal tests at once);
/// candidate planes are the borders of `bins` equal bins of the centroids' box on each axis.
/// The builder sees only triangle boxes and centroids. Counting blocks instead of triangles
/// fills the blocks: 94 % of their lanes hold distinct triangles on the knot, against 69 %.
///
/// Below a depth of 96 a node that SAH cannot split is halved at the median centroid of its
/// longest axis, so leaves never exceed max_leaf_size and the depth stays below 128.
///
/// Traversal runs on an 8-wide tree collapsed from the binary one (`bvh_wide.h`,
/// `bvh_wide_traverse.h`), with the robust slab test of [3] (the far distance is enlarged by
/// 2 gamma(3) so rounding never culls a box the ray truly touches; on AVX2 a fused test on
/// padded boxes) and the watertight triangle test of `triangle.h` on eight triangles at once.
/// Each traversal is compiled for AVX-512, AVX2 and the baseline, chosen per CPU
/// (`bvh_kernels.h`). The fans (`ray_fan.h`) use per-direction constants computed once, and
/// trace packets of 32 neighbouring directions, occlusion and closest hit alike
/// (`bvh_packet_traverse.h`), with the single rays' answers.
///
/// References
///  [1] J. D. MacDonald, K. S. Booth, "Heuristics for ray tracing using space subdivision",
///      The Visual Computer 6, 1990.
///  [2] I. Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", IEEE
///      Symposium on Interactive Ray Tracing, 2007 (binning).
///  [3] T. Ize, "Robust BVH Ray Traversal", Journal of Computer Graphics Techniques 2(2), 2013.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/bvh_wide.h"
#include "geometry/mesh.h"
#include "geometry/ray.h"

namespace prt {

struct RayFan;

/// Options of the BVH build; the defaults suit meshes of 1e3-1e6 triangles.
struct BvhOptions {
  int bins = 16;                  ///< SAH candidate planes per axis are bin borders
  int max_leaf_size = 8;          ///< a larger binary node is always split (clamped to 1..64)
  float traversal_cost = 1.0f;    ///< C_trav: cost of visiting a node (binary and wide)
  /// C_isect: cost of one triangle slot of a block, so a block of eight costs 8 C_isect (also
  /// the C_block of the collapse, bvh_wide.h): a block test costs about two node visits.
  /// Measured on the PRT workload (knot, 1 thread, occlusion, side by side in one process):
  /// block costs of 1, 2 and 4 node visits, and binary leaves of 8 or 16, are within 1 % of
  /// each other.
  float intersection_cost = 0.25f;
};

/// One node in 32 bytes. Interior (count == 0): children are nodes[index] and nodes[index + 1].
/// Leaf (count > 0): triangles prim_indices[index .. index + count).
struct BvhNode {
  glm::vec3 lo;
  std::uint32_t index;
  glm::vec3 hi;
  std::uint32_t count;
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes");

class Bvh {
 public:
  /// Builds over all triangles of `mesh` (which may be dropped afterwards: corner positions are
  /// copied in leaf order). An empty mesh gives an empty tree that nothing hits.
  static Bvh Build(const Mesh& mesh, const BvhOptions& options = {});

  /// True if the ray hits any triangle with t in (ray.tmin, ray.tmax) (any-hit, stops early).
  bool Occluded(const Ray& ray) const;

  /// The closest hit with t in (ray.tmin, ray.tmax), or nothing.
  std::optional<Hit> Intersect(const Ray& ray) const;

  /// Fan of occlusion rays from one origin: for each direction i of `fan` with
  /// dot(normal, d_i) > 0, occluded[i] = 1 if the ray origin + t d_i, t in (0, tmax), hits a
  /// triangle, else 0; directions at or below the horizon get 0 and are not traced.
  /// `occluded` is resized to the fan's size. Same answers as Occluded() on each ray.
  void OccludedFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                   std::vector<std::uint8_t>& occluded) const;

  /// Fan of closest-hit rays, as OccludedFan: hits[i] is Intersect() of ray i (nothing for
  /// directions at or below the horizon and for misses). `hits` is resized to the fan's size.
  void IntersectFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal,
                    float tmax, std::vector<std::optional<Hit>>& hits) const;

  const std::vector<BvhNode>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& prim_indices() const { return prim_indices_; }
  /// The 8-wide tree collapsed from nodes(), which every traversal runs on.
  const WideBvh& wide() const { return wide_; }
  /// Largest side of the root box (0 if empty): the `scene_scale` of OffsetRayOrigin.
  float SceneScale() const;

 private:
  std::vector<BvhNode> nodes_;                         // nodes_[0] is the root
  std::vector<std::uint32_t> prim_indices_;            // triangle ids in leaf order
  WideBvh wide_;                                       // what traversal runs on (bvh_wide.h)
};

/// Surface area of a box, 0 for an empty one.
float BoxArea(const glm::vec3& lo, const glm::vec3& hi);

}  // namespace prt
