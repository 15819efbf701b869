#pragma once
/// \file
/// Rotation of real SH coefficients.
///
/// A rotation R maps each band onto itself: Y_l(R d) = D_l(R) Y_l(d), with D_l an orthogonal
/// (2l+1)x(2l+1) matrix. If an environment L is turned by R, i.e. L'(R d) = L(d), its
/// coefficients become c'_l = D_l(R) c_l.
///
/// D_1 is R itself, reordered to the basis order (y, z, x) and signed for the Condon–Shortley
/// phase. Higher bands follow exactly from D_1 and D_{l-1} by the recurrence of Ivanic and
/// Ruedenberg [1, 2]: each entry is u U + v V + w W, where U, V, W are sums of products of one
/// D_1 entry with one D_{l-1} entry. No angles, no Wigner-d series, exact to rounding for any l.
/// The recurrence is written for the basis without the Condon–Shortley phase; ours is
/// S D S with S = diag((-1)^m).
///
/// Rotations about the polar axis +Z need no matrices: band l mixes only (m, -m) pairs by
/// cos(m a) and sin(m a) (RotateAboutZ).
///
/// References
/// [1] Ivanic, Ruedenberg, "Rotation Matrices for Real Spherical Harmonics. Direct Determination
///     by Recursion", J. Phys. Chem. 100(15), 1996; Additions and Corrections, 102(45), 1998.
/// [2] Green, "Spherical Harmonic Lighting: The Gritty Details", GDC 2003 (the same recurrence
///     presented for graphics).

#include <vector>

#include <glm/mat3x3.hpp>

#include "sh/coeffs.h"

namespace prt {

/// The band matrices D_0..D_lmax of one rotation, built once and applied to many vectors.
class ShRotation {
 public:
  /// R must be a proper rotation (orthonormal, det +1); 0 <= lmax <= kMaxBasisLmax.
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
