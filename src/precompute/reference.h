#pragma once
/// \file
/// Ground truth for PRT: the outgoing radiance of every vertex computed without spherical
/// harmonics, by integrating the full-resolution environment directly [1]:
///
///   direct      Lo(v) = albedo(v)/pi * integral L(w) V(v, w) max(0, n.w) dw
///               (V = 1 for `unshadowed`),
///   bounces     plus albedo(v)/pi * integral over blocked w of Lo_{b-1}(h(w)) max(0, n.w) dw,
///               h the closest hit, for up to `bounces` bounces (`interreflection`): the
///               rendering equation truncated after B bounces, as the transport truncates it.
///
/// Estimator. The direct integral samples the environment by importance (reference_env_sampler.h),
/// so L/p is nearly constant and even a sun disk of 1e4 times the mean radiance adds little
/// noise. The N directions of a vertex are a rank-1 lattice (the 2D Fibonacci lattice,
/// x_i = (i/N, frac(i / golden ratio))) [2], randomly shifted per vertex (Cranley–Patterson
/// rotation [3]), so the error falls faster than N^-1/2 yet stays unbiased. Bounces follow one
/// path per sample: a cosine-weighted direction from the receiver (pdf cos/pi, so the weight is
/// just the albedo), and at the hit point (barycentric normal and albedo) the same direct
/// estimate with an iid direction, recursively: per-vertex path tracing [1, ch. 13].
///
/// Own error. Each vertex is estimated twice with independent shifts, N/2 directions each; the
/// reference is their mean and |A - B| / 2 estimates the error of that mean (for an unbiased
/// estimator, E|A - B|^2 / 4 is exactly its variance). Its RMS over vertices is reported so that
/// every comparison can say whether the reference is good enough.
///
/// Deterministic: vertex v's random streams depend only on (seed, v, half), never on threads.
///
/// References
/// [1] Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., ch. 13 (path tracing,
///     next-event estimation) and sec. A.5 (sampling distributions).
/// [2] Niederreiter, "Random Number Generation and Quasi-Monte Carlo Methods", SIAM 1992,
///     ch. 5 (good lattice points; the Fibonacci lattice).
/// [3] Cranley, Patterson, "Randomization of number theoretic methods for multiple
///     integration", SIAM J. Numer. Anal. 13(6), 1976.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "env/environment.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"

namespace prt {

struct ReferenceOptions {
  TransportMode mode = TransportMode::kShadowed;
  int samples = 8192;    ///< directions per vertex, both halves together (>= 2)
  int bounces = 1;       ///< interreflection bounces
  std::uint64_t seed = 1;
  int table_rows = 512;  ///< environment importance table (reference_env_sampler.h)
  int table_cols = 1024;
};

struct Reference {
  std::vector<glm::dvec3> radiance;  ///< per vertex, linear RGB outgoing radiance (albedo in)
  std::vector<glm::dvec3> error;     ///< per vertex, |A - B| / 2 of the two halves
  double rms_error = 0;              ///< RMS of `error` over vertices and channels
  double rms_radiance = 0;           ///< RMS of `radiance` over vertices and channels
  std::uint64_t rays = 0;            ///< rays traced
};

/// The ground truth of `mesh` under `env` (see above). Throws Error for samples < 2.
Reference ComputeReference(const Mesh& mesh, const Environment& env, const ReferenceOptions& options);

}  // namespace prt
