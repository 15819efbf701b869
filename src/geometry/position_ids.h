#pragma once
/// \file
/// Exact-position identity of vertices, and the position edges between them: the connectivity
/// of the surface as drawn, whatever the file's vertex welding did.
///
/// Vertices are welded by the file's (position, normal) pairs (weld.h), so a crease, a hard edge
/// or a texture seam leaves several vertices at one position, and two triangles across it share
/// no vertex index although they share an edge. Adjacency questions (is the mesh closed? which
/// triangles touch?) must therefore be asked of positions: vertices whose three coordinates are
/// bit-identical get one id (+0 and -0 count as equal). Nothing is merged within a tolerance:
/// that is welding's job, and a surface that only nearly meets is open.
///
/// A position edge is an unordered pair of position ids. In a closed, consistently oriented
/// (oriented 2-manifold) surface every position edge is used by exactly two triangles, once in
/// each direction [1, ch. 2].
///
/// References
///  [1] M. Botsch, L. Kobbelt, M. Pauly, P. Alliez, B. Lévy, "Polygon Mesh Processing",
///      A K Peters, 2010 (ch. 2: mesh data structures, manifolds and orientation).
///  [2] D. E. Knuth, "The Art of Computer Programming", vol. 3, 2nd ed., Addison-Wesley, 1998
///      (sec. 6.4: hashing with open addressing and linear probing).

#include <cstdint>
#include <vector>

#include "geometry/mesh.h"

namespace prt {

/// One id per vertex of `mesh`: vertices with bit-identical positions share it. Ids are
/// numbered 0, 1, ... in order of first appearance in `mesh.positions`, so they depend only on
/// the input. Linear time (one lookup per vertex in a hash table of positions [2]).
std::vector<std::uint32_t> PositionIds(const Mesh& mesh);

/// Key of the undirected edge {a, b} of two 32-bit ids: (min << 32) | max.
inline std::uint64_t PositionEdgeKey(std::uint32_t a, std::uint32_t b) {
  const std::uint64_t lo = a < b ? a : b, hi = a < b ? b : a;
  return (lo << 32) | hi;
}

/// How the triangles use one position edge {lo, hi} (lo < hi).
struct PositionEdge {
  std::uint32_t lo = 0, hi = 0;  ///< its two position ids
  std::uint32_t uses = 0;        ///< triangles with this edge
  std::int32_t balance = 0;      ///< uses running lo -> hi minus uses running hi -> lo
};

/// Every position edge of `mesh`'s triangles, sorted by (lo, hi), given `ids` =
/// PositionIds(mesh). Triangles with two corners at one position (collapsed) are left out.
/// Edges are grouped by their smaller id with a counting sort rather than hashed: ids follow
/// the mesh's own order, so the work stays in cache, and the time is linear in the triangle
/// count (plus sorting each position's few edges). Requires fewer than 2^31 positions.
std::vector<PositionEdge> PositionEdges(const Mesh& mesh, const std::vector<std::uint32_t>& ids);

}  // namespace prt
