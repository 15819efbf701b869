// Sharing a direction among the texels whose centres surround it (wavelet/texel_lerp.h): the
// weights are those of one dual cell (texels that share a corner of the grid, found here from the
// corners' own positions), non-negative, summing to 1, with their weighted centre exactly along
// the direction, and continuous everywhere, across the faces' seams and at the cube's corners.
#include <doctest/doctest.h>

#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/rng.h"
#include "wavelet/texel_lerp.h"

namespace prt {
namespace {

/// Random unit directions, the same every run.
glm::dvec3 RandomDirection(Pcg32& rng) {
  const double z = 2.0 * rng.NextDouble() - 1.0, phi = 2.0 * kPi * rng.NextDouble();
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// Directions within a tenth of a texel of a cube's edge or corner (the places where the cells
/// are not a face's rectangles), and anywhere.
glm::dvec3 TestDirection(Pcg32& rng, int size, int i) {
  const double near = 0.2 / size;  // a tenth of a texel, in face coordinates
  const double a = 2.0 * rng.NextDouble() - 1.0, b = 1.0 - near * rng.NextDouble(), c = 1.0 - near * rng.NextDouble();
  const double sa = rng.NextDouble() < 0.5 ? -1.0 : 1.0, sb = rng.NextDouble() < 0.5 ? -1.0 : 1.0;
  switch (i % 3) {
    case 0: return glm::normalize(glm::dvec3(sa, sb * b, a));        // an edge of +-X
    case 1: return glm::normalize(glm::dvec3(sa, sb * b, c));        // a corner
    default: return RandomDirection(rng);
  }
}

/// The grid corners (as points on the faces' planes, to 1e-9) shared by every texel in `texels`.
int SharedCorners(const CubeGrid& grid, const std::uint32_t* texels, int n) {
  const auto corners = [&grid](std::uint32_t t) {
    const int size = grid.size(), face = static_cast<int>(t / grid.face_texels());
    const std::size_t rest = t % grid.face_texels();
    const double step = 2.0 / size, s = -1.0 + double(rest % size) * step, r = -1.0 + double(rest / size) * step;
    std::vector<glm::dvec3> out;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) out.push_back(grid.FacePoint(face, s + a * step, r + b * step));
    return out;
  };
  int shared = 0;
  for (const glm::dvec3& p : corners(texels[0])) {
    bool everywhere = true;
    for (int i = 1; i < n; ++i) {
      bool here = false;
      for (const glm::dvec3& q : corners(texels[i])) here = here || glm::length(p - q) < 1e-9;
      everywhere = everywhere && here;
    }
    shared += everywhere;
  }
  return shared;
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("texel lerp: one dual cell's weights, non-negative, summing to 1, their centre along the direction") {
    // Rounding only: the weights come from a quadratic's root in the form that keeps its digits.
    constexpr double kRounding = 1e-11;
    for (int size : {1, 2, 8, 32}) {
      CAPTURE(size);
      const CubeGrid grid(size);
      const TexelLerp lerp(grid);
      Pcg32 rng(7, static_cast<std::uint64_t>(size));
      int triangles = 0;
      for (int i = 0; i < 6000; ++i) {
        const glm::dvec3 d = TestDirection(rng, size, i);
        std::uint32_t to[4];
        double w[4];
        const int n = lerp.Weights(d, to, w);
        REQUIRE((n == 3 || n == 4));
        triangles += n == 3;
        // The texels of one cell: they share one corner of the grid (a cube's corner for three).
        CHECK(SharedCorners(grid, to, n) == 1);
        double sum = 0.0;
        glm::dvec3 centre(0.0);
        for (int k = 0; k < n; ++k) {
          CHECK(w[k] >= 0.0);
          sum += w[k];
          centre += w[k] * grid.Direction(to[k]);
        }
        CHECK(std::abs(sum - 1.0) < kRounding);
        // Their weighted centre points along d: a moving source's light is centred where it is.
        CHECK(glm::length(glm::cross(glm::normalize(centre), d)) < kRounding);
        // At a texel's centre, that texel alone.
        if (i % 97 == 0) {
          const std::size_t t = rng.NextU32() % grid.texels();
          const int m = lerp.Weights(grid.Direction(t), to, w);
          double own = 0.0;
          for (int k = 0; k < m; ++k) own += to[k] == t ? w[k] : 0.0;
          CHECK(own == doctest::Approx(1.0).epsilon(kRounding));
        }
      }
      CHECK(triangles > 0);  // the cube's corners were reached
    }
  }

  TEST_CASE("texel lerp: the weights change continuously, across the seams and corners too") {
    // Two directions 1e-7 radians apart share their light alike: summed over both sets of
    // texels, the weights differ by at most a few times the step over a texel's angle (bilinear
    // weights change by 1 across a cell); a cell left for the wrong one, or a seam whose two
    // sides disagree, would jump by up to 1.
    constexpr double kStep = 1e-7;
    for (int size : {2, 8, 32}) {
      CAPTURE(size);
      const CubeGrid grid(size);
      const TexelLerp lerp(grid);
      const double texel = 0.88 * 2.0 / size;  // the narrowest texel's angle (at a cube's corner)
      Pcg32 rng(11, static_cast<std::uint64_t>(size));
      double worst = 0.0;
      for (int i = 0; i < 6000; ++i) {
        const glm::dvec3 d = TestDirection(rng, size, i);
        const glm::dvec3 side = glm::normalize(glm::cross(d, RandomDirection(rng)));
        const glm::dvec3 e = glm::normalize(d + kStep * side);
        std::map<std::uint32_t, double> change;
        std::uint32_t to[4];
        double w[4];
        for (int k = 0, n = lerp.Weights(d, to, w); k < n; ++k) change[to[k]] += w[k];
        for (int k = 0, n = lerp.Weights(e, to, w); k < n; ++k) change[to[k]] -= w[k];
        double moved = 0.0;
        for (const auto& [t, dw] : change) moved += std::abs(dw);
        worst = std::max(worst, moved * texel / kStep);
      }
      // Measured at most 5.5.
      CHECK(worst < 16.0);
    }
  }
}

}  // namespace prt
