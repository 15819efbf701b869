#pragma once
/// \file
/// Spreading a direction over the texels near it: the weights with which a compact source at
/// unit direction d is shared among the texels of a cube (wavelet/cube_grid.h),
///
///   w_t(d) = k_t(d) / sum_u k_u(d),   k_t(d) = max(0, 1 - |d - c_t| / r_t),
///
/// a tent in the chord distance to texel t's centre c_t, of radius r_t = kTentRadius sqrt(Omega_t)
/// (about one texel's width wherever the texel lies on the cube). The weights sum to 1, so a source
/// spread by them keeps its energy exactly; each k_t is continuous in d and the sum never falls
/// near 0 (a direction is always within 0.8 r of some centre), so the weights vary continuously as
/// the source moves, across the faces' seams and corners too: a sun that turns slowly moves its
/// light from texel to texel without a jump. Binning it into the one texel it falls in instead
/// would make everything it lights jump whenever it crosses a texel's edge (the weight a texel's
/// transport gives it differs by several percent across a texel of 2.8 degrees).
///
/// The texels that can have a weight at some direction of texel h are listed once per texel
/// (those whose tent reaches h), so one spread reads about ten texels.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "wavelet/cube_grid.h"

namespace prt {

/// The tent's radius in units of sqrt(Omega_t), the texel's angular width.
inline constexpr double kTentRadius = 1.0;
/// The most texels one spread can touch (the constructor checks no list is longer).
inline constexpr int kMaxSpread = 32;

class TexelSpread {
 public:
  /// The tents of `grid`'s texels; `grid` must outlive this.
  explicit TexelSpread(const CubeGrid& grid);

  /// The texels sharing unit direction `d` and their weights (summing to 1), into `texels` and
  /// `weights` (room for kMaxSpread each); returns how many.
  int Spread(const glm::dvec3& d, std::uint32_t* texels, double* weights) const;

  /// k_t(d), the tent of texel t before normalising (for tests).
  double Tent(std::size_t t, const glm::dvec3& d) const;
  /// The texels whose tent may reach some direction of texel `home`.
  const std::uint32_t* Reach(std::size_t home, std::size_t& count) const;

 private:
  const CubeGrid& grid_;
  std::vector<glm::dvec3> centre_;
  std::vector<double> inv_radius_;
  std::vector<std::uint32_t> offset_, reach_;
};

}  // namespace prt
