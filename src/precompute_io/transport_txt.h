#pragma once
/// \file
/// The course's `transport.txt` (GAMES202 homework 2): the first line is the vertex count, then
/// three rows per face in file order (one per corner; every face of the file, zero-area ones
/// included, see Mesh::file_triangles), each (lmax+1)^2 numbers: the corner's transfer vector. The WebGL framework reads it as per-corner attributes.
/// Written with 7 significant digits (float precision).

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "precompute/transport.h"

namespace prt {

/// The text of transport.txt for channel `channel` of `transport` (0 when it has one channel).
std::string FormatTransportTxt(const Mesh& mesh, const Transport& transport, int channel);

/// The faces of the mesh as read, which the files of this layout have three rows each for:
/// Mesh::file_triangles, or `triangles` when the mesh was not read from a file.
std::size_t FileFaceCount(const Mesh& mesh);

/// The vertex count of the mesh as read: the vertices its faces (FileFaceCount) use, 1 + their
/// largest index. A welded file mesh uses every vertex (weld.h numbers them as its corners come),
/// so that is its vertex count; a mesh split by --max-edge (app: scene_mesh.cpp) keeps the faces
/// as read in file_triangles, on its first vertices (geometry/subdivide.h appends the ones it
/// adds), and the count leaves the added ones out. `vertex_count()` when file_triangles is empty.
std::size_t FileVertexCount(const Mesh& mesh);

/// Per-vertex linear RGB radiance in the same layout (`render --vertex-radiance`): the welded
/// vertex count of the mesh as read (FileVertexCount), then three rows `R G B` per face as read
/// in file order, one per corner (that corner's vertex's radiance: a mesh split by --max-edge
/// keeps the corners as vertices), 9 significant digits (a float reads back exactly). A stable
/// format for comparing results from outside.
std::string FormatVertexRadianceTxt(const Mesh& mesh, const std::vector<glm::vec3>& radiance);

}  // namespace prt
