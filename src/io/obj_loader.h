#pragma once
/// \file
/// Wavefront OBJ meshes through tinyobjloader [1]: polygons triangulated, corners welded into
/// vertices (geometry/weld.h), normals from the file or smooth ones, albedo from the materials'
/// Kd, and every input problem either repaired and counted or reported as
/// `<path>: <problem> (<expected>)`, in prt's words rather than the parser's.
///
/// Stages. The file is read into memory once. One pass over the text (obj_scan.h) refuses
/// non-finite coordinates, malformed or missing indices (quoting the index as written, with its
/// line) and faces of fewer than three corners, counts lines that are not OBJ, and counts the
/// faces of each material. tinyobjloader then parses the same text from memory, reading the
/// material libraries through obj_materials.h; its corners are welded. For a large file a
/// progress bar (core/progress.h) covers reading, scanning, parsing and welding.
///
/// Materials. A `usemtl NAME` used several times in the .mtl resolves to the LAST definition
/// of NAME, as later definitions override earlier ones in MTL readers such as three.js's
/// MTLLoader (the course's WebGL framework); tinyobjloader alone would keep the first. The
/// course's mary.mtl defines `材质` twice (0.8 grey, then 0.27 0.55 0.87 blue): mary's body
/// (material `MC003_Kozakura_Mari`, absent from the .mtl, hence the default 0.8 grey) and its
/// blue part (`材质`) get their two colours.
///
/// Messages. Errors: `<path>: line 12: face uses vertex -7, out of bounds: only 4 vertices
/// precede it (indices 1..9 or -1..-4)`. Warnings: one per missing material, e.g.
/// `<path>: material 'MC003_Kozakura_Mari' is not defined in mary.mtl; its 9904 faces use the
/// default albedo 0.8`. Lines not understood are counted in the report, not warned one by one.
///
/// References
///  [1] S. Fujita, "tinyobjloader", https://github.com/tinyobjloader/tinyobjloader (2.0.0rc10).

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "io/obj_materials.h"

namespace prt {

/// A loaded mesh and what loading had to repair.
struct LoadedMesh {
  Mesh mesh;          ///< welded, in the file's face order
  MeshReport report;  ///< repairs, lines not understood and warnings, for the run summary
  /// One per vertex of `mesh`: 1 when its normal came from the file, 0 when it was computed
  /// because its corners had no normal or a zero-length one.
  std::vector<std::uint8_t> normal_from_file;
  /// The files read: the OBJ, then the material libraries it named that could be read.
  std::vector<std::string> files_read;
  /// The texture files read (obj_textures.h), apart from the OBJ and its libraries: --albedo
  /// replaces them in the frames although they were read.
  std::vector<std::string> texture_files;
  /// What the libraries wrote beyond the colour, for the run summary (obj_materials.h).
  MaterialFields material_fields;
};

/// Corners without a file normal closer than this fraction of the bounding-box diagonal are one
/// position: far below the spacing of distinct vertices in a real mesh, far above the float
/// rounding (6e-8 relative) of one coordinate written twice.
inline constexpr float kWeldRelativeTolerance = 1e-6f;

/// Loads `path`. Throws prt::Error for a missing file, a directory, indices that do not exist,
/// malformed face corners, faces of fewer than three vertices, non-finite coordinates, a file
/// without faces, or only zero-area faces. Zero-area triangles are dropped, zero-length or
/// missing normals recomputed and lines that are not OBJ skipped (counted in the report); a
/// material no library defines (the library missing, unreadable or silent about it) is one
/// warning per name and leaves its faces at the default albedo 0.8.
///
/// Textures (obj_textures.h): materials' map_Kd, or `texture` (non-empty: one file for every
/// face, --texture) make the mesh textured: texture coordinates per corner, a texture per face,
/// each vertex's albedo the mean of the texture at its corners (geometry/mesh_texture.h).
/// `texture` needs texture coordinates in the file: a file with no `vt` is an Error.
LoadedMesh LoadObj(const std::string& path, const std::string& texture = "");

/// The run summary's words for report.skipped_lines, e.g. `3 lines not understood, skipped
/// (first: line 12: 'hello world')`; empty when there were none.
std::string DescribeSkippedLines(const MeshReport& report);

}  // namespace prt
