#include "wavelet/texel_spread.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace prt {

TexelSpread::TexelSpread(const CubeGrid& grid) : grid_(grid) {
  const std::size_t n = grid.texels();
  const int size = grid.size();
  const double step = 2.0 / size;
  centre_.resize(n);
  inv_radius_.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    centre_[t] = grid.Direction(t);
    inv_radius_[t] = 1.0 / (kTentRadius * std::sqrt(grid.SolidAngle(t)));
  }
  // For each texel h: the texels within r_t of some point of h. Candidates are the texels through
  // the points two texels around h's centre on its face plane, continued past the face's edges
  // (where they meet the neighbouring faces); kept if |c_t - c_h| <= r_t + (h's centre to its
  // farthest corner). tests/wavelet/test_texel_spread.cpp checks no tent is missed.
  offset_.assign(n + 1, 0);
  std::vector<std::uint32_t> list;
  for (std::size_t h = 0; h < n; ++h) {
    const int face = static_cast<int>(h / grid.face_texels());
    const std::size_t rest = h % grid.face_texels();
    const double s = -1.0 + (double(rest % size) + 0.5) * step, t = -1.0 + (double(rest / size) + 0.5) * step;
    double corner = 0.0;
    for (int a : {-1, 1})
      for (int b : {-1, 1})
        corner = std::max(corner, glm::length(grid.FacePoint(face, s + 0.5 * a * step, t + 0.5 * b * step) - centre_[h]));
    list.clear();
    for (int a = -3; a <= 3; ++a)
      for (int b = -3; b <= 3; ++b) {
        const std::size_t u = grid.TexelOf(grid.FacePoint(face, s + a * step, t + b * step));
        if (glm::length(centre_[u] - centre_[h]) <= 1.0 / inv_radius_[u] + corner) list.push_back(static_cast<std::uint32_t>(u));
      }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    if (list.size() > static_cast<std::size_t>(kMaxSpread))
      throw Error("texel spread: " + std::to_string(list.size()) + " texels reach one texel (at most " +
                  std::to_string(kMaxSpread) + ")");
    reach_.insert(reach_.end(), list.begin(), list.end());
    offset_[h + 1] = static_cast<std::uint32_t>(reach_.size());
  }
}

double TexelSpread::Tent(std::size_t t, const glm::dvec3& d) const {
  return std::max(0.0, 1.0 - glm::length(d - centre_[t]) * inv_radius_[t]);
}

const std::uint32_t* TexelSpread::Reach(std::size_t home, std::size_t& count) const {
  count = offset_[home + 1] - offset_[home];
  return reach_.data() + offset_[home];
}

int TexelSpread::Spread(const glm::dvec3& d, std::uint32_t* texels, double* weights) const {
  std::size_t count;
  const std::uint32_t* reach = Reach(grid_.TexelOf(d), count);
  int n = 0;
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double k = Tent(reach[i], d);
    if (k <= 0.0) continue;
    texels[n] = reach[i];
    weights[n] = k;
    sum += k;
    ++n;
  }
  for (int i = 0; i < n; ++i) weights[i] /= sum;
  return n;
}

}  // namespace prt
