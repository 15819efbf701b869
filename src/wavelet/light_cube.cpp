#include "wavelet/light_cube.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/color.h"
#include "core/constants.h"
#include "core/parallel.h"
#include "wavelet/haar.h"

namespace prt {
namespace {

/// A frame (x, y, axis) around unit `axis`.
void Frame(const glm::dvec3& axis, glm::dvec3& x, glm::dvec3& y) {
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  x = glm::normalize(glm::cross(helper, axis));
  y = glm::cross(axis, x);
}

/// The environment's quadrature nodes gathered into the cells of `fine`: per cell the nodes'
/// energy and solid angle, and their directions weighted by luminance times solid angle (where a
/// bright source in the cell lies) and by solid angle alone (for a cell that is black).
struct Cells {
  std::vector<glm::dvec3> energy, bright, moment;
  std::vector<double> solid_angle;
};

Cells GatherNodes(const Environment& env, const CubeGrid& fine) {
  Cells cells;
  cells.energy.assign(fine.texels(), glm::dvec3(0.0));
  cells.moment.assign(fine.texels(), glm::dvec3(0.0));
  cells.bright.assign(fine.texels(), glm::dvec3(0.0));
  cells.solid_angle.assign(fine.texels(), 0.0);
  double smallest = 4.0 * kPi;
  for (std::size_t t = 0; t < fine.face_texels(); ++t) smallest = std::min(smallest, fine.SolidAngle(t));
  const auto add = [&](const glm::dvec3& d, double omega, const glm::dvec3& radiance) {
    const std::size_t c = fine.TexelOf(d);
    cells.energy[c] += omega * radiance;
    cells.moment[c] += omega * d;
    cells.bright[c] += omega * Luminance(radiance) * d;
    cells.solid_angle[c] += omega;
  };
  std::vector<Texel> row;
  for (std::size_t i = 0; i < env.RowCount(); ++i) {
    env.Row(i, row);
    for (const Texel& node : row) {
      // A node wider than half the smallest cell is cut into k x k equal parts on the square of
      // its own solid angle around its direction (its shape is not known; its energy is kept).
      const int k = std::min(64, static_cast<int>(std::ceil(std::sqrt(node.solid_angle / (0.5 * smallest)))));
      if (k <= 1) {
        add(node.dir, node.solid_angle, node.radiance);
        continue;
      }
      glm::dvec3 x, y;
      Frame(node.dir, x, y);
      const double side = std::sqrt(node.solid_angle), part = node.solid_angle / (double(k) * k);
      for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b)
          add(glm::normalize(node.dir + side * (((a + 0.5) / k - 0.5) * x + ((b + 0.5) / k - 0.5) * y)), part,
              node.radiance);
    }
  }
  return cells;
}

/// Per cell, the least radiance of each channel among the cells within `reach` of it along each
/// side on its face (empty cells left out): the light around the cell without what stands out.
std::vector<glm::dvec3> Floor(const Cells& cells, int size, int reach) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const std::size_t per_face = static_cast<std::size_t>(size) * size;
  std::vector<glm::dvec3> radiance(cells.energy.size(), glm::dvec3(kNone)), rows(radiance.size());
  for (std::size_t c = 0; c < radiance.size(); ++c)
    if (cells.solid_angle[c] > 0.0) radiance[c] = cells.energy[c] / cells.solid_angle[c];
  // A square's least value: the least along each row, then along each column of those.
  const auto least = [size, reach](const std::vector<glm::dvec3>& in, std::vector<glm::dvec3>& out,
                                    std::size_t face_start, bool along_rows) {
    const auto at = [&](int line, int i) {
      return face_start + (along_rows ? std::size_t(line) * size + i : std::size_t(i) * size + line);
    };
    for (int line = 0; line < size; ++line)
      for (int i = 0; i < size; ++i) {
        glm::dvec3 m(kNone);
        for (int j = std::max(0, i - reach); j <= std::min(size - 1, i + reach); ++j) m = glm::min(m, in[at(line, j)]);
        out[at(line, i)] = m;
      }
  };
  std::vector<glm::dvec3> floor(radiance.size());
  for (int f = 0; f < 6; ++f) {
    least(radiance, rows, f * per_face, true);
    least(rows, floor, f * per_face, false);
  }
  return floor;
}

}  // namespace

LightCube::LightCube(const Environment& env, const CubeGrid& grid, int fine) : grid_(grid), lerp_(grid) {
  if (fine <= 0) fine = std::max(1, std::min(kFineCells, kMaxCellFace / grid.size()));
  const CubeGrid cells_grid(grid.size() * fine);
  const Cells cells = GatherNodes(env, cells_grid);
  const std::vector<glm::dvec3> floor = Floor(cells, cells_grid.size(), fine);
  for (std::size_t c = 0; c < cells_grid.texels(); ++c) {
    if (cells.solid_angle[c] <= 0.0) continue;
    const glm::dvec3 m = glm::length(cells.bright[c]) > 0.0 ? cells.bright[c] : cells.moment[c];
    const glm::dvec3 centroid = glm::length(m) > 0.0 ? glm::normalize(m) : cells_grid.Direction(c);
    // The cell's light as its floor over its whole solid angle plus what rises above it (at
    // most the whole; never below 0, the floor being a least value).
    const glm::dvec3 base = glm::min(cells.energy[c], cells.solid_angle[c] * floor[c]);
    pieces_.push_back({centroid, cells.solid_angle[c], base, cells.energy[c] - base});
    base_energy_ += base;
    energy_ += cells.energy[c];
  }
  // Each disk cut into rings even in cos theta and sectors even in azimuth: equal solid angles,
  // at most a quarter of a cell apart (a cell spans at least 0.88 / (F fine) radians, at the
  // cube's corners: its side over 3^(3/4)).
  const double spacing = 0.22 / cells_grid.size();
  for (const LightDisk& d : env.Disks()) {
    const double radius = std::acos(std::clamp(d.cos_radius, -1.0, 1.0));
    const int rings = std::max(16, static_cast<int>(std::ceil(radius / spacing)));
    const int sectors = std::max(32, static_cast<int>(std::ceil(2.0 * kPi * std::sin(std::min(radius, kPi / 2)) / spacing)));
    glm::dvec3 x, y;
    const glm::dvec3 z = glm::normalize(d.dir);
    Frame(z, x, y);
    const double dz = (1.0 - d.cos_radius) / rings;
    const glm::dvec3 energy = d.radiance * (dz * 2.0 * kPi / sectors);
    for (int r = 0; r < rings; ++r) {
      const double cz = 1.0 - (r + 0.5) * dz, sz = std::sqrt(std::max(0.0, 1.0 - cz * cz));
      for (int s = 0; s < sectors; ++s) {
        const double phi = 2.0 * kPi * (s + 0.5) / sectors;
        pieces_.push_back({sz * std::cos(phi) * x + sz * std::sin(phi) * y + cz * z, 0.0, glm::dvec3(0.0), energy});
        energy_ += energy;
      }
    }
  }
}

void LightCube::Resample(const glm::dmat3& turn, CubeRgb& out) const {
  const std::size_t texels = grid_.texels();
  // The pieces in kChunks fixed runs, each shared into its own sums, then the runs added in
  // order: the same bits for any thread count.
  constexpr std::size_t kChunks = 16;
  struct Sum {
    glm::dvec3 base{0.0}, rise{0.0};
    double area = 0.0;
  };
  std::vector<std::vector<Sum>> sums(kChunks);
  const std::size_t per = (pieces_.size() + kChunks - 1) / kChunks;
  ParallelFor(kChunks, 1, [&](std::size_t begin, std::size_t end) {
    std::uint32_t to[4];
    double w[4];
    for (std::size_t k = begin; k < end; ++k) {
      std::vector<Sum>& s = sums[k];
      s.assign(texels, Sum{});
      for (std::size_t p = k * per; p < std::min(pieces_.size(), (k + 1) * per); ++p) {
        const Piece& piece = pieces_[p];
        const int n = lerp_.Weights(turn * piece.dir, to, w);
        for (int i = 0; i < n; ++i) {
          Sum& t = s[to[i]];
          t.base += w[i] * piece.base;
          t.rise += w[i] * piece.rise;
          t.area += w[i] * piece.solid_angle;
        }
      }
    }
  });
  // Each texel: its floor's mean radiance over the solid angle it gathered, plus what rises
  // above it over its own solid angle.
  CubeRgb base;
  for (int c = 0; c < 3; ++c) out.c[c].assign(texels, 0.0), base.c[c].assign(texels, 0.0);
  glm::dvec3 got(0.0);
  for (std::size_t t = 0; t < texels; ++t) {
    Sum total;
    for (const std::vector<Sum>& s : sums) total.base += s[t].base, total.rise += s[t].rise, total.area += s[t].area;
    for (int c = 0; c < 3; ++c) {
      if (total.area > 0.0) base.c[c][t] = total.base[c] / total.area;
      out.c[c][t] = total.rise[c] / grid_.SolidAngle(t);
      got[c] += grid_.SolidAngle(t) * base.c[c][t];
    }
  }
  // One factor per channel: the floor's total back to the environment's (what rises above it
  // is kept exactly already).
  for (int c = 0; c < 3; ++c) {
    const double factor = got[c] > 0.0 ? base_energy_[c] / got[c] : 0.0;
    for (std::size_t t = 0; t < texels; ++t) out.c[c][t] += factor * base.c[c][t];
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
