#pragma once
/// \file
/// Wigner's small d-matrix d^l_{mk}(beta), the rotation about the y axis, for every band up to
/// lmax, by the three-term recurrence in l.
///
/// For fixed (m, k), d^l_{mk}(beta) as a function of l is a Jacobi polynomial in cos(beta)
/// times a fixed factor, and satisfies [1, 2]
///   l sqrt(((l+1)^2 - m^2)((l+1)^2 - k^2)) d^{l+1}
///       = (2l+1) (l(l+1) cos(beta) - m k) d^l - (l+1) sqrt((l^2 - m^2)(l^2 - k^2)) d^{l-1},
/// started at l0 = max(|m|, |k|), where the d^{l0-1} term vanishes, from the closed form
///   d^{l0}_{l0,k} = (-1)^(l0-k) sqrt(C(2 l0, l0 + k)) cos(beta/2)^(l0+k) sin(beta/2)^(l0-k)
/// and its symmetries d_{mk} = (-1)^(m-k) d_{km} = d_{-k,-m}. Like the recurrence of the
/// associated Legendre functions (d^l_{m0} is one, up to normalisation), running it upward in l
/// is stable: the band matrices built from it stay orthogonal to 2e-14 at lmax 200 (measured
/// figures in sh/rotation.h), where the Ivanic–Ruedenberg recurrence on whole band matrices
/// drifts to 2e-8 at lmax 100 and to 7e4 by 200.
/// The start value (up to C(400, 200) ~ 1e119 times powers of 1/2) is formed in long double
/// logarithms, so it carries no error beyond the last bit of a double.
///
/// Convention: d^l_{mk}(beta) = <l m| exp(-i beta J_y) |l k> (Wigner's; Edmonds [1] 4.1).
///
/// References
/// [1] Edmonds, "Angular Momentum in Quantum Mechanics", Princeton 1957, 4.1 and 4.8.
/// [2] Kostelec, Rockmore, "FFTs on the Rotation Group", J. Fourier Anal. Appl. 14, 2008,
///     section 2 (the recurrence in l, used there to bandwidth 512).

namespace prt {

/// d^l_{mk}(beta) for l = max(|m|, |k|) .. lmax, written to out[l] (entries below l0 are not
/// touched). |m|, |k| <= lmax.
void WignerDRun(int m, int k, double beta, int lmax, double* out);

/// The same entry by Wigner's explicit sum, in long double: slow and, for large l, cancelling;
/// the reference for tests at low l.
double WignerDExplicit(int l, int m, int k, double beta);

}  // namespace prt
