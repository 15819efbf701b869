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

/// Per-vertex linear RGB radiance in the same layout (`render --vertex-radiance`): the welded
/// vertex count, then three rows `R G B` per face in file order, one per corner, 9 significant
/// digits (a float reads back exactly). A stable format for comparing results from outside.
std::string FormatVertexRadianceTxt(const Mesh& mesh, const std::vector<glm::vec3>& radiance);

}  // namespace prt
