#pragma once
/// \file
/// Per-vertex diffuse transport: the SH vector T(v) such that a vertex of albedo rho under a
/// distant light with coefficients L sends out radiance  rho * sum_k L_k T_k(v)  [1].
///
///   unshadowed       T_k = (1/pi) integral max(0, n.w) Y_k(w) dw = (A_l/pi) Y_k(n), closed form
///                    (sh/zonal.h): no rays, no BVH.
///   shadowed         T_k = (1/pi) integral V(w) max(0, n.w) Y_k(w) dw. Estimated with a control
///                    variate: the closed form minus the Monte Carlo estimate of what is blocked,
///                      T = T_unshadowed - (4 pi / N) (1/pi) sum over blocked w_i of (n.w_i) Y(w_i),
///                    which is unbiased, exact for unoccluded vertices (they get the closed form
///                    and are counted), and has noise only where something is in the way.
///   interreflection  adds bounces: T^{b+1}(v) = (1/pi) integral over blocked directions of
///                    rho(h) max(0, n.w) T^b(h) dw, h the closest hit, T^b(h) and rho(h)
///                    interpolated barycentrically; T = T^0 + T^1 + ... [1, sec. 5]. Stops early
///                    once a bounce adds less than `bounce_tolerance` of the direct energy.
///                    With coloured albedo, bounces differ per channel: three vectors a vertex.
///
/// Glossy materials with a fixed camera (material/material.h; transport_glossy.cpp) add a second
/// vector per vertex, the view-dependent transfer of the lobe toward the camera:
///
///   G_k = KS integral Y_k(s) V(s) h(r.s) max(0, n.s) ds      (+ its bounces),
///
/// r the mirror of the direction to the eye. Estimated with the same control variate: the
/// unshadowed lobe transfer by quadrature (material/lobe_transfer.h) minus what is blocked,
/// found by `lobe_samples` rays drawn from the lobe itself (a rank-1 lattice, shifted per vertex),
/// so an unoccluded vertex gets the quadrature and a sharp lobe costs no more rays than a broad
/// one. With interreflection, a blocked lobe ray gathers the light its hit point sends out,
/// treating the hit as diffuse: albedo(h) times h's diffuse transfer through bounce B - 1.
/// Then  B = albedo (L . T) + L . G  is exact for a light of bands <= lmax: no product is
/// truncated, only the light.
///
/// The albedo of the receiving vertex stays outside T (the course's convention). Directions
/// come from a pool of `direction_sets` sets drawn by the chosen sampler, each prepared once as
/// a ray fan (geometry/ray_fan.h); vertex v uses set hash(seed, v) mod pool size, so neighbours
/// get different sets, results do not depend on the thread count, and no fan is rebuilt per
/// vertex. With `seen` (the vertices a render's frames show), those draw from a pool of
/// `samples` directions and the others from one of `hidden_samples` (direction_pool.h,
/// DirectionPlan; sample_rule.h says why); each vertex weighs its estimates by its own count.
///
/// Interreflection runs on a copy of the mesh whose long edges are split, so that the light a
/// bounce reads at a hit point does not depend on how coarsely the senders are triangulated;
/// only the mesh's own vertices are returned (bounce_senders.h).
///
/// References
/// [1] Sloan, Kautz, Snyder, "Precomputed Radiance Transfer for Real-Time Rendering in Dynamic,
///     Low-Frequency Lighting Environments", SIGGRAPH 2002.
/// [2] Green, "Spherical Harmonic Lighting: The Gritty Details", GDC 2003, sec. "Diffuse
///     shadowed / interreflected transfer".

#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "precompute/transport_types.h"

namespace prt {

/// Computes the transport of `mesh` (unit normals, albedo in [0, 1]).
Transport ComputeTransport(const Mesh& mesh, const TransportOptions& options, TransportReport* report);

/// The light interreflection adds to shadowed transport, alone: ComputeTransport in mode
/// interreflection (whatever options.mode says; diffuse) minus its own direct part, the same
/// directions for both. What the wavelet basis takes from SH (wavelet/transport.h).
Transport ComputeBouncedTransport(const Mesh& mesh, const TransportOptions& options, TransportReport* report);

/// Monte Carlo estimate of the unshadowed transfer from a direction set (weights 4 pi/N), kept
/// to test samplers against the closed form.
std::vector<double> EstimateUnshadowed(const std::vector<glm::dvec3>& dirs, const glm::dvec3& normal, int lmax);

}  // namespace prt
