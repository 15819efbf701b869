#pragma once
/// \file
/// The unshadowed transfer vector of a lobe: for a lobe h about the axis r and a surface of
/// normal n,
///
///   t_k = integral Y_k(s) h(r.s) max(0, n.s) ds,
///
/// so that integral L(s) h(r.s) max(0, n.s) ds = sum_k L_k t_k for any light of bands <= lmax.
/// The product of a lobe about r and a clamped cosine about n is zonal about neither, so there is
/// no closed form; it is integrated by a product rule in the lobe's own frame:
///
///   s = cos(theta) r + sin(theta) (cos(phi) e1 + sin(phi) e2),   e1 along n's part across r,
///   n.s = a + b cos(phi),  a = (n.r) cos(theta),  b = |n x r| sin(theta).
///
/// On the ring of angle theta, n.s > 0 on the arc |phi| < acos(-a/b) (the whole ring when
/// a >= b, none when a <= -b): the arc is integrated by Gauss–Legendre, a whole ring by equally
/// spaced points (exact for its trigonometric polynomial of degree lmax + 1). In theta, the
/// integrand has kinks where rings start and stop crossing the horizon, theta = |pi/2 - g| and
/// pi/2 + g (g the angle between n and r); theta is split there (with pieces graded toward each
/// kink, where the ring integral behaves like a power 3/2) and every lobe width, up to where the
/// lobe falls below 1e-18 of its peak, and each piece is integrated by Gauss–Legendre.
/// Accuracy is measured in tests/material/test_lobe_transfer.cpp against a brute-force
/// integration of a different parametrisation.
///
/// The rule costs thousands of basis evaluations (70 us at lmax 2, 500 us at lmax 8 on an AMD
/// EPYC core), too many per vertex. But in the lobe's frame (r = +Z, n in the XZ plane) the
/// transfer depends on one number, the angle g between n and r; LobeTransferTable integrates it
/// once on a uniform grid of g in [0, pi] (32 nodes per lobe width, at least 1024) and each vertex
/// interpolates (4-point Lagrange, cubic) and turns the result to its own frame with the SH
/// rotation of (e1, e2, r) (sh/rotation.h): t = D(R) t_local(g).

#include <vector>

#include <glm/vec3.hpp>

#include "material/lobe.h"

namespace prt {

/// Writes t_0 .. t_{(lmax+1)^2 - 1} (see above) to `out`; n and r unit vectors.
void LobeTransfer(const Lobe& lobe, const glm::dvec3& n, const glm::dvec3& r, int lmax, double* out);

/// The same through a table over g (see above), built once per lobe and lmax.
class LobeTransferTable {
 public:
  LobeTransferTable(const Lobe& lobe, int lmax);
  /// t for the unit normal n and unit lobe axis r, written to `out`.
  void Transfer(const glm::dvec3& n, const glm::dvec3& r, double* out) const;
  int nodes() const { return nodes_; }

 private:
  int lmax_, count_, nodes_;
  std::vector<double> table_;  ///< [node * count + k], node i at g = pi i / (nodes - 1)
};

/// The lobe's cosine-weighted integral, integral h(r.s) max(0, n.s) ds (sqrt(4 pi) t_0): what a
/// white furnace reflects through the lobe.
double LobeCosineIntegral(const Lobe& lobe, const glm::dvec3& n, const glm::dvec3& r);

/// The mirror of the view direction v (surface to eye) about the unit normal n: 2 (n.v) n - v.
glm::dvec3 MirrorView(const glm::dvec3& n, const glm::dvec3& v);

/// The lobe's axis at a surface point seen from `eye`: the mirrored unit direction to the eye
/// (the normal itself for a point at the eye).
glm::dvec3 LobeAxis(const glm::dvec3& normal, const glm::dvec3& position, const glm::dvec3& eye);

}  // namespace prt
