// The light on the wavelet cube (wavelet/light_cube.h): a constant light exactly, the sun's
// energy exactly at every rotation, the rotation's direction, and the light-term truncation.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "env/equirect.h"
#include "env/load_environment.h"
#include "env/procedural.h"
#include "sh/rotation.h"
#include "wavelet/light_cube.h"

namespace prt {
namespace {

/// The bound on the cube's integral against the environment's, per channel.
constexpr double kEnergy = 1e-3;

/// The environment's own integral: its quadrature rows plus its disks' energy.
glm::dvec3 EnvironmentIntegral(const Environment& env) {
  glm::dvec3 sum(0.0);
  std::vector<Texel> row;
  for (std::size_t i = 0; i < env.RowCount(); ++i) {
    env.Row(i, row);
    for (const Texel& t : row) sum += t.solid_angle * t.radiance;
  }
  for (const LightDisk& d : env.Disks()) sum += 2 * kPi * (1 - d.cos_radius) * d.radiance;
  return sum;
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("light cube: a constant light gives every texel exactly that constant") {
    const auto furnace = MakeFurnace(0.7);
    const CubeGrid grid(16);
    CubeRgb rgb;
    LightCube(*furnace, grid).Resample(AxisAngle({0, 1, 0}, 0.4), rgb);
    for (int c = 0; c < 3; ++c)
      for (double v : rgb.c[c]) CHECK(std::abs(v - 0.7) < 1e-12);
  }

  TEST_CASE("light cube: the sky's integral, sun included, is the environment's at every frame") {
    const auto sky = MakeSky(SkyParams{});
    const glm::dvec3 expected = EnvironmentIntegral(*sky);
    for (int f : {16, 32}) {
      const CubeGrid grid(f);
      const LightCube cube(*sky, grid);
      for (int frame = 0; frame < 8; ++frame) {
        CubeRgb rgb;
        cube.Resample(AxisAngle(glm::normalize(glm::dvec3(0.2, 1, 0.1)), 2 * kPi * frame / 8), rgb);
        const glm::dvec3 got = CubeIntegral(grid, rgb);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(got[c] / expected[c] - 1.0) < kEnergy);
      }
    }
  }

  TEST_CASE("light cube: the sun lands in the texel of its turned direction") {
    // A sun a quarter of a texel wide: after turning by R its energy sits in TexelOf(R s).
    SkyParams p;
    p.radius = 0.5;
    const auto sky = MakeSky(p);
    const CubeGrid grid(16);
    const glm::dmat3 turn = AxisAngle({0, 1, 0}, 1.1);
    CubeRgb rgb;
    LightCube(*sky, grid).Resample(turn, rgb);
    std::size_t brightest = 0;
    for (std::size_t t = 1; t < grid.texels(); ++t)
      if (rgb.c[1][t] > rgb.c[1][brightest]) brightest = t;
    CHECK(brightest == grid.TexelOf(turn * SunDirection(p)));
    CHECK(brightest != grid.TexelOf(glm::transpose(turn) * SunDirection(p)));
  }

  TEST_CASE("light cube: turned by whole columns, an equirect sky is its shifted image") {
    // Turning about +Y by 2 pi k / W moves the equirect's columns by k: the light of the turned
    // original equals the light of the shifted image, texel for texel (same sub-sample
    // directions, same bilinear weights).
    constexpr int kWidth = 128, kHeight = 64, kShift = 16;
    const auto sky = MakeSky(SkyParams{});
    const auto radiance = [&sky](const glm::dvec3& d) { return sky->RadianceWithoutDisks(d); };
    const auto original = EquirectFromFunction(radiance, kWidth, kHeight);
    const glm::dmat3 turn = AxisAngle({0, 1, 0}, 2 * kPi * kShift / kWidth);
    const auto shifted = EquirectFromFunction(
        [&](const glm::dvec3& d) { return radiance(glm::transpose(turn) * d); }, kWidth, kHeight);
    const CubeGrid grid(16);
    CubeRgb a, b;
    LightCube(*original, grid).Resample(turn, a);
    LightCube(*shifted, grid).Resample(glm::dmat3(1.0), b);
    double worst = 0.0, scale = 0.0;
    for (std::size_t t = 0; t < grid.texels(); ++t) {
      worst = std::max(worst, std::abs(a.c[2][t] - b.c[2][t]));
      scale = std::max(scale, b.c[2][t]);
    }
    CHECK(worst < 1e-6 * scale);  // the turned texel centres land on pixel centres up to rounding
  }

  TEST_CASE("light cube: keeping K light terms keeps the K most important and zeroes the rest") {
    const auto sky = MakeSky(SkyParams{});
    const CubeGrid grid(16);
    CubeRgb rgb;
    LightCube(*sky, grid).Resample(glm::dmat3(1.0), rgb);
    CubeToHaar(grid.size(), rgb);
    CubeRgb kept = rgb;
    CHECK(KeepLightTerms(SelectionWeights(16, Selection::kMagnitude), 64, kept) == 64);
    std::size_t nonzero = 0;
    double dropped_max = 0.0, kept_min = 1e300;
    for (std::size_t i = 0; i < grid.texels(); ++i) {
      const bool on = kept.c[0][i] != 0 || kept.c[1][i] != 0 || kept.c[2][i] != 0;
      nonzero += on;
      const double y = 0.2126 * std::abs(rgb.c[0][i]) + 0.7152 * std::abs(rgb.c[1][i]) + 0.0722 * std::abs(rgb.c[2][i]);
      if (on) {
        kept_min = std::min(kept_min, y);
        CHECK(kept.c[1][i] == rgb.c[1][i]);
      } else {
        dropped_max = std::max(dropped_max, y);
      }
    }
    CHECK(nonzero == 64);
    CHECK(kept_min >= dropped_max);
  }
}

}  // namespace prt
