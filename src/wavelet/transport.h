#pragma once
/// \file
/// Per-vertex transport in a Haar wavelet basis on a cube map (all-frequency PRT [1]), beside
/// the SH transport of precompute/transport.h. What it stores, per vertex:
///
///   direct     the transport of each texel t of the cube (wavelet/cube_grid.h),
///                T_t = (1/pi) integral over texel t of V(w) max(0, n.w) dw,
///              split as T_t = S_t + W_t: S its smooth part, the SH projection up to base_lmax
///              (4: 25 floats s_j, wavelet/texel_sh.h), and W what S leaves out (the shadow and
///              horizon edges), taken to Haar coefficients face by face (wavelet/haar.h): the six
///              faces' scaling coefficients (their means) as floats, and of the details only the
///              `budget` - 6 most important (wavelet/selection.h), each a 16-bit index and a
///              16-bit integer times the vertex's step (its largest kept detail / 32767).
///              Then a vertex of albedo rho under a light L_t on the texels (light_cube.h)
///              sends out  rho (sum_j s_j l_j + sum_k L^_k W^_k)  (the transform is
///              orthonormal), l_j the light's own SH coefficients over the texels, the second sum
///              sparse over the kept k.
///
///              Why the base. Without it the budget went first to the smooth cosine over the open
///              sky, whose Haar coefficients decay slowly and spread over the whole hemisphere,
///              wherever the light is: below about 400 terms the block around the sun was left
///              at a coarse mean and the error jumped past SH's (10.9 % at 256 terms against SH
///              lmax 8's 6.0 %, and 5 times worse with the sun at 90 degrees than at 45). Ng et
///              al. avoid it by choosing terms from the light each frame over a transport stored
///              per light coefficient [1]; here SH holds the smooth part, which it does well, and
///              the terms go to the edges alone, so a budget too small for the sun falls back to
///              SH lmax 4's blur, never below it.
///   bounced    with interreflection, the light that arrives after one or more bounces, as SH
///              transfer vectors (precompute/transport.h, the bounced part alone): bounced light is low
///              frequency, and the SH light of the same environment lights it.
///
/// The texel integral: the clamped cosine over the texel is exact (CubeGrid::ClampedCosine), and
/// V is its share that rays find open: split x split rays per texel, one in each sub-square at a
/// jittered point (a pool of `kJitterSets` jittered fans, vertex v taking set hash(seed, v)), each
/// weighted by its cosine times its sub-square's solid angle. A vertex that nothing blocks gets
/// the exact transport, so a white sky gives exactly the albedo. Vertices that no frame shows
/// (TransportOptions::seen) take one ray per texel (their bounces are the SH pass's); a run with
/// --vertex-radiance marks every vertex seen, as the file lists them all.
///
/// Memory: 4 bytes a kept detail, plus 136 a vertex (base, means, step, offset): 2,160 bytes at
/// the default 512 terms, against 4,204 with 32-bit indices and float values. Quantising costs
/// nothing measurable: each detail's error is at most half a step, 1.5e-5 of the vertex's
/// largest, and a white sky still gives exactly the albedo (the means are floats).
///
/// Defaults, measured (Intel Xeon, AVX-512, 2 vCPUs): the sample knot over a ground of 40 x 40
/// quads (5,521 vertices) under sky.hdr, the sky as `prt sample-files` writes it (1024 x 512, a
/// 2-degree sun a few pixels wide), per-vertex relative RMS against prt reference (8192
/// directions, its own error 0.10 %), shadowed, F 32, 4 rays a texel, the sky turned about +Y by
/// 0 / 45 / 90 degrees:
///
///   kept         128                 256                 512                 1024   all (6,144)
///   SH base 4    3.39 / 2.86 / 3.52  2.15 / 1.89 / 2.27  1.26 / 1.27 / 1.31  0.86   0.70
///   (magnitude)
///   no base      -                   8.28 (0 degrees)    1.27 (0 degrees)    -      -
///   (area)
///
/// (SH at the same angles: lmax 4 8.7 %, lmax 8 6.0 %.) With the base, area weights keep worse
/// details at every budget (2.19 % at 256, 1.49 % at 512), so the details are kept by magnitude.
/// So: F = 32, 4 rays a texel, SH base lmax 4, 512 kept by magnitude (2,160 bytes a vertex).
/// SH lmax 2, 4, 8, 16 on the same file (16384 directions, unturned): 12.6, 8.7, 6.0, 3.9 %.
/// One bounce (its SH at lmax 4) at the defaults: 1.59 % (reference's own error 0.38 %). Under
/// the built-in sky (its sun an exact disk) the same: 1.26 % shadowed, 1.60 % with one bounce.
///
/// References
/// [1] Ng, Ramamoorthi, Hanrahan, "All-Frequency Shadows Using Non-linear Wavelet Lighting
///     Approximation", SIGGRAPH 2003.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "wavelet/options.h"

namespace prt {

/// Jittered fans in the pool the vertices draw from.
inline constexpr int kJitterSets = 8;
/// Quantisation steps on each side of 0 (a detail is an int16 times the vertex's step).
inline constexpr double kQuantSteps = 32767.0;

struct WaveletTransport {
  int face_size = 0;
  std::size_t vertices = 0;
  /// The smooth part of the direct transport in SH (-1: none): per vertex (base_lmax + 1)^2
  /// coefficients at base[v * (base_lmax + 1)^2]; the wavelets below keep what it leaves out.
  int base_lmax = -1;
  std::vector<float> base;
  std::vector<float> means;            ///< per vertex its 6 faces' scaling coefficients, [6 v + face]
  std::vector<std::uint64_t> offsets;  ///< vertex v's details: [offsets[v], offsets[v + 1])
  std::vector<std::uint16_t> index;    ///< detail index (face * F^2 + row * F + col), increasing per vertex
  std::vector<std::int16_t> value;     ///< detail / scale[v], rounded
  std::vector<float> scale;            ///< per vertex: its quantisation step
  /// Interreflection: the bounced light as SH transfer (precompute/transport.h layout); no coefficients
  /// otherwise.
  Transport bounce;
  /// A sample of vertices with every coefficient kept (the unkept transport), to measure what
  /// the truncation costs: probe p is vertex probes[p], its 6 F^2 coefficients at p * 6 F^2.
  std::vector<std::uint32_t> probes;
  std::vector<float> probe_coeffs;
  double kept_energy = 0.0;  ///< mean over vertices of sum kept T^2 / sum T^2
  std::uint64_t rays = 0;
  double seconds = 0.0;

  /// Coefficients kept, all vertices together (the means and the details).
  std::size_t Kept() const { return means.size() + index.size(); }
  /// Bytes of the kept coefficients and what locates them.
  std::size_t Bytes() const {
    return base.size() * sizeof(float) + means.size() * sizeof(float) + index.size() * sizeof(std::uint16_t) + value.size() * sizeof(std::int16_t) +
           scale.size() * sizeof(float) + offsets.size() * sizeof(std::uint64_t);
  }
};

/// The wavelet transport of every vertex of `mesh` (unit normals): direct in wavelets; with
/// sh.mode interreflection, the bounces in SH at sh.lmax (ComputeBouncedTransport). Unshadowed
/// mode has no visibility: V = 1. `report` gets the SH bounce pass's report (if any).
WaveletTransport ComputeWaveletTransport(const Mesh& mesh, const TransportOptions& sh, const WaveletOptions& options,
                                         TransportReport* report);

}  // namespace prt
