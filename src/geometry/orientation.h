#pragma once
/// \file
/// Detecting and repairing inside-out meshes.
///
/// Users' meshes arrive inside out in two ways. (a) The triangles are wound clockwise seen from
/// outside and the file has no normals: the smooth normals computed from the winding then point
/// inward, a shadowed precompute sees no sky from any vertex and the mesh renders black.
/// (b) The file's normals point inward: shading lights the mesh from the wrong side.
///
/// Which side is outside is only decidable for a closed surface. The divergence theorem turns
/// the enclosed volume into a sum over the triangles [1],
///   V = (1/6) sum_t p0 . (p1 x p2),
/// which is the true volume when every triangle is wound counter-clockwise seen from outside,
/// and its negative when every triangle is wound the other way. The sum is taken relative to
/// the centre of the mesh's bounding box (it does not depend on the origin for a closed surface,
/// and the small coordinates keep it accurate far from the origin). It decides the winding only
/// when the surface is closed and consistently oriented: every position edge (position_ids.h)
/// used by exactly two triangles, once in each direction [2, ch. 2]; otherwise the triangles
/// may disagree among themselves and an open surface (a floor quad) has no inside at all.
///
/// The test runs per connected part (triangles linked through shared positions), so a scene of
/// a closed statue on an open floor has its statue repaired and its floor left alone; when
/// closed parts were repaired, open parts shaded by their winding alone are warned about (one
/// exporter usually winds a whole file the same way).
///
/// Normals are judged against the winding area by area: a face's corner normals (summed) point
/// against the winding when their dot product with the face's normal (p1 - p0) x (p2 - p0) is
/// negative. A whole part's normals from the file are negated only when they point against its
/// (corrected) winding on most of its area: an export that wrote inward normals.
///
/// `file_triangles` is never touched: it lists the file's faces in file order for formats with
/// one row per face corner (the course's transport.txt), and reversing a face's corners there
/// would reorder those rows; the vertices it names keep their meaning, only their normals may
/// have been negated.
///
/// References
///  [1] C. Zhang, T. Chen, "Efficient feature extraction for 2D/3D objects in mesh
///      representation", ICIP 2001 (volume as a sum of signed tetrahedra).
///  [2] M. Botsch, L. Kobbelt, M. Pauly, P. Alliez, B. Lévy, "Polygon Mesh Processing",
///      A K Peters, 2010 (ch. 2: manifolds and orientability).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/mesh.h"

namespace prt {

/// What `OrientMesh` found and did, for the run summary.
struct OrientationReport {
  /// Every position edge is shared by exactly two triangles, oppositely directed (watertight
  /// and consistently oriented), and the mesh has at least one triangle.
  bool closed = false;
  /// (1/6) sum p0 . (p1 x p2) relative to the bounding-box centre, before any fix; the enclosed
  /// volume (world units cubed) when `closed` and wound outward.
  double signed_volume = 0.0;
  /// Area fraction of the faces whose corner normals (summed) point against the winding's face
  /// normal, before any fix; 0 for a mesh without area.
  double normals_against_winding = 0.0;
  std::size_t flipped_triangles = 0;  ///< triangles whose winding was reversed
  std::size_t flipped_normals = 0;    ///< vertex normals negated (file or computed ones)
  std::string fixed;    ///< non-empty: what was repaired and why ("clause; clause", lower case)
  std::string warning;  ///< non-empty: a problem seen but not repaired, with the remedy (likewise)
};

/// Makes closed parts of `mesh` face outward (see the file comment) and reports what it did.
/// `normal_from_file[v] != 0` when vertex v's normal came from the file; otherwise it was computed
/// from the winding (SmoothNormals) and turns with it when its part's winding is reversed (negated,
/// which equals recomputing them). Vertices beyond its size count as computed (an empty vector: no
/// normal came from the file). Zero-area and collapsed triangles are allowed. Open or
/// inconsistently wound parts are left unchanged (with a warning when their file normals disagree
/// with their winding). Deterministic; linear in the size of the mesh.
OrientationReport OrientMesh(Mesh& mesh, const std::vector<std::uint8_t>& normal_from_file);

}  // namespace prt
