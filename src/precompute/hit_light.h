#pragma once
/// \file
/// The light a hit point sends out, as every pass that follows a ray to a surface gathers it
/// (the direct pass's recorded hits, the bounces, the glossy lobe's rays, the transfer matrices,
/// the reference): which side of the surface the ray hit, the albedo there, and its transfer
/// interpolated over the hit triangle. FrontSide is defined with the direct pass
/// (transport_direct.cpp), AddHitLight and HitAlbedo with the bounces (transport_bounce.cpp),
/// beside the loops that call them most.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/bvh.h"
#include "geometry/mesh.h"

namespace prt {

/// Does the ray along `dir` hit the lit side of the triangle, the side its vertex normals face?
/// The side is decided by the triangle's plane (the geometric normal), oriented by the sum of
/// its vertex normals so that the file's winding order does not matter. (Testing the
/// interpolated shading normal instead would call grazing hits on coarse smooth meshes "back"
/// and lose their light.)
bool FrontSide(const Mesh& mesh, const Hit& hit, const glm::vec3& dir);

/// Adds `scale` times the light a hit point sends out as a diffuse surface, per light
/// coefficient: albedo(h) T(h) for channel c, T barycentric over the hit triangle (u, v) from
/// `transfer` laid out [(vertex * channels + c) * count + k], the albedo barycentric too, or
/// `*albedo` when given (a textured mesh's, HitAlbedo, looked up once for the three channels).
/// The gather of every bounce.
void AddHitLight(const Mesh& mesh, std::uint32_t triangle, float u, float v, const std::vector<double>& transfer,
                 int channels, int count, int c, double scale, double* out, const glm::vec3* albedo = nullptr);

/// A blocked direction of a vertex and what it hit (kept for the bounces).
struct VertexHit {
  std::uint32_t triangle;
  float u, v;          ///< barycentrics of the hit point
  std::uint32_t dir;   ///< index into the vertex's direction set
  bool front;          ///< hit the lit (front) side of the surface
};

/// A textured mesh's albedo at the hit at barycentrics (u, v) of `triangle`, one ray of
/// `directions` from `vertex`: the texture filtered over the patch of surface the ray stands for
/// (geometry/mesh_texture.h, RayFootprint).
glm::vec3 HitAlbedo(const Mesh& mesh, std::size_t vertex, std::uint32_t triangle, float u, float v,
                    std::size_t directions);

}  // namespace prt
