#pragma once
/// \file
/// A distant light as the wavelet basis sees it: the environment turned by the frame's rotation
/// and resampled onto the cube of wavelet/cube_grid.h, each texel holding its mean radiance over
/// its solid angle,
///
///   L_t = (1 / Omega_t) integral over texel t of L(R^T w) dw,
///
/// so that sum_t L_t T_t is the integral of the light times a transport T_t that is itself an
/// integral over the texel (transport.h). Two parts, each kept exact where
/// it matters:
///   - the radiance the environment's grid resolves (RadianceWithoutDisks) is averaged over
///     `split` x `split` sub-squares of every texel, each weighted by its exact solid angle, so a
///     constant light gives every texel exactly that constant (the white furnace);
///   - the disks no grid resolves (the sky's sun, Environment::Disks) are cut into pieces of
///     equal solid angle (rings even in cos theta, sectors even in azimuth) small beside a texel,
///     each piece's energy added to the texel its centre falls in, so the cube holds each disk's
///     energy exactly, wherever the rotation puts it.
/// Then each face of each colour channel goes through the Haar transform (wavelet/haar.h).
///
/// Keeping only the K most important light coefficients per frame (wavelet/selection.h) is
/// Ng's non-linear approximation of the light [1]; KeepLightTerms does it on the luminance.
/// Measured on the sample knot over a 40 x 40 ground under the sky (AMD EPYC; F 32, 512
/// transport terms, against prt reference): 64 light terms 1.69 %, 256 1.41 %, 1024 and all
/// 1.39 %. It buys no speed here: each vertex's dot product runs over its own kept transport
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

namespace prt {

/// RGB values per texel of a cube, one array per channel.
struct CubeRgb {
  std::vector<double> c[3];
};

class LightCube {
 public:
  /// Resamples `env` (which must outlive this) onto `grid` with `split` x `split` sub-squares
  /// per texel.
  LightCube(const Environment& env, const CubeGrid& grid, int split = 2);

  /// The texels' mean radiance of the environment turned by `turn` (L'(w) = L(turn^T w)).
  void Resample(const glm::dmat3& turn, CubeRgb& out) const;

  const CubeGrid& grid() const { return grid_; }

 private:
  const Environment& env_;
  const CubeGrid& grid_;
  int split_;
  std::vector<double> sub_solid_angle_;  ///< per sub-square of one face
  std::vector<glm::dvec3> disk_pieces_;  ///< centres of the disks' pieces (world directions)
  struct PieceSet {
    glm::dvec3 radiance;
    double solid_angle;                  ///< of each piece
    std::size_t begin, end;              ///< its pieces in disk_pieces_ (world directions)
  };
  std::vector<PieceSet> disks_;
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
