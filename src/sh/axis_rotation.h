#pragma once
/// \file
/// Turning a light about one fixed axis, frame after frame, cheaply and without drift.
///
/// About the SH polar axis +Z a turn by angle a only mixes each (m, -m) pair by cos(m a) and
/// sin(m a): O(lmax^2) a frame, no matrices (RotateAboutZ). Any other axis k is brought onto
/// +Z by a fixed rotation Q (Q k = +Z), so that
///     R_k(a) = Q^T R_z(a) Q   and   D(R_k(a)) = D(Q)^T D(R_z(a)) D(Q):
/// the band matrices of Q are built once, and each frame applies D(Q), the cheap polar turn,
/// and D(Q)^T (the same matrices, transposed). Every frame is built from its absolute angle, never by accumulating per-frame
/// steps, so frame 36000 is as exact as frame 1.

#include <string>

#include <glm/vec3.hpp>

#include "sh/rotation.h"

namespace prt {

class AxisRotation {
 public:
  /// `axis` need not be unit length but must not be zero; lmax is the highest band to turn.
  AxisRotation(const glm::dvec3& axis, int lmax);

  /// The light `coeffs` turned by `angle` radians (right-handed) about the axis.
  ShRgb Rotate(const ShRgb& coeffs, double angle) const;

  /// True when the axis is the polar axis (no conjugation needed).
  bool polar() const { return polar_; }
  /// One line for the run summary: which path is used and why.
  std::string Describe() const;

 private:
  glm::dvec3 axis_;
  bool polar_;
  double sign_;        ///< +1 for +Z, -1 for -Z (polar case)
  ShRotation to_pole_;  ///< D(Q); D(Q)^T turns back
};

}  // namespace prt
