// The light on the wavelet cube (wavelet/light_cube.h): a constant light exactly, every
// environment's energy exactly at every rotation, smooth in a slow turn, the rotation's
// direction, a quarter turn against the rolled image, and the light-term truncation.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <memory>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/constants.h"
#include "core/rng.h"
#include "env/cubemap.h"
#include "env/equirect.h"
#include "env/load_environment.h"
#include "env/procedural.h"
#include "sh/rotation.h"
#include "wavelet/light_cube.h"
#include "tests/test_support.h"

namespace prt {
namespace {

/// The bound on the cube's integral against the environment's, per channel.
constexpr double kEnergy = 1e-4;
/// The bound on the change of the sunlit ground from one frame to the next in a slow turn.
constexpr double kFrameToFrame = 0.003;

/// The environment's own integral of f(w) L(turn^T w): its quadrature rows plus its disks (each
/// cut into 64 x 64 pieces of equal solid angle), brute force.
glm::dvec3 Integral(const Environment& env, const glm::dmat3& turn = glm::dmat3(1.0),
                    const std::function<double(const glm::dvec3&)>& f = [](const glm::dvec3&) { return 1.0; }) {
  glm::dvec3 sum(0.0);
  std::vector<Texel> row;
  for (std::size_t i = 0; i < env.RowCount(); ++i) {
    env.Row(i, row);
    for (const Texel& t : row) sum += f(turn * t.dir) * t.solid_angle * t.radiance;
  }
  for (const LightDisk& d : env.Disks()) {
    const glm::dvec3 z = glm::normalize(d.dir);
    const glm::dvec3 x = glm::normalize(glm::cross(std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), z));
    const glm::dvec3 y = glm::cross(z, x);
    constexpr int kCut = 64;
    const double dz = (1.0 - d.cos_radius) / kCut, piece = dz * 2.0 * kPi / kCut;
    for (int r = 0; r < kCut; ++r)
      for (int s = 0; s < kCut; ++s) {
        const double cz = 1.0 - (r + 0.5) * dz, sz = std::sqrt(1.0 - cz * cz), phi = 2.0 * kPi * (s + 0.5) / kCut;
        sum += f(turn * (sz * std::cos(phi) * x + sz * std::sin(phi) * y + cz * z)) * piece * d.radiance;
      }
  }
  return sum;
}

/// The sky as `prt sample-files` writes sky.hdr (its radiance at the pixels' centres, the sun a
/// few pixels wide), at `width` x width/2.
std::unique_ptr<Environment> SkyImage(int width) {
  const auto sky = MakeSky(SkyParams{});
  return EquirectFromFunction([&sky](const glm::dvec3& d) { return sky->Radiance(d); }, width, width / 2);
}

/// The irradiance (over pi) of normal n from the cube's light: sum_t L_t (clamped cosine)_t / pi.
double CubeIrradiance(const CubeGrid& grid, const CubeRgb& rgb, const glm::dvec3& n, int channel) {
  double sum = 0.0;
  for (std::size_t t = 0; t < grid.texels(); ++t) sum += rgb.c[channel][t] * grid.ClampedCosine(t, n) / kPi;
  return sum;
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("light cube: a constant light gives every texel exactly that constant, turned or not") {
    // The built-in furnace (a product rule) and a constant image (pixels), at a turn that is no
    // multiple of a quarter: each texel's light is its energy over the solid angle it gathered,
    // not over its own, so the cells' uneven cover of a texel cancels.
    const auto furnace = MakeFurnace(0.75);  // exact in the image's floats too
    const auto flat = EquirectFromFunction([](const glm::dvec3&) { return glm::dvec3(0.75); }, 96, 48);
    const CubeGrid grid(16);
    for (const Environment* env : {static_cast<const Environment*>(furnace.get()), static_cast<const Environment*>(flat.get())}) {
      CubeRgb rgb;
      LightCube(*env, grid).Resample(AxisAngle(glm::normalize(glm::dvec3(0.3, 1, 0.2)), 0.4), rgb);
      for (int c = 0; c < 3; ++c)
        for (double v : rgb.c[c]) CHECK(std::abs(v - 0.75) < 1e-12);
    }
  }

  TEST_CASE("light cube: the cube's integral is the environment's, per channel, at every turn") {
    // The built-in sky (a product rule and its sun disk), its image as sample-files writes it
    // (sky.hdr: a sun of a few pixels, no disk), an image of one bright pixel, an image of
    // noise, and a cubemap of coarse faces (a texel wider than the cube's: cut into parts), each
    // against the brute-force integral of its own quadrature, at turns no quarter turn maps
    // onto the cube.
    const auto sky = MakeSky(SkyParams{});
    const auto sky_image = SkyImage(256);
    ImageF one(64, 32), noise(64, 32);
    one.at(23, 9) = glm::vec3(5000.0f, 3000.0f, 100.0f);
    Pcg32 rng(5, 6);
    for (glm::vec3& p : noise.pixels) p = glm::vec3(rng.NextDouble(), rng.NextDouble() * 3.0, rng.NextDouble() * 0.1);
    const EquirectEnvironment one_pixel(one, "one bright pixel"), noisy(noise, "noise");
    const auto cubemap = CubemapFromFunction([&sky](const glm::dvec3& d) { return sky->Radiance(d); }, 8);
    const Environment* envs[] = {sky.get(), sky_image.get(), &one_pixel, &noisy, cubemap.get()};
    for (int f : {8, 32}) {
      const CubeGrid grid(f);
      for (const Environment* env : envs) {
        CAPTURE(env->Describe());
        const glm::dvec3 expected = Integral(*env);
        const LightCube cube(*env, grid);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(cube.Energy()[c] / expected[c] - 1.0) < kEnergy);
        for (double angle : {0.3, 1.1, 2.0}) {
          CubeRgb rgb;
          cube.Resample(AxisAngle(glm::normalize(glm::dvec3(0.2, 1, 0.1)), angle), rgb);
          const glm::dvec3 got = CubeIntegral(grid, rgb);
          for (int c = 0; c < 3; ++c) CHECK(std::abs(got[c] / expected[c] - 1.0) < kEnergy);
        }
      }
    }
  }

  TEST_CASE("light cube: in a slow turn the light a surface gets changes smoothly with the sun") {
    // 16 frames 0.94 degrees apart (a third of the 48-frame turn: a texel is 2.8 degrees,
    // so each crosses a texel edge) under sky.hdr's image and under the built-in sky, at the
    // default cube: for ground facing up and for tilted surfaces, the cube's irradiance against
    // the exact one of the turned environment. Its error may be a few tenths of a percent but must
    // not jump between frames: a sun put in the one texel it falls in is weighed by that texel's
    // mean cosine, which jumps by several percent from texel to texel.
    // Scaled under a sanitizer (tests/README.md): 6 frames, two texel edges crossed.
    const int kSlowTurnFrames = test::kSanitized ? 6 : 16;
    const auto sky = MakeSky(SkyParams{});
    const auto sky_image = SkyImage(512);
    const CubeGrid grid(32);
    const glm::dvec3 normals[] = {{0, 1, 0}, glm::normalize(glm::dvec3(0.3, 1, 0.2)), glm::normalize(glm::dvec3(1, 0.5, 0))};
    for (const Environment* env : {static_cast<const Environment*>(sky.get()), static_cast<const Environment*>(sky_image.get())}) {
      const LightCube cube(*env, grid);
      for (const glm::dvec3& n : normals) {
        double before = 0.0, worst = 0.0;
        for (int frame = 0; frame < kSlowTurnFrames; ++frame) {
          const glm::dmat3 turn = AxisAngle({0, 1, 0}, frame * 0.94 * kPi / 180.0);
          CubeRgb rgb;
          cube.Resample(turn, rgb);
          const double exact = Integral(*env, turn, [&n](const glm::dvec3& w) { return std::max(0.0, glm::dot(n, w)) / kPi; })[1];
          const double error = CubeIrradiance(grid, rgb, n, 1) / exact - 1.0;
          if (frame > 0) worst = std::max(worst, std::abs(error - before));
          before = error;
        }
        CHECK(worst < kFrameToFrame);
      }
    }
  }

  TEST_CASE("light cube: the sun's light lies where the turn puts it") {
    // A sun a quarter of a texel wide: the luminance-weighted mean direction of the cube's light
    // is its turned direction to a fraction of a texel, not the direction the inverse turn gives.
    SkyParams p;
    p.radius = 0.5;
    p.sun = 50.0;  // the sun outweighs the sky: the mean direction is the sun's
    const auto sky = MakeSky(p);
    const CubeGrid grid(16);
    const glm::dmat3 turn = AxisAngle({0, 1, 0}, 1.1);
    CubeRgb rgb;
    LightCube(*sky, grid).Resample(turn, rgb);
    glm::dvec3 mean(0.0);
    for (std::size_t t = 0; t < grid.texels(); ++t)
      mean += grid.SolidAngle(t) * Luminance(glm::dvec3(rgb.c[0][t], rgb.c[1][t], rgb.c[2][t])) * grid.Direction(t);
    const double texel = 2.0 / grid.size();
    CHECK(std::acos(std::min(1.0, glm::dot(glm::normalize(mean), turn * SunDirection(p)))) < 0.5 * texel);
    CHECK(std::acos(std::min(1.0, glm::dot(glm::normalize(mean), glm::transpose(turn) * SunDirection(p)))) > 4 * texel);
  }

  TEST_CASE("light cube: a bright pixel's light follows it within its cell") {
    // Two images alike but for which of two neighbouring pixels in one cell is bright: a cell
    // placed at its pixels' centre of area would give both the same light; placed where its
    // light comes from, the light's mean direction moves with the pixel.
    constexpr int kWidth = 1024, kHeight = 512;
    const CubeGrid grid(8), cells(8 * 8);  // the light cube's cells at F 8
    ImageF a(kWidth, kHeight), b(kWidth, kHeight);
    for (ImageF* im : {&a, &b})
      for (glm::vec3& p : im->pixels) p = glm::vec3(0.1f);
    const EquirectEnvironment probe(a, "probe");
    std::vector<Texel> row;
    probe.Row(200, row);
    int col = 0;
    while (cells.TexelOf(row[col].dir) != cells.TexelOf(row[col + 1].dir)) ++col;  // two pixels in one cell
    a.at(col, 200) = glm::vec3(1000.0f);
    b.at(col + 1, 200) = glm::vec3(1000.0f);
    const EquirectEnvironment env_a(a, "a"), env_b(b, "b");
    CubeRgb la, lb;
    LightCube(env_a, grid).Resample(glm::dmat3(1.0), la);
    LightCube(env_b, grid).Resample(glm::dmat3(1.0), lb);
    const auto mean = [&grid](const CubeRgb& l) {
      glm::dvec3 m(0.0);
      for (std::size_t t = 0; t < grid.texels(); ++t) m += grid.SolidAngle(t) * (l.c[1][t] - 0.1) * grid.Direction(t);
      return glm::normalize(m);
    };
    // The mean moves the way the bright pixel moved.
    const glm::dvec3 step = row[col + 1].dir - row[col].dir;
    CHECK(glm::dot(mean(lb) - mean(la), step) > 0.25 * glm::dot(step, step));
  }

  TEST_CASE("light cube: a world turned a quarter is the image rolled a quarter") {
    // Turning about +Y by a quarter moves the equirect's columns by W/4 and maps the cube onto
    // itself: the turned original and the rolled image give the same light, texel for texel
    // (the same nodes in the same cells, to rounding; pixels small beside the cells, which are
    // not cut into parts).
    constexpr int kWidth = 1024, kHeight = 512;
    const auto sky = MakeSky(SkyParams{});
    const auto radiance = [&sky](const glm::dvec3& d) { return sky->Radiance(d); };
    const auto original = EquirectFromFunction(radiance, kWidth, kHeight);
    const glm::dmat3 turn = AxisAngle({0, 1, 0}, kPi / 2);
    const auto rolled = EquirectFromFunction([&](const glm::dvec3& d) { return radiance(glm::transpose(turn) * d); }, kWidth, kHeight);
    const CubeGrid grid(8);
    CubeRgb a, b;
    LightCube(*original, grid).Resample(turn, a);
    LightCube(*rolled, grid).Resample(glm::dmat3(1.0), b);
    double worst = 0.0, scale = 0.0;
    for (std::size_t t = 0; t < grid.texels(); ++t) {
      worst = std::max(worst, std::abs(a.c[2][t] - b.c[2][t]));
      scale = std::max(scale, b.c[2][t]);
    }
    CHECK(worst < 1e-9 * scale);
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
