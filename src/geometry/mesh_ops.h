#pragma once
/// \file
/// Small operations on `Mesh` shared by the procedural builders and the OBJ loader: bounds,
/// appending one mesh to another, a uniform albedo, and smooth vertex normals.
///
/// References
///  [1] G. Thürmer, C. A. Wüthrich, "Computing vertex normals from polygonal facets",
///      Journal of Graphics Tools 3(1), 1998 (angle-weighted normals).
///  [2] S. Jin, R. R. Lewis, D. West, "A comparison of algorithms for vertex normal computation",
///      The Visual Computer 21, 2005 (area and angle weights compared).

#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace prt {

/// Albedo of meshes that do not say otherwise (procedural meshes, OBJ files without usable
/// materials): 0.8 grey, like mary.mtl's Kd.
inline constexpr float kDefaultAlbedo = 0.8f;

/// Axis-aligned bounding box of a set of points; empty when lo > hi.
struct Bounds3 {
  glm::vec3 lo{1e30f};
  glm::vec3 hi{-1e30f};
  /// Grows the box to contain p.
  void Extend(const glm::vec3& p);
  /// Largest side length (0 for an empty box).
  float MaxExtent() const;
};

/// Bounds of all vertex positions of `mesh`.
Bounds3 MeshBounds(const Mesh& mesh);

/// Appends `src` to `dst`: vertices after dst's, triangle indices shifted accordingly. A textured
/// `src` needs an empty or textured `dst` (its texture indices are shifted after dst's).
void AppendMesh(Mesh& dst, const Mesh& src);

/// Sets every vertex albedo to `albedo` (linear RGB), e.g. for `--albedo`; drops any textures.
void SetUniformAlbedo(Mesh& mesh, const glm::vec3& albedo);

/// Twice the area of triangle `t` (|e1 x e2|), in world units squared.
float TriangleDoubleArea(const Mesh& mesh, std::size_t t);

/// Smooth vertex normals: each triangle adds its unit face normal weighted by its area times
/// the corner angle at the vertex [1, 2], so a vertex's normal does not depend on how a flat
/// region around it is split into triangles, and large faces count more than slivers.
/// Vertices touched by no non-degenerate triangle get (0, 0, 1).
/// Returns one unit normal per vertex.
std::vector<glm::vec3> SmoothNormals(const Mesh& mesh);

/// Applies the affine map p -> scale * p + offset to positions (normals are unchanged, so
/// `scale` must be positive).
void TransformMesh(Mesh& mesh, float scale, const glm::vec3& offset);

}  // namespace prt
