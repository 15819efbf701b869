#pragma once
/// \file
/// Wavefront OBJ meshes through tinyobjloader [1]: polygons triangulated, corners welded into
/// vertices (geometry/weld.h), normals from the file or smooth ones, albedo from the materials'
/// Kd, and every input problem either repaired and counted or reported as
/// `<path>: <problem> (<expected>)`.
///
/// Materials. A `usemtl NAME` used several times in the .mtl resolves to the LAST definition
/// of NAME, as later definitions override earlier ones in MTL readers such as three.js's
/// MTLLoader (the course's WebGL framework); tinyobjloader alone would keep the first. The
/// course's mary.mtl defines `材质` twice (0.8 grey, then 0.27 0.55 0.87 blue): mary's body
/// (material `MC003_Kozakura_Mari`, absent from the .mtl, hence the default 0.8 grey) and its
/// blue part (`材质`) get their two colours.
///
/// References
///  [1] S. Fujita, "tinyobjloader", https://github.com/tinyobjloader/tinyobjloader (2.0.0rc10).

#include <string>

#include "geometry/mesh.h"

namespace prt {

/// A loaded mesh and what loading had to repair.
struct LoadedMesh {
  Mesh mesh;
  MeshReport report;
};

/// Corners without a file normal closer than this fraction of the bounding-box diagonal are one
/// position: far below the spacing of distinct vertices in a real mesh, far above the float
/// rounding (6e-8 relative) of one coordinate written twice.
inline constexpr float kWeldRelativeTolerance = 1e-6f;

/// Loads `path`. Throws prt::Error for a missing file, a directory, a parse error, indices out
/// of range, non-finite coordinates, a file without faces, or only zero-area faces.
/// Zero-area triangles are dropped and zero-length or missing normals recomputed (counted in
/// the report); a missing or unreadable .mtl, or an unknown material, is a warning and leaves
/// the default albedo 0.8.
LoadedMesh LoadObj(const std::string& path);

}  // namespace prt
