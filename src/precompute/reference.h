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
///   glossy      a `phong:N,KS` material (material/material.h) adds its lobe toward the eye:
///               KS * integral h(r.s) max(0, n.s) X(s) ds, with h the lobe (material/lobe.h),
///               r = 2 (n.e) n - e the mirror of the unit direction e to the eye, and X(s) = L(s)
///               where s sees the environment, Lo_{B-1}(h(s)) where it is blocked with
///               interreflection (the hit sends out what a DIFFUSE surface does with B - 1
///               further bounces, as the transport's glossy bounce assumes), 0 where it is
///               blocked otherwise.
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
/// Glossy estimator. The diffuse part is estimated exactly as above (same samples, same
/// numbers). For the lobe term each lattice point i also gives a lobe direction s_i: mu = r.s
/// by Lobe::SampleMu, the azimuth about r uniform, both from the lattice point under a shift of
/// its own, so the density is p_lobe(s) = h(r.s) / c with c = h / density constant ((N+1)/(2 pi)
/// mu^N for Phong). With w_i the environment direction (density p_env) the term's estimate at
/// lattice point i is multiple importance sampling with the balance heuristic [4]:
///
///   KS h(r.w_i) max(0, n.w_i) V(w_i) L(w_i) a(w_i) / p_env(w_i)
///     + KS c max(0, n.s_i) [V(s_i) L(s_i) (1 - a(s_i)) + (1 - V(s_i)) Lo_{B-1}(h(s_i))],
///   a(s) = p_env(s) / (p_env(s) + p_lobe(s)),
///
/// the last term only with interreflection, p_env of a lobe direction by EnvSampler::Pdf.
/// Where both techniques can draw a direction the weights a and 1 - a sum to 1, so the sum is
/// unbiased; blocked directions only the lobe draws, with weight 1. Either technique's
/// unblocked term is KS h cos L / (p_env + p_lobe), below both KS c cos L (bounded for a sharp
/// lobe under a smooth sky) and KS h cos L / p_env (bounded for a sun under a broad lobe). The
/// hit point's Lo is the diffuse path of the previous paragraph, its random numbers drawn from
/// the lobe's stream.
///
/// Own error. Each vertex is estimated twice with independent shifts, N/2 directions each; the
/// reference is their mean and |A - B| / 2 estimates the error of that mean (for an unbiased
/// estimator, E|A - B|^2 / 4 is exactly its variance). Its RMS over vertices is reported so that
/// every comparison can say whether the reference is good enough.
///
/// Deterministic: vertex v's random streams depend only on (seed, v, half), never on threads.
/// The lobe samples have a stream of their own, so KS = 0 reproduces the diffuse material bit
/// for bit.
///
/// References
/// [1] Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., ch. 13 (path tracing,
///     next-event estimation) and sec. A.5 (sampling distributions).
/// [2] Niederreiter, "Random Number Generation and Quasi-Monte Carlo Methods", SIAM 1992,
///     ch. 5 (good lattice points; the Fibonacci lattice).
/// [3] Cranley, Patterson, "Randomization of number theoretic methods for multiple
///     integration", SIAM J. Numer. Anal. 13(6), 1976.
/// [4] Veach, Guibas, "Optimally combining sampling techniques for Monte Carlo rendering",
///     SIGGRAPH 1995 (multiple importance sampling; the balance heuristic).

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "env/environment.h"
#include "geometry/mesh.h"
#include "material/material.h"
#include "precompute/transport.h"

namespace prt {

/// Which techniques sample a glossy lobe's term (see above); the single ones are for tests that
/// show what the mixture buys.
enum class GlossySampling {
  kBalance,      ///< environment and lobe, balance heuristic
  kEnvironment,  ///< environment only (the lobe still gathers blocked directions)
  kLobe,         ///< lobe only
};

struct ReferenceOptions {
  TransportMode mode = TransportMode::kShadowed;
  int samples = 8192;    ///< directions per vertex, both halves together (>= 2)
  int bounces = 1;       ///< interreflection bounces
  std::uint64_t seed = 1;
  int table_rows = 512;  ///< environment importance table (reference_env_sampler.h)
  int table_cols = 1024;
  Material material;                ///< diffuse, or a Phong lobe (needs `eye`)
  std::optional<glm::dvec3> eye;    ///< the camera the glossy lobe is seen from
  GlossySampling glossy_sampling = GlossySampling::kBalance;
  /// The vertices computed (a farm job's shard): the others' radiance and error stay 0 (and
  /// count as 0 in the RMS figures). Every vertex by default.
  VertexBlock block;
};

struct Reference {
  std::vector<glm::dvec3> radiance;  ///< per vertex, linear RGB outgoing radiance (albedo in)
  std::vector<glm::dvec3> error;     ///< per vertex, |A - B| / 2 of the two halves
  double rms_error = 0;              ///< RMS of `error` over vertices and channels
  double rms_radiance = 0;           ///< RMS of `radiance` over vertices and channels
  std::uint64_t rays = 0;            ///< rays traced
};

/// The ground truth of `mesh` under `env` (see above). Throws Error for samples < 2 and for a
/// glossy material without an eye.
Reference ComputeReference(const Mesh& mesh, const Environment& env, const ReferenceOptions& options);

/// Sets `ref`'s rms_error and rms_radiance from its per-vertex radiance and error, over every
/// vertex (ComputeReference does; so does the merge of a farm job's shards).
void SummarizeReference(Reference& ref);

}  // namespace prt
