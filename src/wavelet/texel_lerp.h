#pragma once
/// \file
/// Sharing a direction among the texels whose centres surround it, so that a compact source
/// moves its light from texel to texel continuously and with its centre where it is.
///
/// The texel centres c_t (unit, wavelet/cube_grid.h) tile the sphere with a dual mesh: around
/// each corner of the texel grid, the centres of the texels that share it, joined by great-circle
/// arcs. Inside a face and across a seam that is a quadrilateral of four centres; at each of the
/// cube's eight corners, where three faces meet, a triangle of three. A unit direction d inside
/// such a cell gets the weights that make d the direction of the weighted sum of its corners:
///
///   quadrilateral c0 c1 c2 c3:  (1-u)(1-v) c0 + u (1-v) c1 + u v c2 + (1-u) v c3  parallel to d,
///   triangle c0 c1 c2:          (1-u-v) c0 + u c1 + v c2                         parallel to d,
///
/// (u, v) in [0, 1] (from the sum's two components across d: a quadratic's root for the
/// quadrilateral, a 2 x 2 system for the triangle). On an arc shared by two cells both give the
/// weights of its two ends alone, (1-u) c_a + u c_b parallel to d, which depend on nothing else:
/// the weights are continuous everywhere, the seams and corners included. They are non-negative
/// and sum to 1, so a source shared by them keeps its energy, and their weighted sum of centres
/// points exactly at d: the light a smooth transport sees from a source moving across a texel
/// differs from the transport at the source only at second order (the chords' sag between the
/// centres). Sharing by tents in the distance to each centre, as this folder did before, moved
/// a source's centre by up to 0.14 of a texel (measured with tests/wavelet/test_light_cube_sun's
/// suns), a first-order wobble that a slow turn showed as flicker.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "wavelet/cube_grid.h"

namespace prt {

class TexelLerp {
 public:
  /// The dual cells of `grid` (which must outlive this).
  explicit TexelLerp(const CubeGrid& grid);

  /// The 3 or 4 texels whose centres surround unit direction `d`, and their weights (>= 0,
  /// summing to 1), into `texels` and `weights`; returns how many.
  int Weights(const glm::dvec3& d, std::uint32_t* texels, double* weights) const;

 private:
  /// The texels around one corner of the grid, in order around it (the last repeated for a
  /// cube's corner, which three share).
  struct Corner {
    std::array<std::uint32_t, 4> texel;
    int count;
  };
  const CubeGrid& grid_;
  std::vector<glm::dvec3> centre_;
  std::vector<Corner> corner_;  ///< texel t's four corners at 4 t + (2 b + a), a along s, b along t
};

}  // namespace prt
