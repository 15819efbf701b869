#pragma once
/// \file
/// Spherical harmonics over the texels of a cube (wavelet/cube_grid.h): the integrals
///
///   Ybar_j(t) = integral over texel t of Y_j(w) dw,   j < (lmax + 1)^2,
///
/// taken by the midpoint rule on 4 x 4 sub-squares of exact solid angle (sh/basis.h's real
/// basis). They carry a function given by its texel integrals (a transport T_t, transport.h)
/// or by its texel means (a light L_t, light_cube.h) to SH and back:
///
///   Project    s_j = sum_t (T_t / Omega_t) Ybar_j(t)   (the SH projection of the function that
///                                                       is T_t / Omega_t over texel t)
///   Texels     S_t = sum_j s_j Ybar_j(t)                (the texel integrals of sum_j s_j Y_j)
///   OfLight    l_j = sum_t L_t Ybar_j(t)                (the projection of the texel light)
///
/// so that sum_t L_t S_t = sum_j s_j l_j exactly, whatever the quadrature's own error: a
/// transport split as T_t = S_t + W_t gives sum_t L_t T_t = sum_j s_j l_j + sum_t L_t W_t.

#include <cstddef>
#include <vector>

#include "wavelet/cube_grid.h"

namespace prt {

class TexelSh {
 public:
  TexelSh(const CubeGrid& grid, int lmax);

  int lmax() const { return lmax_; }
  int count() const { return count_; }

  /// s (count() values) from the texel integrals `integrals` (grid.texels() values).
  void Project(const double* integrals, double* s) const;
  /// integrals[t] -= S_t for the SH function with coefficients `s`.
  void Subtract(const double* s, double* integrals) const;
  /// l (count() values) of the texel means `means`.
  void OfLight(const std::vector<double>& means, double* l) const;

 private:
  int lmax_, count_;
  std::size_t texels_;
  std::vector<double> ybar_;      ///< [j * texels + t]
  std::vector<double> inv_area_;  ///< 1 / Omega_t
};

}  // namespace prt
