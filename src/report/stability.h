#pragma once
/// \file
/// The stiff and extreme cases of `prt report --stability`. Each case states what it checks,
/// the measured figure, the limit and pass or fail:
///   - high bands: basis orthonormality at lmax 32 and 64 on an exact Gauss rule [1], rotation
///     Y(R d) = D(R) Y(d) and orthogonality of D(R) at lmax 32, 64, 100 and 200, the basis finite
///     to lmax 200 at the exact poles and at z = 1 - 1e-15;
///   - an HDR sun (peak/mean > 1e4): ringing as min(reconstruction)/peak for no window, Hann and
///     Lanczos; `--window auto` at lmax 2, 4, 8 and 16, and on a sun of 1e5 x the mean at lmax
///     8 and 64, each failing if any direction stays negative (its own search and 200,000
///     Fibonacci directions);
///   - scene scale 1e-4 and 1e4: a lone convex sphere is never shadowed;
///   - 36000 frames of rotation: the last frame rebuilt from its absolute angle against the
///     directly rotated coefficients, and what accumulating per-frame steps in float gives;
///   - 10^6 terms of a Monte Carlo transfer estimate summed naively in float, naively in double
///     and compensated (Neumaier), each against a long-double sum of the same terms [2];
///   - awkward inputs (stability_inputs.h): extreme meshes, albedo 0.99 with 64 bounces in a
///     deep well, NaN/Inf/negative/1e30 texels, a Phong lobe of N = 1000 at lmax 2 (both glossy
///     paths);
///   - each basis's own cases, whose basis has a study (Basis::Study, basis/study.h), in the
///     list's order (bases/list.h): the wavelet basis's is against prt reference on the scene
///     it was measured on (a knot on a 40 x 40 ground under the sky's small sun) at the default
///     budget, shadowed and with one bounce.
///
/// References
/// [1] Atkinson, Han, "Spherical Harmonics and Approximations on the Unit Sphere", 2012, 5.2.
/// [2] Higham, "The accuracy of floating point summation", SIAM J. Sci. Comput. 14(4), 1993.

#include <string>
#include <vector>

#include "basis/stability_case.h"
#include "basis/study.h"

namespace prt {

/// What the bases' cases run on: a knot (segments x sides) on a ground (quads a side). The
/// default (all 0) is each basis's measured scene, the one `prt report --stability` runs and
/// whose figures its limits were set from; the tests' runs under a sanitizer take a smaller one.
struct StabilityOptions {
  StudySceneSize study_scene;
  /// Whether the other cases, whose inputs are fixed, run too (false: the bases' ones alone).
  bool fixed_cases = true;
};

/// Runs every case (24 s on 2 cores of an AMD EPYC, 17 s of it the wavelet cases' references
/// and transports).
std::vector<StabilityCase> RunStabilityCases(const StabilityOptions& options = {});

/// stability.csv and the Markdown table of the cases.
std::string StabilityCsv(const std::vector<StabilityCase>& cases);
std::string StabilityMarkdown(const std::vector<StabilityCase>& cases);

}  // namespace prt
