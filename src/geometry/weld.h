#pragma once
/// \file
/// Vertex welding: turning a list of triangle corners (three per triangle, as read from a file)
/// into shared vertices.
///
/// Corners that carry a normal from the file are one vertex exactly when they use the same
/// (position, normal) pair of the file: a crease, hard edge or seam written with split normals
/// keeps its separate vertices, and so do coincident vertices the file keeps apart. This is the
/// course's count: mary.obj has 7905 vertices by (position, normal) index pairs. (Merging its
/// coincident positions with equal normal values would give 6794 and break the course's
/// transport files, whose first line is that count.)
///
/// Corners without a normal are welded by position: those within `position_tolerance` of an
/// earlier such corner join its vertex (k-d tree radius search [1]), so a triangle soup becomes
/// a connected surface whose smooth normals can be computed. Vertices are numbered in order of
/// first appearance, so the result follows the file's face order.
///
/// References
///  [1] J. L. Blanco, P. K. Rai, "nanoflann: a C++ header-only fork of FLANN", 2014,
///      https://github.com/jlblancoc/nanoflann

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace prt {

/// Triangle corners before welding: element 3 t + c is corner c of triangle t.
struct CornerSoup {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  ///< unit normal, or (0, 0, 0) when the corner has none
  /// The file's identity of the corner, e.g. (position index << 32 | normal index); corners
  /// with a normal and equal ids are one vertex. Ignored for corners without a normal.
  std::vector<std::uint64_t> ids;
  std::vector<glm::vec3> albedo;   ///< linear RGB of the corner's material
  /// Texture coordinates per corner and the texture of each triangle (t, not 3 t + c); both
  /// empty for an untextured soup. They pass to the kept triangles unwelded (Mesh::corner_uv).
  std::vector<glm::vec2> uv;
  std::vector<std::uint32_t> texture;
};

/// A welded mesh and, per vertex, where its normal came from.
struct WeldedMesh {
  Mesh mesh;  ///< welded vertices, triangles and file_triangles
  /// One per vertex: 1 when the normal is the (normalised sum of) the file's normals of its
  /// corners, 0 when it was computed because its corners had none (or zero-length ones, which
  /// the caller passes as none). Mesh repairs that may flip normals need to know which they are.
  std::vector<std::uint8_t> normal_from_file;
};

/// Welds `soup` into a mesh. A vertex takes the position of its first corner, the normalised sum
/// of its corners' normals, and the mean albedo of its corners (so albedo is averaged where
/// materials meet). Vertices whose corners have no normal get area-and-angle-weighted smooth
/// normals (counted in report.recomputed_normals, flagged 0 in normal_from_file). Triangles that
/// collapse because two of their corners weld together are dropped (report.dropped_degenerate).
/// report.welded_away counts corners that joined an existing vertex.
WeldedMesh WeldCorners(const CornerSoup& soup, float position_tolerance, MeshReport& report);

}  // namespace prt
