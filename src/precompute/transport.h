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

#include <cstdint>
#include <string>
#include <vector>

#include <optional>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "material/material.h"
#include "precompute/bounce_senders.h"
#include "precompute/samplers.h"
#include "sh/coeffs.h"

namespace prt {

enum class TransportMode { kUnshadowed, kShadowed, kInterreflection };

TransportMode TransportModeFromName(const std::string& name);
const char* TransportModeName(TransportMode mode);

struct TransportOptions {
  TransportMode mode = TransportMode::kShadowed;
  int lmax = 2;
  int samples = 1024;                ///< directions per vertex (stratified: floor(sqrt)^2); 1024 =
                                     ///< DefaultHiddenSamples(2, kFibonacci), precompute/sample_rule.h
  Sampler sampler = Sampler::kFibonacci;
  /// Directions per vertex the camera does not see (`seen`); 0: `samples` (sample_rule.h).
  int hidden_samples = 0;
  /// Per vertex, nonzero when the camera sees it (some pixel of a frame shows a triangle of
  /// it); empty: every vertex is seen. Those take `samples` directions, the others
  /// `hidden_samples`.
  std::vector<std::uint8_t> seen;
  int bounces = 1;                   ///< interreflection bounces
  std::uint64_t seed = 1;
  double bounce_tolerance = 1e-4;    ///< stop when a bounce adds less than this share of direct
  int direction_sets = 64;           ///< size of the pool of direction sets
  Material material;                 ///< diffuse, or a Phong lobe (needs `eye`)
  std::optional<glm::dvec3> eye;     ///< the fixed camera the glossy transfer is computed for
  int lobe_samples = 0;              ///< lobe rays per vertex; 0: LobeSamplesOf(samples)
  /// Transfer matrices instead of the fixed-view vector G (a glossy material seen from a camera
  /// that moves; transfer_matrix.h).
  bool matrices = false;
};

/// The lobe rays per vertex for `samples` pool directions: a quarter of them, at least 64
/// (drawn from the lobe, they have far less variance than uniform directions).
int LobeSamplesOf(int samples);

/// Transfer vectors of every vertex.
struct Transport {
  int lmax = 0;
  int channels = 1;  ///< 1: one vector for R, G and B; 3: one per channel (coloured bounces)
  std::size_t vertices = 0;
  std::vector<float> coeffs;  ///< [(v * channels + c) * CoeffCount(lmax) + k]
  /// Glossy materials: the lobe's view-dependent transfer G, KS included, laid out as `coeffs`;
  /// empty for diffuse.
  std::vector<float> glossy;
  /// Transfer matrices (transfer_matrix.h) for views that move: n x n per vertex and channel,
  /// [((v * channels + c) * n + i) * n + j], n = CoeffCount(lmax); empty unless asked for.
  std::vector<float> matrices;
  /// The material the glossy parts were computed for (diffuse: none).
  Material material;

  const float* at(std::size_t v, int c) const {
    return coeffs.data() + (v * channels + (channels == 1 ? 0 : c)) * CoeffCount(lmax);
  }
  const float* glossy_at(std::size_t v, int c) const {
    return glossy.data() + (v * channels + (channels == 1 ? 0 : c)) * CoeffCount(lmax);
  }
};

/// What the precompute did and left out, for the run summary.
struct TransportReport {
  bool bvh_built = false;
  double bvh_seconds = 0, direct_seconds = 0, bounce_seconds = 0;
  std::uint64_t rays = 0;                 ///< rays actually traced
  std::uint64_t basis_evaluations = 0;    ///< directions whose SH basis was evaluated (transport_direct.h)
  std::size_t closed_form_vertices = 0;   ///< vertices given the exact closed form
  int directions_per_vertex = 0;          ///< directions of each vertex the camera sees
  int hidden_directions = 0;              ///< directions of each it does not see (0: none such)
  std::size_t hidden_vertices = 0;        ///< vertices the camera does not see, given those
  std::vector<double> bounce_share;       ///< energy each bounce added, relative to direct
  std::string bounce_stop;                ///< why the bounces stopped
  double glossy_seconds = 0;              ///< the lobe's transfer (glossy materials)
  std::uint64_t lobe_rays = 0;            ///< rays traced from the lobes
  int lobe_samples = 0;                   ///< lobe rays per vertex
  double matrix_seconds = 0;              ///< the transfer matrices
  SenderRefinement senders;               ///< interreflection: the bounce senders split (bounce_senders.h)
};

/// Vectors per vertex the transport of `mesh` in `mode` will have: 3 for interreflection with
/// coloured albedo (bounces differ per channel), else 1.
int TransportChannels(const Mesh& mesh, TransportMode mode);

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
