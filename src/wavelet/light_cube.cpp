#include "wavelet/light_cube.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/color.h"
#include "core/constants.h"
#include "core/parallel.h"
#include "env/cube_faces.h"
#include "wavelet/haar.h"

namespace prt {
namespace {

/// A frame (x, y, axis) around unit `axis`.
void Frame(const glm::dvec3& axis, glm::dvec3& x, glm::dvec3& y) {
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  x = glm::normalize(glm::cross(helper, axis));
  y = glm::cross(axis, x);
}

}  // namespace

LightCube::LightCube(const Environment& env, const CubeGrid& grid, int split) : env_(env), grid_(grid), split_(split) {
  // The sub-squares' solid angles, the same on every face.
  const int n = grid.size() * split;
  sub_solid_angle_.resize(static_cast<std::size_t>(n) * n);
  const double step = 2.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      sub_solid_angle_[std::size_t(i) * n + j] =
          FaceRectSolidAngle(-1.0 + j * step, -1.0 + i * step, -1.0 + (j + 1) * step, -1.0 + (i + 1) * step);
  // Each disk cut into rings even in cos theta and sectors even in azimuth: equal solid angles.
  // A texel spans 2 / size radians at a face's centre and about 0.88 / size at the cube's
  // corners (its side over 3^(3/4)); pieces at most 0.35 / size apart (rings 4 a step of
  // 1.4 / size, sectors 8 pi sin(radius) a step along the rim) are under half the smallest.
  const double texel_angle = 1.4 / grid.size();
  for (const LightDisk& d : env.Disks()) {
    const double radius = std::acos(std::clamp(d.cos_radius, -1.0, 1.0));
    const int rings = std::max(16, static_cast<int>(std::ceil(4.0 * radius / texel_angle)));
    const int sectors = std::max(32, static_cast<int>(std::ceil(8.0 * kPi * std::sin(std::min(radius, kPi / 2)) / texel_angle)));
    glm::dvec3 x, y;
    Frame(glm::normalize(d.dir), x, y);
    const glm::dvec3 z = glm::normalize(d.dir);
    const double dz = (1.0 - d.cos_radius) / rings;
    PieceSet set{d.radiance, dz * 2.0 * kPi / sectors, disk_pieces_.size(), 0};
    for (int r = 0; r < rings; ++r) {
      const double cz = 1.0 - (r + 0.5) * dz, sz = std::sqrt(std::max(0.0, 1.0 - cz * cz));
      for (int s = 0; s < sectors; ++s) {
        const double phi = 2.0 * kPi * (s + 0.5) / sectors;
        disk_pieces_.push_back(sz * std::cos(phi) * x + sz * std::sin(phi) * y + cz * z);
      }
    }
    set.end = disk_pieces_.size();
    disks_.push_back(set);
  }
}

void LightCube::Resample(const glm::dmat3& turn, CubeRgb& out) const {
  const std::size_t texels = grid_.texels();
  for (auto& c : out.c) c.assign(texels, 0.0);
  const glm::dmat3 back = glm::transpose(turn);
  const int size = grid_.size(), n = size * split_;
  const double step = 2.0 / n;
  // The grid's radiance: each texel the solid-angle-weighted mean of its sub-squares.
  ParallelFor(texels, 256, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      const int face = static_cast<int>(t / grid_.face_texels());
      const std::size_t rest = t % grid_.face_texels();
      const int row = static_cast<int>(rest / size), col = static_cast<int>(rest % size);
      glm::dvec3 sum(0.0);
      double area = 0.0;
      for (int i = row * split_; i < (row + 1) * split_; ++i)
        for (int j = col * split_; j < (col + 1) * split_; ++j) {
          const double w = sub_solid_angle_[std::size_t(i) * n + j];
          const glm::dvec3 d = grid_.FacePoint(face, -1.0 + (j + 0.5) * step, -1.0 + (i + 0.5) * step);
          sum += w * env_.RadianceWithoutDisks(back * d);
          area += w;
        }
      for (int c = 0; c < 3; ++c) out.c[c][t] = sum[c] / area;
    }
  });
  // The disks: each piece's energy into the texel its turned centre falls in.
  for (const PieceSet& set : disks_)
    for (std::size_t p = set.begin; p < set.end; ++p) {
      const std::size_t t = grid_.TexelOf(turn * disk_pieces_[p]);
      const glm::dvec3 add = set.radiance * (set.solid_angle / grid_.SolidAngle(t));
      for (int c = 0; c < 3; ++c) out.c[c][t] += add[c];
    }
}

glm::dvec3 CubeIntegral(const CubeGrid& grid, const CubeRgb& rgb) {
  glm::dvec3 sum(0.0);
  for (std::size_t t = 0; t < grid.texels(); ++t)
    for (int c = 0; c < 3; ++c) sum[c] += grid.SolidAngle(t) * rgb.c[c][t];
  return sum;
}

void CubeToHaar(int face_size, CubeRgb& rgb) {
  const std::size_t per_face = static_cast<std::size_t>(face_size) * face_size;
  std::vector<double> scratch;
  for (auto& c : rgb.c)
    for (int f = 0; f < 6; ++f) HaarForward(c.data() + f * per_face, face_size, scratch);
}

void CubeFromHaar(int face_size, CubeRgb& rgb) {
  const std::size_t per_face = static_cast<std::size_t>(face_size) * face_size;
  std::vector<double> scratch;
  for (auto& c : rgb.c)
    for (int f = 0; f < 6; ++f) HaarInverse(c.data() + f * per_face, face_size, scratch);
}

std::size_t KeepLightTerms(const std::vector<double>& weights, std::size_t terms, CubeRgb& coeffs) {
  const std::size_t n = coeffs.c[0].size();
  std::vector<double> luminance(n);
  for (std::size_t i = 0; i < n; ++i)
    luminance[i] = kLuminanceWeights[0] * std::abs(coeffs.c[0][i]) + kLuminanceWeights[1] * std::abs(coeffs.c[1][i]) +
                   kLuminanceWeights[2] * std::abs(coeffs.c[2][i]);
  std::vector<std::uint32_t> kept;
  KeepLargest(luminance.data(), weights, terms, kept);
  std::vector<std::uint8_t> keep(n, 0);
  for (std::uint32_t i : kept) keep[i] = 1;
  for (auto& c : coeffs.c)
    for (std::size_t i = 0; i < n; ++i)
      if (!keep[i]) c[i] = 0.0;
  return kept.size();
}

}  // namespace prt
