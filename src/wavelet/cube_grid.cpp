#include "wavelet/cube_grid.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "env/cube_faces.h"

namespace prt {
namespace {

const std::array<FaceFrame, 6>& Frames() { return FaceFrames(CubeLayout::kStandard); }

}  // namespace

CubeGrid::CubeGrid(int size) : size_(size) {
  if (size < 1 || size > 512 || (size & (size - 1)) != 0)
    throw Error("cube face size " + std::to_string(size) + ": must be a power of two from 1 to 512");
  solid_angle_.resize(face_texels());
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) solid_angle_[std::size_t(row) * size + col] = TexelSolidAngle(col, row, size);
}

glm::dvec3 CubeGrid::FacePoint(int face, double s, double t) const {
  const FaceFrame& f = Frames()[face];
  return glm::normalize(f.n + s * f.u + t * f.v);
}

glm::dvec3 CubeGrid::Direction(std::size_t t) const {
  const std::size_t face = t / face_texels(), rest = t % face_texels();
  const double step = 2.0 / size_;
  const int row = static_cast<int>(rest / size_), col = static_cast<int>(rest % size_);
  return FacePoint(static_cast<int>(face), -1.0 + (col + 0.5) * step, -1.0 + (row + 0.5) * step);
}

std::size_t CubeGrid::TexelOf(const glm::dvec3& d) const {
  // The face whose axis the direction is closest to (the largest |component|), then the point
  // where the direction crosses its plane.
  const glm::dvec3 a = glm::abs(d);
  int face;
  if (a.x >= a.y && a.x >= a.z) face = d.x >= 0 ? 0 : 1;
  else if (a.y >= a.z) face = d.y >= 0 ? 2 : 3;
  else face = d.z >= 0 ? 4 : 5;
  const FaceFrame& f = Frames()[face];
  const double along = glm::dot(d, f.n);
  const double s = glm::dot(d, f.u) / along, t = glm::dot(d, f.v) / along;
  const auto cell = [this](double x) {
    return std::clamp(static_cast<int>(std::floor((x + 1.0) * 0.5 * size_)), 0, size_ - 1);
  };
  return (static_cast<std::size_t>(face) * size_ + cell(t)) * size_ + cell(s);
}

double CubeGrid::ClampedCosine(std::size_t t, const glm::dvec3& n) const {
  const std::size_t face = t / face_texels(), rest = t % face_texels();
  const FaceFrame& f = Frames()[face];
  const double step = 2.0 / size_;
  const double s0 = -1.0 + double(rest % size_) * step, t0 = -1.0 + double(rest / size_) * step;
  // The texel's corners on the face plane, in order around it.
  const std::array<glm::dvec3, 4> quad = {f.n + s0 * f.u + t0 * f.v, f.n + (s0 + step) * f.u + t0 * f.v,
                                          f.n + (s0 + step) * f.u + (t0 + step) * f.v,
                                          f.n + s0 * f.u + (t0 + step) * f.v};
  // Clip by the horizon n.x >= 0 (Sutherland–Hodgman against one plane).
  std::array<glm::dvec3, 8> poly;
  int m = 0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3& a = quad[i];
    const glm::dvec3& b = quad[(i + 1) % 4];
    const double da = glm::dot(n, a), db = glm::dot(n, b);
    if (da >= 0) poly[m++] = a;
    if ((da >= 0) != (db >= 0)) poly[m++] = a + (b - a) * (da / (da - db));
  }
  if (m < 3) return 0.0;
  // Lambert's formula; the sign of the sum fixes the orientation (a texel is far smaller than a
  // hemisphere, so its vector irradiance points into it).
  glm::dvec3 phi(0.0), centre(0.0);
  for (int i = 0; i < m; ++i) {
    const glm::dvec3 a = glm::normalize(poly[i]), b = glm::normalize(poly[(i + 1) % m]);
    centre += a;
    const glm::dvec3 c = glm::cross(a, b);
    const double len = glm::length(c);
    if (len == 0.0) continue;
    phi += std::atan2(len, glm::dot(a, b)) * (c / len);
  }
  if (glm::dot(phi, centre) < 0) phi = -phi;
  return std::max(0.0, 0.5 * glm::dot(n, phi));
}

void CubeGrid::SubTexels(int split, std::vector<glm::dvec3>& dirs, std::vector<double>& solid_angles) const {
  const std::size_t per = static_cast<std::size_t>(split) * split;
  dirs.resize(texels() * per);
  solid_angles.resize(texels() * per);
  const double step = 2.0 / size_, sub = step / split;
  for (std::size_t t = 0; t < texels(); ++t) {
    const std::size_t face = t / face_texels(), rest = t % face_texels();
    const double s0 = -1.0 + double(rest % size_) * step, t0 = -1.0 + double(rest / size_) * step;
    for (int i = 0; i < split; ++i)
      for (int j = 0; j < split; ++j) {
        const double a = s0 + j * sub, b = t0 + i * sub;
        const std::size_t k = t * per + static_cast<std::size_t>(i) * split + j;
        dirs[k] = FacePoint(static_cast<int>(face), a + 0.5 * sub, b + 0.5 * sub);
        solid_angles[k] = FaceRectSolidAngle(a, b, a + sub, b + sub);
      }
  }
}

}  // namespace prt
