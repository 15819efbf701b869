#pragma once
/// \file
/// The albedo of a textured mesh at a point of its surface, for the stages that need it away from
/// the rasterizer's pixels: the bounces (the albedo at a ray's hit point) and the per-vertex
/// albedo of the reference, the error report and `--vertex-radiance`.
///
/// Footprint. A texture is filtered over the patch of surface one sample stands for (ray-cone
/// footprints [1]): a ray of a set of N directions covers 4 pi / N steradians, so at distance d
/// it meets a patch about d sqrt(4 pi / N) wide. The patch's width in texture coordinates comes
/// from the hit triangle's own scale, sqrt(area in uv / area in space), and sets the mip level
/// (texture/texture.h). A vertex stands for its triangles: its corners are filtered over each
/// triangle's own width.
///
/// References
///  [1] T. Akenine-Möller, J. Nilsson, M. Andersson, C. Barré-Brisebois, R. Toth, T. Karras,
///      "Texture Level of Detail Strategies for Real-Time Ray Tracing", Ray Tracing Gems, 2019.

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace prt {

/// Texture coordinates at barycentrics (u, v) of triangle t: (1 - u - v) uv0 + u uv1 + v uv2.
/// Precondition: mesh.textured().
glm::vec2 TriangleUv(const Mesh& mesh, std::uint32_t t, float u, float v);

/// Texture-coordinate length per unit of world length on triangle t: sqrt(uv area / area).
float UvPerWorldUnit(const Mesh& mesh, std::uint32_t t);

/// The albedo at barycentrics (u, v) of triangle t, filtered over a patch `footprint` world units
/// wide: the texture there for a textured mesh, the barycentric vertex albedo otherwise.
glm::vec3 SurfaceAlbedo(const Mesh& mesh, std::uint32_t t, float u, float v, float footprint);

/// The world width of the patch one of `directions` rays covers at `distance`: d sqrt(4 pi / N).
float RayFootprint(float distance, std::size_t directions);

/// Sets every vertex albedo of a textured mesh to the mean, over its corners, of the texture at
/// the corner filtered over the corner's triangle; does nothing to an untextured mesh.
void SetVertexAlbedoFromTextures(Mesh& mesh);

}  // namespace prt
