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
///   smoothness a compact source's light moves continuously from texel to texel as it turns
///              (wavelet/texel_spread.h), so nothing it lights flickers in a slow turn.
///
/// How. Once per environment, its quadrature nodes (pixels with their exact solid angles, or a
/// procedural light's product rule) are gathered into the cells of a finer cube, `fine` x `fine`
/// cells a texel: each cell keeps the energy and solid angle of the nodes in it and their
/// centroid weighted by luminance (where the light in the cell comes from), a node larger than a
/// cell being first cut into equal parts around its direction.
/// The disks no grid resolves (the sky's sun) are cut into pieces of equal solid angle small
/// beside a cell. Each frame every cell and piece, turned, is spread over the texels by
/// TexelSpread: texel t gathers energy E_t and solid angle A_t (from the cells alone, which tile
/// the sphere), and L_t = E_t / A_t, so a constant stays exactly constant; then one factor per
/// channel returns the total to the environment's integral (A_t differs from Omega_t by the
/// cells' quadrature of the tent).
///
/// Keeping only the K most important light coefficients per frame (wavelet/selection.h) is
/// Ng's non-linear approximation of the light [1]; KeepLightTerms does it on the luminance.
/// Measured on the sample knot over a 40 x 40 ground under sky.hdr (Intel Xeon; F 32, 512
/// transport terms, against prt reference): 64 light terms 1.42 %, 256, 1024 and all 1.26 %. It buys no speed here: each vertex's dot product runs over its own kept transport
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
#include "wavelet/texel_spread.h"

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

  /// Cells a texel, along each side. Measured on the sample knot's sunlit ground in a slow turn
  /// under sky.hdr (48 frames 0.94 degrees apart, F 32, 512 terms): the mean changes from frame
  /// to frame by at most 0.25 % at 4 cells a texel, 0.10 % at 8 (0.20 and 0.04 % with every
  /// coefficient kept: the cells' quadrature of the tents is most of it).
  static constexpr int kFineCells = 8;
  /// The cells' cube at most this many a side (6 x 256^2 cells: 31 MB while gathering).
  static constexpr int kMaxCellFace = 256;

 private:
  struct Piece {
    glm::dvec3 dir;       ///< world direction (unit)
    double solid_angle;   ///< 0 for a disk's piece (the cells alone tile the sphere)
    glm::dvec3 energy;    ///< radiance times solid angle
  };
  const CubeGrid& grid_;
  TexelSpread spread_;
  std::vector<Piece> pieces_;
  glm::dvec3 energy_{0.0};
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
