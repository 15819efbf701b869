#pragma once
/// \file
/// How many directions per vertex the shadowed and interreflected transport needs for its
/// bands: the rule behind the default of `--samples`, and the warning below its minimum.
///
/// Projecting visibility onto (L+1)^2 coefficients by N directions leaves Monte Carlo noise
/// that grows with the number of coefficients, while the SH truncation error (what bands above
/// L would add) falls with L. More directions than needed to bring the noise under the
/// truncation error buy nothing a user can see; fewer show as per-vertex blotches. So:
///
///   MinimumSamples(L, s) = 2^ceil(log2(c_s (L+1)^2))      sampling error = truncation error
///   DefaultSamples(L, s) = max(1024, 8 MinimumSamples(L, s))
///
/// with c_s per sampler s: fibonacci 2, stratified 4, uniform 19.
///
/// Measurement (`prt report --quick --max-lmax 16 --max-samples 16384`: the report scene, the
/// `sky` environment, shadowed transport, 65536 converged directions, reference of 2048
/// directions; errors are deterministic, so no CPU enters them; measured on an AMD EPYC, 2
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
/// The factor 8 of the default: at equal RMS, per-vertex noise is far more visible than the
/// smooth truncation error. The demo scene at lmax 15 (480x360) shows blotches in the sun's
/// shadow with 1024 fibonacci directions, fainter ones with 2048 and none to see with 4096,
/// which is 8 times the minimum of 512; yet on the report scene the sampling error of 1024 is
/// already under half the truncation error (2.1% against 4.8%; 1.1% at 2048, 0.7% at 4096). Eight times the minimum cuts the sampling error by
/// 8^0.77 = 5 for fibonacci (measured slope -0.77 against directions) and by 2.8 for uniform.
/// The floor of 1024 keeps the low bands where they were: the default is 1024 up to lmax 4 for
/// stratified and up to lmax 7 for fibonacci (the default sampler); uniform, the baseline the
/// others are measured against, needs 2048 already at lmax 2. Unshadowed
/// transport is closed form and needs no directions at all.
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

}  // namespace prt
