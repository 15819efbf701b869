#include "wavelet/texel_lerp.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/error.h"
#include "env/cube_faces.h"

namespace prt {
namespace {

double Cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

/// (u, v) with q0 + u e + v f + u v g = 0, e = q1 - q0, f = q3 - q0, g = q0 - q1 + q2 - q3: crossing
/// with e + v g leaves A v^2 + B v + C = 0, whose root near the parallelogram's (-C / B; the other
/// is far outside, g being small beside e and f) is taken in the form that loses no digits.
glm::dvec2 InverseBilinear(const glm::dvec2* q) {
  const glm::dvec2 e = q[1] - q[0], f = q[3] - q[0], g = q[0] - q[1] + q[2] - q[3], h = -q[0];
  const double a = Cross(f, g), b = Cross(f, e) - Cross(h, g), c = Cross(e, h);
  const double root = std::sqrt(std::max(0.0, b * b - 4.0 * a * c));
  const double v = -2.0 * c / (b + (b >= 0.0 ? root : -root));
  const glm::dvec2 across = e + v * g;
  return {glm::dot(h - v * f, across) / glm::dot(across, across), v};
}

}  // namespace

TexelLerp::TexelLerp(const CubeGrid& grid) : grid_(grid) {
  const std::size_t n = grid.texels();
  const int size = grid.size();
  const double step = 2.0 / size, probe = 0.25 * step;
  centre_.resize(n);
  corner_.resize(4 * n);
  for (std::size_t t = 0; t < n; ++t) {
    centre_[t] = grid.Direction(t);
    const int face = static_cast<int>(t / grid.face_texels());
    const std::size_t rest = t % grid.face_texels();
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) {
        // The texels just around the corner, in order around it; past a face's edge the points
        // of its plane fall on the neighbouring face.
        const double s = -1.0 + double(rest % size + a) * step, r = -1.0 + double(rest / size + b) * step;
        const double ds[4] = {-probe, probe, probe, -probe}, dr[4] = {-probe, -probe, probe, probe};
        Corner& c = corner_[4 * t + 2 * b + a];
        c.count = 0;
        for (int k = 0; k < 4; ++k) {
          const auto u = static_cast<std::uint32_t>(grid.TexelOf(grid.FacePoint(face, s + ds[k], r + dr[k])));
          if (c.count == 0 || c.texel[c.count - 1] != u) c.texel[c.count++] = u;
        }
        if (c.count > 1 && c.texel[c.count - 1] == c.texel[0]) --c.count;
        if (c.count < 3) throw Error("texel lerp: " + std::to_string(c.count) + " texels around a corner of texel " + std::to_string(t));
      }
  }
}

int TexelLerp::Weights(const glm::dvec3& d, std::uint32_t* texels, double* weights) const {
  // d's face, its point (s, r) on the face's plane, its texel, and which of the texel's corners
  // d lies towards: that corner's cell first, then the others (a seam's arcs are bent, so d may
  // lie in the cell of a neighbouring corner).
  const glm::dvec3 m = glm::abs(d);
  const int face = m.x >= m.y && m.x >= m.z ? (d.x >= 0 ? 0 : 1) : m.y >= m.z ? (d.y >= 0 ? 2 : 3) : (d.z >= 0 ? 4 : 5);
  const FaceFrame& frame = FaceFrames(CubeLayout::kStandard)[face];
  const double inv = 1.0 / glm::dot(d, frame.n), s = glm::dot(d, frame.u) * inv, r = glm::dot(d, frame.v) * inv;
  const int size = grid_.size();
  const double x = (s + 1.0) * 0.5 * size, y = (r + 1.0) * 0.5 * size;
  const int col = std::clamp(static_cast<int>(std::floor(x)), 0, size - 1), row = std::clamp(static_cast<int>(std::floor(y)), 0, size - 1);
  const std::size_t t = (static_cast<std::size_t>(face) * size + row) * size + col;
  const int a = x >= col + 0.5, b = y >= row + 0.5;
  // The conditions on the weights: sum_i w_i c_i . (u - s n) = 0 and sum_i w_i c_i . (v - r n) = 0,
  // both vectors perpendicular to d: each corner a point q_i of a plane, the origin d's image.
  const glm::dvec3 e1 = frame.u - s * frame.n, e2 = frame.v - r * frame.n;
  double best = -1e300, w[4];
  int count = 0;
  for (const int k : {2 * b + a, 2 * b + (1 - a), 2 * (1 - b) + a, 2 * (1 - b) + (1 - a)}) {
    const Corner& c = corner_[4 * t + k];
    glm::dvec2 q[4];
    for (int i = 0; i < c.count; ++i) q[i] = glm::dvec2(glm::dot(centre_[c.texel[i]], e1), glm::dot(centre_[c.texel[i]], e2));
    if (c.count == 4) {
      const glm::dvec2 uv = InverseBilinear(q);
      w[0] = (1 - uv.x) * (1 - uv.y), w[1] = uv.x * (1 - uv.y), w[2] = uv.x * uv.y, w[3] = (1 - uv.x) * uv.y;
    } else {
      const glm::dvec2 e = q[1] - q[0], f = q[2] - q[0];
      const double area = 1.0 / Cross(e, f), u = Cross(f, q[0]) * area, v = Cross(q[0], e) * area;
      w[0] = 1 - u - v, w[1] = u, w[2] = v;
    }
    const double least = std::min(std::min(w[0], w[1]), c.count == 4 ? std::min(w[2], w[3]) : w[2]);
    if (least <= best) continue;
    best = least;
    count = c.count;
    for (int i = 0; i < count; ++i) texels[i] = c.texel[i], weights[i] = w[i];
    if (least >= 0.0) break;
  }
  // Rounding at a cell's edge: clamp to the cell and share again.
  if (best < 0.0) {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += weights[i] = std::max(0.0, weights[i]);
    for (int i = 0; i < count; ++i) weights[i] /= sum;
  }
  return count;
}

}  // namespace prt
