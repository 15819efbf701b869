#pragma once
/// \file
/// Splitting long edges, so per-vertex transport has vertices where shadows fall.
///
/// Transport is computed at the vertices and interpolated linearly across each triangle, so a
/// shadow that falls inside one triangle is never seen: a floor made of one quad shows no
/// contact shadow at all. Splitting every edge longer than `max_edge` bounds the distance over
/// which shading is interpolated.
///
/// Each pass looks at every triangle's three edges. A long edge (longer than max_edge) is split
/// at its midpoint, one vertex shared by the two triangles on it (a cache keyed by the edge's
/// vertex pair), so no vertex ends up in the middle of a neighbour's edge (no T-junction, no
/// crack). A triangle with k long edges becomes k + 1 triangles [1, 2], each counter-clockwise
/// like its parent:
///
///       c               c               c               c
///      / \             /|\             /|\             / \     a triangle with
///     /   \    k=1    / | \    k=2    / | q    k=3    r---q    k long edges
///    /     \   -->   /  |  \   -->   /  |/ \   -->   / \ / \   becomes k + 1
///   a-------b       a---m---b       a---p---b       a---p---b
///
/// (m, p, q, r are edge midpoints. k = 1: the long edge's midpoint joins the opposite corner;
/// k = 2: the corner between the two long edges (b) is cut off and the quadrilateral left
/// (a p q c) is split along its shorter diagonal (here p c); k = 3: four half-size copies.)
/// Passes repeat until no edge is long.
///
/// Whether an edge is long depends only on its two end positions, so two triangles sharing an
/// edge through different vertices at the same positions (a crease, split normals) split it
/// both and their midpoints coincide: the surface stays closed as drawn.
///
/// Termination and a bound, e = max_edge, L = a triangle's longest edge: a k = 1 split makes
/// medians no longer than the two short edges' mean (<= e); k = 3 halves every edge; the shorter
/// diagonal of k = 2 is at most the root mean square of the two medians it could be, i.e.
/// d^2 <= L^2 / 4 + e^2 / 2. So the longest long edge of every child obeys
///   L'^2 <= L^2 / 4 + e^2 / 2,
/// whose fixed point 2 e^2 / 3 lies below e^2: a triangle is done after at most
/// P = ceil(log4(3 L^2 / e^2 - 2)) passes, with at most 4^P descendants.
///
/// References
///  [1] R. E. Bank, A. H. Sherman, A. Weiser, "Refinement algorithms and data structures for
///      regular local mesh refinement", Scientific Computing (IMACS), 1983 (red-green
///      refinement).
///  [2] M.-C. Rivara, "Mesh refinement processes based on the generalized bisection of
///      simplices", SIAM Journal on Numerical Analysis 21(3), 1984.

#include <cstddef>

#include "geometry/mesh.h"

namespace prt {

/// The smallest max_edge that SplitLongEdges resolves on `mesh`: the rounding margin (2^-20 of
/// the largest coordinate) m must leave (e - m)^2 above the bound's fixed point 2 e^2 / 3, so
/// e > m / (1 - sqrt(2/3)), about 5.45 m.
double MinimumMaxEdge(const Mesh& mesh);

/// Upper bound on the triangle count after SplitLongEdges(mesh, max_edge), computed without
/// splitting so that a request too fine for memory can be refused before any work. Per
/// triangle: exact while all three of its edges are long (each pass then makes four half-size
/// copies), then 4^P with P from the bound of the file comment; on ordinary meshes it is 1 to 8
/// times the actual count. Decisions are kept a rounding margin (2^-20 of the largest
/// coordinate) away from max_edge, so float midpoints cannot exceed it. Saturates at the
/// largest std::size_t, which it also returns when max_edge is not positive or is finer than
/// float positions resolve there. Linear in the triangle count.
std::size_t EstimateSplitTriangles(const Mesh& mesh, float max_edge);

/// What SplitLongEdges did.
struct SplitReport {
  std::size_t triangles_before = 0;  ///< triangle count on entry
  std::size_t triangles_after = 0;   ///< triangle count on return
  std::size_t vertices_added = 0;    ///< edge midpoints created
  int passes = 0;                    ///< passes that split at least one edge
};

/// Splits triangles until no edge is longer than `max_edge` (world units, > 0 and resolvable by
/// float positions, else throws prt::Error), conformingly (no T-junctions; see the file comment). A
/// new vertex takes the midpoint of its edge's position, albedo and normal (the normal
/// renormalised). Vertex and triangle order depend only on the input: new vertices are appended in
/// the order their edges are met, a split triangle's children take its place. When anything was
/// split, `file_triangles` is cleared (the mesh no longer matches the file face for face); when no
/// edge is long the mesh is left as it is.
SplitReport SplitLongEdges(Mesh& mesh, float max_edge);

}  // namespace prt
