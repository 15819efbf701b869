#pragma once
/// \file
/// Rotation of real SH coefficients.
///
/// A rotation R maps each band onto itself: Y_l(R d) = D_l(R) Y_l(d), with D_l an orthogonal
/// (2l+1)x(2l+1) matrix. If an environment L is turned by R, i.e. L'(R d) = L(d), its
/// coefficients become c'_l = D_l(R) c_l.
///
/// The band matrices are built from the Euler factorisation R = Rz(alpha) Ry(beta) Rz(gamma):
///   D_l(R) = Z_l(alpha) Y_l(beta) Z_l(gamma),
/// where Z_l(a), the turn about the polar axis, only mixes each (m, -m) pair by cos(m a) and
/// sin(m a) (exact: no recurrence at all), and Y_l(beta) is Wigner's small d-matrix
/// (sh/wigner_d.h, a recurrence in l that stays stable at high order) taken to the real basis.
/// Measured (tests/sh/test_rotation.cpp): max |D_l D_l^T - I| 1.1e-15 at lmax 64, 2.4e-15 at
/// 100, 2e-14 at 200, and max |Y(R d) - D Y(d)| 1e-13 at 200, near-degenerate rotations
/// (beta within 1e-9 of 0 or pi) included. The Ivanic–Ruedenberg recurrence on whole band
/// matrices [1], used before, drifts from orthogonality as l grows (2.4e-11 at lmax 64, 5.7e-8
/// at 100, useless by 200). Orders above kMaxBasisLmax are refused with an Error.
///
/// Rotations about the polar axis +Z need no matrices at all (RotateAboutZ).
///
/// References
/// [1] Ivanic, Ruedenberg, "Rotation Matrices for Real Spherical Harmonics. Direct Determination
///     by Recursion", J. Phys. Chem. 100(15), 1996 (the recurrence this replaced).
/// [2] Blanco, Florez, Bermejo, "Evaluation of the rotation matrices in the basis of real
///     spherical harmonics", J. Mol. Struct. (Theochem) 419, 1997 (real from complex d-matrices).

#include <vector>

#include <glm/mat3x3.hpp>

#include "sh/coeffs.h"

namespace prt {

/// The band matrices D_0..D_lmax of one rotation, built once and applied to many vectors.
class ShRotation {
 public:
  /// R must be a proper rotation (orthonormal, det +1); lmax outside 0..kMaxBasisLmax throws
  /// Error. Costs O(lmax^3): 0.16 s at lmax 200.
  ShRotation(const glm::dmat3& R, int lmax);

  int lmax() const { return lmax_; }
  /// D_l, row-major, (2l+1)^2 entries; entry (m, m') at [(m + l)(2l + 1) + (m' + l)].
  const std::vector<double>& Band(int l) const { return bands_[l]; }

  /// c' = D c for one coefficient vector of bands 0..lmax (in and out may not alias).
  void Apply(const double* in, double* out) const;
  /// The same for RGB coefficients (their own lmax may be lower than lmax()).
  ShRgb Apply(const ShRgb& in) const;

 private:
  int lmax_;
  std::vector<std::vector<double>> bands_;
};

/// Coefficients of the environment turned by angle `a` (radians, right-handed) about +Z.
ShRgb RotateAboutZ(const ShRgb& in, double a);

/// The rotation matrix of angle `a` (radians, right-handed) about the unit axis `axis`.
glm::dmat3 AxisAngle(const glm::dvec3& axis, double a);

}  // namespace prt
