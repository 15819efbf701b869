#pragma once
/// \file
/// Shading with precomputed transfer: the outgoing radiance of vertex v is
///     albedo(v) * sum_k L_k T_k(v)  [+ sum_k L_k G_k(v) for a glossy material's fixed view]
/// per colour channel,
/// a dot product of (lmax+1)^2 numbers: this is why PRT relights in real time. Only the bands
/// the transport has are used (a light of more bands is truncated, of fewer padded with 0).

#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "sh/coeffs.h"

namespace prt {

/// Linear RGB outgoing radiance of every vertex of `mesh` under `light`; without `albedo`, as if
/// every albedo were 1 and the material diffuse (the irradiance over pi, shadows and bounces
/// included; a glossy material's lobe is left out).
/// Transfer matrices (a glossy material seen from a camera that moves) add the lobe's radiance
/// toward `eye` (precompute/transfer_matrix.h), which they then need.
std::vector<glm::vec3> ShadeVertices(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                                     bool albedo = true, const glm::dvec3* eye = nullptr);

/// The same into `out` (resized to the vertex count): a frame loop passes the same buffer every
/// frame and the diffuse shading allocates nothing.
void ShadeVerticesInto(const Mesh& mesh, const Transport& transport, const ShRgb& light, bool albedo,
                       const glm::dvec3* eye, std::vector<glm::vec3>& out);

/// The diffuse part alone: albedo(v) sum_k L_k T_k(v) per channel (without `albedo`, as if it were
/// 1); what ShadeVertices adds a glossy lobe to.
std::vector<glm::vec3> ShadeDiffuse(const Mesh& mesh, const Transport& transport, const ShRgb& light, bool albedo = true);
/// The same into `out` (resized to the vertex count), allocating nothing once it is.
void ShadeDiffuseInto(const Mesh& mesh, const Transport& transport, const ShRgb& light, bool albedo,
                      std::vector<glm::vec3>& out);

/// A glossy material's lobe term alone (what ShadeVertices adds to the diffuse part): L . G for
/// the fixed view, or the lobe applied to M L toward `eye` from transfer matrices; 0 for diffuse.
std::vector<glm::vec3> ShadeGlossy(const Mesh& mesh, const Transport& transport, const ShRgb& light,
                                   const glm::dvec3* eye = nullptr);

}  // namespace prt
