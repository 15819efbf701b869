#pragma once
/// \file
/// A distant light as the wavelet basis sees it: the environment turned by the frame's rotation
/// and put on the cube of wavelet/cube_grid.h, each texel t holding a radiance L_t such that
/// sum_t L_t T_t approximates the integral of the light times a transport T_t that is itself an
/// integral over the texel (transport.h). Three properties are kept, at every rotation:
///
///   energy     sum_t Omega_t L_t equals the environment's own integral (its quadrature rows and
///              its disks, env/environment.h) per channel, up to rounding: nothing is point
///              sampled, so a sun a few pixels wide in an HDR file keeps its energy wherever the
///              rotation puts it;
///   constants  a constant light gives every texel exactly that constant (the white furnace);
///   smoothness a compact source's light moves continuously from texel to texel as it turns, its
///              centre exactly where the turn puts it (wavelet/texel_lerp.h), so nothing it
///              lights flickers in a slow turn.
///
/// How. Once per environment, its quadrature nodes (pixels with their exact solid angles, or a
/// procedural light's product rule) are gathered into the cells of a finer cube, `fine` x `fine`
/// cells a texel: each cell keeps the energy and solid angle of the nodes in it and their
/// centroid weighted by luminance (where the light in the cell comes from), a node larger than a
/// cell being first cut into equal parts around its direction. Each cell's light is split in
/// two: its floor, the least radiance (per channel) of the cells within a texel's width of it on
/// its face, over the cell's solid angle, and what rises above that floor (a sun smaller than a
/// texel rises whole). The disks no grid resolves (the sky's sun) are cut into pieces of equal
/// solid angle small beside a cell, all rise. Each frame every cell and piece, turned, is shared
/// among the three or four texels whose centres surround it (TexelLerp); texel t gathers the
/// floors' energy F_t, their solid angle A_t (the cells tile the sphere) and the rise R_t, and
///
///   L_t = c F_t / A_t + R_t / Omega_t,
///
/// the floor a mean radiance, so a constant light (all floor) stays exactly constant, and the
/// rise a source's energy over the texel's own solid angle, so a sun keeps exactly its energy and
/// its centre. One factor c per channel returns the floors' total to theirs (A_t differs from
/// Omega_t by the cells' quadrature of the weights, and the texels near the cube's seams and
/// corners gather up to 1.3 % more and 11 % less than their own solid angle: dividing a sun's light
/// by A_t, as every cell's once was, moved its light and its centre as it crossed them).
///
/// Measured (tests/wavelet/test_light_cube_sun.cpp; Intel Xeon, F 32): under a sun of 2 x 2
/// pixels of a 1024 x 512 image (smaller than a cell) carrying half of its channel's energy over
/// a smooth sky, 2, 30, 60 and 85 degrees up, on a seam and at a corner of the cube, turned in
/// steps of 0.94 degrees, what fixed shadings see of that channel (the ground's clamped cosine and
/// smooth lobes (1 + n.w)^2 / 4 of four normals), against the image's own quadrature: its error
/// changes by at most 0.036 % a step at still quality (8 cells a texel) and 0.046 % at
/// interactive (2), and is at most 0.11 % (before: 0.51 to 1.2 % a step under five of the six
/// suns at still quality, 2.9 % at interactive; the ground under the sun 2 degrees up 1.4 % too
/// dark). Measured the same way outside the tests, under sky.hdr's image (the built-in sky at
/// 1024 x 512, its sun 4 degrees wide) over 48 steps: the ground's irradiance in green changes by
/// at most 0.0033 % a step at still quality and 0.0034 % at interactive (before: 0.036 and
/// 0.88 %).
///
/// Keeping only the K most important light coefficients per frame (wavelet/selection.h) is
/// Ng's non-linear approximation of the light [1]; KeepLightTerms does it on the luminance.
/// Measured on the sample knot over a 40 x 40 ground under sky.hdr (Intel Xeon; F 32, 512
/// transport terms, against prt reference; with the light shared by tents, before TexelLerp): 64
/// light terms 1.42 %, 256, 1024 and all 1.26 %. It buys no speed here: each vertex's dot product
/// runs over its own kept transport
/// terms whatever the light keeps (Ng stored the transport by light coefficient instead), so it
/// is off by default and serves to show what the basis keeps (--view light).
///
/// References
/// [1] Ng, Ramamoorthi, Hanrahan, "All-Frequency Shadows Using Non-linear Wavelet Lighting
///     Approximation", SIGGRAPH 2003.

#include <cstddef>
#include <vector>

#include <glm/mat3x3.hpp>

#include "env/environment.h"
#include "wavelet/cube_grid.h"
#include "wavelet/selection.h"
#include "wavelet/texel_lerp.h"

namespace prt {

/// RGB values per texel of a cube, one array per channel.
struct CubeRgb {
  std::vector<double> c[3];
};

class LightCube {
 public:
  /// Gathers `env` into cells `fine` x `fine` a texel of `grid` (which must outlive this); 0:
  /// kFineCells, fewer if the cells' cube would pass kMaxCellFace a side.
  LightCube(const Environment& env, const CubeGrid& grid, int fine = 0);

  /// The light of the environment turned by `turn` (L'(w) = L(turn^T w)) on the texels.
  void Resample(const glm::dmat3& turn, CubeRgb& out) const;

  const CubeGrid& grid() const { return grid_; }
  /// The environment's integral per channel, as the cube keeps it.
  const glm::dvec3& Energy() const { return energy_; }

  /// Cells a texel, along each side. Measured under the suns above (the file comment): steps of
  /// at most 0.036 % at 8 cells a texel, 0.046 % at 2. At F 32 under a 1024 x 512 image (one
  /// thread of an Intel Xeon, medians): building the cube 190 ms at 8 cells, 14 ms at 2 (170-194
  /// and 19 ms sharing by tents); a frame's Resample 31 ms at 8, 2.1 ms at 2 (26 and 2.0 ms).
  static constexpr int kFineCells = 8;
  /// The cells' cube at most this many a side (6 x 256^2 cells: 31 MB while gathering).
  static constexpr int kMaxCellFace = 256;

 private:
  struct Piece {
    glm::dvec3 dir;       ///< world direction (unit)
    double solid_angle;   ///< 0 for a disk's piece (the cells alone tile the sphere)
    glm::dvec3 base;      ///< the floor's radiance times solid_angle
    glm::dvec3 rise;      ///< the rest of the piece's energy (radiance times solid angle)
  };
  const CubeGrid& grid_;
  TexelLerp lerp_;
  std::vector<Piece> pieces_;
  glm::dvec3 energy_{0.0};
  glm::dvec3 base_energy_{0.0};  ///< the pieces' base, summed
};

/// Integral of the cube's radiance over the sphere, per channel: sum_t Omega_t L_t.
glm::dvec3 CubeIntegral(const CubeGrid& grid, const CubeRgb& rgb);

/// The Haar transform of every face of every channel, in place (and its inverse).
void CubeToHaar(int face_size, CubeRgb& rgb);
void CubeFromHaar(int face_size, CubeRgb& rgb);

/// Keeps the `terms` light coefficients of largest importance (selection weights times the
/// Rec. 709 luminance of the coefficient's three channels), setting the others to 0 in every
/// channel. Returns how many were kept.
std::size_t KeepLightTerms(const std::vector<double>& weights, std::size_t terms, CubeRgb& coeffs);

}  // namespace prt
