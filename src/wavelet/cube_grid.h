#pragma once
/// \file
/// The cube map on which the wavelet basis lives: six faces of F x F texels, F a power of two,
/// faces and orientation as the standard table of env/cube_faces.h (posx negx posy negy posz
/// negz). Texel t = (face * F + row) * F + col looks along normalize(N + s U + t V) at the centre
/// of its square of face coordinates, and covers the exact solid angle TexelSolidAngle gives
/// (all 6 F^2 of them sum to 4 pi).
///
/// The clamped cosine over one texel has a closed form, so the transport of a vertex that
/// nothing blocks is exact in this basis: the texel is a spherical quadrilateral whose edges are
/// great-circle arcs (straight lines of the face plane), the part above the horizon of n is the
/// quadrilateral clipped by the plane n.x = 0 (a plane through the centre, so clipping the flat
/// face polygon is exact), and for a spherical polygon with unit corners v_i Lambert's formula
/// gives [1, eq. 10; 2]
///
///   integral over P of (n . w) dw = 1/2 sum_i  angle(v_i, v_(i+1))  n . unit(v_i x v_(i+1)),
///
/// with the corners in counter-clockwise order seen from outside.
///
/// References
/// [1] Arvo, "Applications of Irradiance Tensors to the Simulation of Non-Lambertian Phenomena",
///     SIGGRAPH 1995 (the vector irradiance of a polygon).
/// [2] Lambert, "Photometria", 1760 (the form factor of a polygon).

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace prt {

class CubeGrid {
 public:
  /// A grid of faces `size` x `size`; `size` a power of two from 1 to 512.
  explicit CubeGrid(int size);

  int size() const { return size_; }
  std::size_t texels() const { return 6 * face_texels(); }
  std::size_t face_texels() const { return static_cast<std::size_t>(size_) * size_; }

  /// Unit direction through the centre of texel t.
  glm::dvec3 Direction(std::size_t t) const;
  /// Unit direction through face coordinates (s, t) in [-1, 1]^2 of `face`.
  glm::dvec3 FacePoint(int face, double s, double t) const;
  /// Exact solid angle of texel t.
  double SolidAngle(std::size_t t) const { return solid_angle_[t % face_texels()]; }
  /// The texel that unit (or any non-zero) direction `d` goes through.
  std::size_t TexelOf(const glm::dvec3& d) const;
  /// Exact integral over texel t of max(0, n . w) dw, n a unit normal (the file comment).
  double ClampedCosine(std::size_t t, const glm::dvec3& n) const;

  /// The `split` x `split` sub-squares of every texel, in texel order (texel t owns entries
  /// t * split^2 .. (t + 1) * split^2 - 1): their centre directions and exact solid angles.
  void SubTexels(int split, std::vector<glm::dvec3>& dirs, std::vector<double>& solid_angles) const;

 private:
  int size_;
  std::vector<double> solid_angle_;  ///< per texel of one face (the same on every face)
};

}  // namespace prt
