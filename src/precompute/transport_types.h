#pragma once
/// \file
/// The values the transport's passes share: what to compute (TransportOptions, TransportMode),
/// what comes out (Transport: the transfer vectors, the glossy vectors or matrices) and what the
/// run summary says of it (TransportReport), with the two counts the passes read from them
/// (LobeSamplesOf, TransportChannels) and the modes' `--transport` words.
///
/// transport.h computes them and has the maths. Its passes (transport_bounce.h,
/// transport_glossy.h, transfer_matrix.h) include this header, not transport.h, which
/// transport.cpp takes them from: so no pass includes the unit that includes it, and a change to
/// how the transport is chained rebuilds no pass.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "material/material.h"
#include "precompute/bounce_senders.h"
#include "precompute/samplers.h"
#include "sh/coeffs.h"

namespace prt {

enum class TransportMode { kUnshadowed, kShadowed, kInterreflection };

/// "unshadowed", "shadowed" or "interreflection" (the `--transport` words) as a mode; throws
/// Error for any other name.
TransportMode TransportModeFromName(const std::string& name);
/// The `--transport` word of `mode`.
const char* TransportModeName(TransportMode mode);
/// Every mode's word, in the enum's order.
std::vector<std::string> TransportModeNames();

/// A block of whole vertices [begin, end): what one shard of a farm job computes
/// (farm/vertex_blocks.h). Every vertex by default.
struct VertexBlock {
  std::size_t begin = 0;
  std::size_t end = std::numeric_limits<std::size_t>::max();
  bool Has(std::size_t v) const { return v >= begin && v < end; }
};

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
  /// The vertices computed; the others are left 0. Each vertex's transfer is its own (its
  /// directions from hash(seed, v)), so a block's rows are those of the whole run to the bit.
  /// Not in the cache key (a shard's rows belong to the whole run's transport).
  VertexBlock block;
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

/// The transport of a farm job, assembled from its shards (farm/assemble_shards.h), which a
/// basis takes in place of computing it (basis/basis.h, BasisInputs).
struct ShardedTransport {
  const Transport* transport = nullptr;
  std::uint64_t key = 0;  ///< the cache key the shards were made with
  int shards = 0;
};

}  // namespace prt
