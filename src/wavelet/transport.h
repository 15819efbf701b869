#pragma once
/// \file
/// Per-vertex transport in a Haar wavelet basis on a cube map (all-frequency PRT [1]), beside
/// the SH transport of precompute/transport.h. What it stores, per vertex:
///
///   direct     the transport of each texel t of the cube (wavelet/cube_grid.h),
///                T_t = (1/pi) integral over texel t of V(w) max(0, n.w) dw,
///              taken to Haar coefficients face by face (wavelet/haar.h): the six faces' scaling
///              coefficients (their means) as floats, and of the details only the `budget` - 6
///              most important (wavelet/selection.h), each a 16-bit index and a 16-bit integer
///              times the vertex's step (its largest kept detail / 32767).
///              Then a vertex of albedo rho under a light whose texels hold their mean radiance
///              L_t (wavelet/light_cube.h) sends out  rho sum_t L_t T_t = rho sum_k L^_k T^_k
///              (the transform is orthonormal), a sparse dot product over the kept k.
///   bounced    with interreflection, the light that arrives after one or more bounces, as SH
///              transfer vectors (precompute/transport.h, the bounced part alone): bounced light is low
///              frequency, and the SH light of the same environment lights it.
///
/// The texel integral: the clamped cosine over the texel is exact (CubeGrid::ClampedCosine), and
/// V is its share that rays find open: split x split rays per texel, one in each sub-square at a
/// jittered point (a pool of `kJitterSets` jittered fans, vertex v taking set hash(seed, v)), each
/// weighted by its cosine times its sub-square's solid angle. A vertex that nothing blocks gets
/// the exact transport, so a white sky gives exactly the albedo. Vertices that no frame shows
/// (TransportOptions::seen) take one ray per texel: only --vertex-radiance reads their direct
/// light (their bounces are the SH pass's).
///
/// Memory: 4 bytes a kept detail, plus 36 a vertex (means, step, offset): 2,060 bytes at the
/// default 512 terms, against 4,104 with 32-bit indices and float values. Quantising costs
/// nothing measurable: each detail's error is at most half a step, 1.5e-5 of the vertex's
/// largest, and a white sky still gives exactly the albedo (the means are floats).
///
/// Defaults, measured (AMD EPYC, 2 vCPUs): the sample knot over a ground of 40 x 40 quads under
/// the built-in sky (2-degree sun), 5,521 vertices, per-vertex relative RMS against prt reference
/// (65,536 directions, its own error 0.03 %), shadowed:
///
///   F   rays a texel   kept 256   kept 512        kept 1024   all kept
///   16  16             8.0 %      1.47 %          -           -
///   32  4              9.1 %      1.39 % (1.75 %  1.01 %      0.67 % (6,144)
///                                 by magnitude)
///   64  1              -          1.45 %          1.20 %      0.51 % (24,576)
///
/// (SH: lmax 2, 4, 8, 16: 12.6, 8.7, 6.0, 3.9 %.) One bounce (SH lmax 4) at F 32, 512 kept:
/// 1.62 %. Below about 400 terms the truncation error jumps: the smooth cosine over the open
/// sky needs its fine coefficients wherever the sun may stand. So: F = 32, 4 rays a texel, 512
/// kept, area-weighted. The whole `prt render` of that scene (--max-edge 0.2, 160x120, one frame,
/// median of 3) takes 2.1 s and 68 MB at these defaults, against 4.0 s and 195 MB at SH lmax 16.
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
