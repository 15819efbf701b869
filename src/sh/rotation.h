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
/// Measured by `prt report --stability` (one seeded random rotation; above lmax 64 every 7th
/// band and the last): max |D_l D_l^T - I| 1.1e-15 at lmax 64, 1.2e-15 at 100, 2.6e-15 at
/// 200, and max |Y(R d) - D Y(d)| 2.3e-14, 5.0e-14, 1.0e-13; rotations within 1e-9 of beta = 0
/// or pi reach 2e-14 in orthogonality at 200 (tests/sh/test_rotation.cpp, which bounds them all
/// by 1e-12 and 1e-11). The Ivanic–Ruedenberg recurrence on whole band matrices [1], used
/// before, drifts as l grows, by an amount that depends on the rotation: measured on the
/// replaced code, 1e-12 to 8e-12 at lmax 64, 4e-10 to 2e-8 at 100, 5e-3 to 7e4 at 200. Orders
/// above kMaxBasisLmax are refused with an Error.
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
  /// Error. Costs O(lmax^3): 0.14 to 0.16 s at lmax 200 (AMD EPYC, one core).
  ShRotation(const glm::dmat3& R, int lmax);

  int lmax() const { return lmax_; }
  /// D_l, row-major, (2l+1)^2 entries; entry (m, m') at [(m + l)(2l + 1) + (m' + l)].
  const std::vector<double>& Band(int l) const { return bands_[l]; }

  /// c' = D c for one coefficient vector of bands 0..lmax (in and out may not alias).
  void Apply(const double* in, double* out) const;
  /// The same for RGB coefficients (their own lmax may be lower than lmax()); `transposed`
  /// applies D^T = D(R^T), the inverse rotation, from the same matrices.
  ShRgb Apply(const ShRgb& in, bool transposed = false) const;

 private:
  int lmax_;
  std::vector<std::vector<double>> bands_;
};

/// Coefficients of the environment turned by angle `a` (radians, right-handed) about +Z.
ShRgb RotateAboutZ(const ShRgb& in, double a);

/// The rotation matrix of angle `a` (radians, right-handed) about the unit axis `axis`.
glm::dmat3 AxisAngle(const glm::dvec3& axis, double a);

}  // namespace prt
