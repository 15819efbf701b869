#pragma once
/// \file
/// How many directions per vertex the shadowed and interreflected transport needs for its
/// bands: the rule behind the defaults of `--samples` and `--hidden-samples`, and the warning
/// below its minimum.
///
/// Projecting visibility onto (L+1)^2 coefficients by N directions leaves Monte Carlo noise
/// that grows with the number of coefficients, while the SH truncation error (what bands above
/// L would add) falls with L. The minimum is where the two meet:
///
///   MinimumSamples(L, s)       = 2^ceil(log2(c_s (L+1)^2))     sampling error = truncation error
///   DefaultHiddenSamples(L, s) = max(1024, 8 MinimumSamples(L, s))
///   DefaultSamples(L, s)       = max(8192, 2 DefaultHiddenSamples(L, s))
///
/// with c_s per sampler s: fibonacci 2, stratified 4, uniform 19. DefaultSamples is for the
/// vertices a frame shows (render/seen_vertices.h; every vertex when there is no camera, as in
/// `prt precompute`), DefaultHiddenSamples for the others.
///
/// The minimum's measurement (`prt report --quick --max-lmax 16 --max-samples 16384`: the
/// report scene, the `sky` environment, shadowed transport, 65536 converged directions,
/// reference of 2048 directions; errors are deterministic, so no CPU enters them; AMD EPYC, 2
/// cores). For each lmax, the truncation error is the converged transport's total error and the
/// crossing is where the sampling error falls to it, interpolated log-log between the doubling
/// sample counts. Crossings per coefficient, N / (L+1)^2, for L = 2..16:
///   fibonacci   1.3 to 1.4 (every L)                   -> c = 2
///   stratified  2.3 at L = 2 rising to 4.0 at L = 16  -> c = 4
///   uniform     5.2 at L = 2 rising to 18.2 at L = 16 -> c = 19
/// Truncation error (relative RMS of vertex radiance) 15.0% at L = 2, 7.1% at L = 8, 4.8% at
/// L = 15. Fibonacci's crossing is proportional to the coefficient count; the others grow a
/// little faster (their error falls as N^-0.7 and N^-0.5 against the truncation error falling
/// with L), so their c is the largest measured and the rule is not meant beyond about L = 16 for
/// them without a new measurement: `prt report` prints the crossings of its own sweep beside
/// what this rule gives.
///
/// The defaults aim at what a viewer sees, not at the RMS: a smooth truncation error is
/// invisible, while independent per-vertex noise of the same RMS shows as blotches. The aim:
/// frame 0 of a render within 2 levels of a converged frame at every pixel and within 1 level at
/// 99.9 % of them. 1024 fibonacci directions at every vertex (8 times the minimum, prt's
/// default before) missed it: on the demo (lmax 4, the sky's sun) up to 8 levels and 1.9 % of
/// the pixels over 1 level from the frame with 16384 directions; on the course's mary under
/// GraceCathedral (lmax 2, shadowed) 6 levels and 0.7 %. Ways tried (`prt report`'s
/// visible-noise table has them on its scene):
///   - one set shared by every vertex (--direction-sets 1): the error is smooth between
///     neighbours but as large; 8 levels, 2.2 % on the demo;
///   - four times the directions everywhere (4096): 3 levels, 0.07 % on the demo; on mary
///     4 levels, 0.06 %;
///   - a cosine-weighted hemisphere set per vertex (no ray below the horizon): at equal rays
///     no better than fibonacci's sphere (3 levels, 0.05 % at 2048 rays a vertex on the demo);
///   - more directions where a first pass's own error estimate (its even and odd directions
///     apart), weighted by the light over its turn, was largest: no better than the same rays
///     spent evenly (the noise is spread over most of the vertices the sun reaches);
///   - more directions for the vertices a frame shows: a pixel is the interpolation of the
///     three vertices of the triangle it shows, so a vertex no frame shows reaches the picture
///     only through the light it bounces, gathered from many hit points at once. The demo shows
///     16149 of its 33985 vertices, mary 3718 of 7905. 8192 directions for those and 1024 for
///     the others met the aim on the demo (2 levels, 0.023 %, 0.29 x the time of 16384 at every
///     vertex, medians of 3), on mary shadowed and with interreflection and on the sample scene
///     of `prt sample-files` (2 levels or fewer, under 0.01 %; 0.18 to 0.38 x), and is the
///     default.
/// 2 DefaultHiddenSamples keeps the seen count at least twice the hidden one above lmax 7.
/// Measured at lmax 2 and 4; at lmax 15 the sun's shadow is sharper and even 16384 directions
/// are not converged (frames 9 levels apart from 32768 on the demo): the aim is not claimed
/// there. Unshadowed transport is closed form and needs no directions at all.
///
/// References
/// [1] Sloan, Kautz, Snyder, "Precomputed Radiance Transfer for Real-Time Rendering in Dynamic,
///     Low-Frequency Lighting Environments", SIGGRAPH 2002, sec. 4 (transfer by Monte Carlo
///     integration over a fixed direction set).
/// [2] Marques et al., "Spherical Fibonacci Point Sets for Illumination Integrals", Computer
///     Graphics Forum 2013 (why fibonacci's error falls faster than N^-1/2).

#include <string>

#include "precompute/samplers.h"

namespace prt {

/// The default for the vertices the camera sees: at least this many, and this factor over the
/// default for those it does not (above: why).
constexpr int kDefaultFloor = 8192;
constexpr int kSeenOverHidden = 2;
/// The default for the vertices it does not see (their light reaches the picture only through
/// bounces, averaged over many hits): the count every vertex had before (above: why 8).
constexpr int kHiddenFloor = 1024;
constexpr int kHiddenMargin = 8;

/// Directions per coefficient at which the sampling error met the truncation error (above).
int SamplesPerCoefficient(Sampler sampler);

/// The fewest directions per vertex whose sampling error stays below the SH truncation error
/// at `lmax` (0..kMaxLmax), a power of two.
int MinimumSamples(int lmax, Sampler sampler);

/// The default directions per vertex at `lmax`: max(1024, 8 MinimumSamples), a power of two.
int DefaultSamples(int lmax, Sampler sampler);

/// The default directions per vertex the camera does not see at `lmax`.
int DefaultHiddenSamples(int lmax, Sampler sampler);

/// "c (L+1)^2 rounded up to a power of two" in words, for help texts and the run summary.
std::string SampleRuleText(Sampler sampler);
/// The same for a run with no camera (precompute), where every vertex takes the seen count.
std::string SampleRuleTextEveryVertex(Sampler sampler);

}  // namespace prt
