// Transport in the Haar wavelet basis (wavelet/transport.h) and its shading
// (wavelet/shade.h): the white furnace exactly, one texel of light, agreement with
// prt reference under a sun, the SH bounces, and the same bytes for any thread count.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/parallel.h"
#include "env/procedural.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "precompute/error_metrics.h"
#include "precompute/light.h"
#include "precompute/reference.h"
#include "precompute/shade.h"
#include "wavelet/shade.h"
#include "wavelet/transport.h"
#include "tests/test_support.h"
#include "wavelet/light_cube.h"
#include "wavelet/texel_sh.h"

namespace prt {
namespace {

/// Float storage of coefficients summed over a few hundred terms.
constexpr double kFloatSums = 1e-5;
/// A one-texel light meets three details per level (9 at F = 8), each of its coefficients at
/// most 1 and each detail off by at most half a quantisation step (1/65534 of the vertex's
/// largest detail, below 0.1 here): 9 * 0.1 / 65534, with room to spare.
constexpr double kQuantised = 1e-4;

/// The light `t` reads of `env` turned by `turn`, every coefficient kept (with the l_j of its
/// SH base, if it has one).
WaveletLight LightOf(const Environment& env, const WaveletTransport& t, const glm::dmat3& turn = glm::dmat3(1.0)) {
  const CubeGrid grid(t.face_size);
  const std::unique_ptr<TexelSh> base = t.base_lmax >= 0 ? std::make_unique<TexelSh>(grid, t.base_lmax) : nullptr;
  CubeRgb rgb;
  return TurnedWaveletLight(LightCube(env, grid), turn, 0, {}, base.get(), rgb);
}

/// The light of texel means `texels` for `t`, every coefficient kept.
WaveletLight LightOfTexels(CubeRgb texels, const WaveletTransport& t) {
  std::vector<glm::vec4> sh;
  if (t.base_lmax >= 0) sh = BaseLight(TexelSh(CubeGrid(t.face_size), t.base_lmax), texels);
  CubeToHaar(t.face_size, texels);
  return PackWaveletLight(texels, sh);
}

/// A small knot standing on a ground of 24 x 24 quads (1,393 vertices). Scaled under a sanitizer
/// (tests/README.md): a coarser knot on 12 x 12 quads (457 vertices), the same shapes.
Mesh SunScene() {
  const int segments = test::kSanitized ? 48 : 96, sides = test::kSanitized ? 6 : 8, quads = test::kSanitized ? 12 : 24;
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, segments, sides, glm::vec3(0.80f, 0.30f, 0.20f));
  StandUpright(knot, 2.0f, 0.05f);
  AppendMesh(knot, MakePlane(8.0f, quads, 0.0f, glm::vec3(0.75f)));
  return knot;
}

}  // namespace

TEST_SUITE("wavelet") {
  TEST_CASE("wavelet transport: white furnace, nothing blocking: the radiance is the albedo exactly") {
    // A sphere blocks none of its own directions. Truncated to a few terms, each vertex still
    // keeps its faces' scaling coefficients, which are all a constant light has.
    const Mesh sphere = MakeSphere(12, 1.0f, glm::vec3(0.0f), glm::vec3(0.6f, 0.3f, 0.9f));
    const auto furnace = MakeFurnace(0.7);
    TransportOptions sh;
    sh.mode = TransportMode::kShadowed;
    WaveletOptions w;
    w.face_size = 16;
    w.budget = 24;
    const WaveletTransport t = ComputeWaveletTransport(sphere, sh, w, nullptr);
    const std::vector<glm::vec3> lit = ShadeWavelet(sphere, t, LightOf(*furnace, t), {}, true);
    for (std::size_t v = 0; v < sphere.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) CHECK(std::abs(lit[v][c] - 0.7 * sphere.albedo[v][c]) < kFloatSums);
  }

  TEST_CASE("wavelet transport: a light that is one texel gives that texel's transport entry") {
    // An open plane facing up: T_t = (clamped cosine over texel t) / pi, exactly. With every
    // coefficient kept, a light of 1 in texel t alone must give exactly T_t.
    const Mesh plane = MakePlane(2.0f, 1);
    TransportOptions sh;
    WaveletOptions w;
    w.face_size = 8;
    w.budget = 6 * 8 * 8;
    const WaveletTransport t = ComputeWaveletTransport(plane, sh, w, nullptr);
    const CubeGrid grid(8);
    const glm::dvec3 n(plane.normals[0]);
    int tested = 0;
    for (std::size_t texel = 0; texel < grid.texels(); texel += 7) {
      CubeRgb rgb;
      for (auto& c : rgb.c) c.assign(grid.texels(), 0.0);
      rgb.c[0][texel] = 1.0;  // red 1, green 0, blue 2: each channel its own
      rgb.c[2][texel] = 2.0;
      const glm::vec3 lit = ShadeWavelet(plane, t, LightOfTexels(rgb, t), {}, false)[0];
      const double expected = grid.ClampedCosine(texel, n) / kPi;
      CHECK(std::abs(lit.x - expected) < kQuantised);
      CHECK(std::abs(lit.y) < kQuantised);
      CHECK(std::abs(lit.z - 2 * expected) < 2 * kQuantised);
      tested += expected > 0;
    }
    CHECK(tested > 20);
  }

  TEST_CASE("wavelet transport: under the sky's sun it agrees with prt reference far better than SH") {
    // The sun's shadow is what SH cannot draw: at lmax 8 the knot's shadow is a blob.
    const Mesh mesh = SunScene();
    const auto sky = MakeSky(SkyParams{});
    ReferenceOptions ro;
    ro.samples = 4096;
    const Reference ref = ComputeReference(mesh, *sky, ro);
    TransportOptions sh;
    WaveletOptions w;
    const WaveletTransport t = ComputeWaveletTransport(mesh, sh, w, nullptr);
    const double wavelet = CompareVertices(ShadeWavelet(mesh, t, LightOf(*sky, t), {}, true), ref.radiance).relative;
    sh.lmax = 8;
    sh.samples = 4096;
    const double sh8 =
        CompareVertices(ShadeVertices(mesh, ComputeTransport(mesh, sh, nullptr), ProjectLight(*sky, 8), true), ref.radiance)
            .relative;
    MESSAGE("relative RMS against prt reference: wavelets " << 100 * wavelet << "%, SH lmax 8 " << 100 * sh8
                                                            << "%, the reference's own " << 100 * ref.rms_error / ref.rms_radiance << "%");
    // Measured 1.67 % (wavelets) and 5.46 % (SH lmax 8) on this scene; the bound leaves room for
    // the reference's own noise at 4096 samples (0.2 %).
    constexpr double kWaveletAgreement = 0.025;
    CHECK(wavelet < kWaveletAgreement);
    CHECK(wavelet < 0.5 * sh8);
  }

  TEST_CASE("wavelet transport: a budget too small for the sun falls back to SH's blur, and more terms help") {
    // The smooth part of the transport is in SH (lmax 4): with its 6 faces' means alone a vertex
    // is lit as SH lmax 4 lights it, and every budget does better, at two sun angles (a quarter
    // turn apart). Without the base, 128 terms were worse than SH lmax 4: the Haar terms went to
    // the smooth cosine over the open sky and the sun met a coarse block's mean.
    const Mesh mesh = SunScene();
    for (double azimuth : {35.0, 125.0}) {
      CAPTURE(azimuth);
      SkyParams p;
      p.azimuth = azimuth;
      const auto sky = MakeSky(p);
      ReferenceOptions ro;
      ro.samples = 2048;
      const Reference ref = ComputeReference(mesh, *sky, ro);
      TransportOptions sh;
      sh.lmax = 4;
      sh.samples = 4096;
      const double sh4 =
          CompareVertices(ShadeVertices(mesh, ComputeTransport(mesh, sh, nullptr), ProjectLight(*sky, 4), true), ref.radiance)
              .relative;
      double previous = 1e300;
      for (int budget : {6, 64, 256}) {
        CAPTURE(budget);
        WaveletOptions w;
        w.face_size = 16;
        w.budget = budget;
        const WaveletTransport t = ComputeWaveletTransport(mesh, sh, w, nullptr);
        const double error = CompareVertices(ShadeWavelet(mesh, t, LightOf(*sky, t), {}, true), ref.radiance).relative;
        MESSAGE("budget " << budget << ": " << 100 * error << "% (SH lmax 4 " << 100 * sh4 << "%)");
        // The base alone is SH lmax 4 up to the rays (4 a texel against 4096 directions) and the
        // reference's noise (2048 directions: about 0.3 %).
        constexpr double kSameAsSh = 1.1;
        CHECK(error < kSameAsSh * sh4);
        CHECK(error < previous);
        previous = error;
      }
      CHECK(previous < 0.5 * sh4);  // 256 terms draw the sun's shadow SH lmax 4 cannot
    }
  }

  TEST_CASE("wavelet transport: the bounces are SH interreflection without its direct part") {
    const Mesh mesh = SunScene();
    TransportOptions o;
    o.mode = TransportMode::kInterreflection;
    o.lmax = 2;
    o.samples = 256;
    const Transport bounced = ComputeBouncedTransport(mesh, o, nullptr);
    const Transport full = ComputeTransport(mesh, o, nullptr);
    TransportOptions direct = o;
    direct.mode = TransportMode::kShadowed;
    const Transport shadowed = ComputeTransport(mesh, direct, nullptr);
    REQUIRE(bounced.coeffs.size() == full.coeffs.size());
    double worst = 0.0, scale = 0.0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < full.channels; ++c)
        for (int k = 0; k < CoeffCount(o.lmax); ++k) {
          const double expected = full.at(v, c)[k] - shadowed.at(v, 0)[k];
          worst = std::max(worst, std::abs(bounced.at(v, c)[k] - expected));
          scale = std::max(scale, std::abs(double(full.at(v, c)[k])));
        }
    // The direct parts differ only where the bounce senders' split changes the triangles a ray
    // meets at an edge (bounce_senders.h): float rounding of the same directions.
    CHECK(worst < 1e-3 * scale);
    // And the wavelet transport carries them, unchanged.
    WaveletOptions w;
    w.face_size = 8;
    const WaveletTransport t = ComputeWaveletTransport(mesh, o, w, nullptr);
    CHECK(t.bounce.coeffs == bounced.coeffs);
    // Shading adds them to the direct light: interreflection minus shadowed is the SH bounce.
    direct.lmax = o.lmax;
    const WaveletTransport only_direct = ComputeWaveletTransport(mesh, direct, w, nullptr);
    const auto sky = MakeSky(SkyParams{});
    const ShRgb sh_light = ProjectLight(*sky, o.lmax);
    const WaveletLight light = LightOf(*sky, t);
    const std::vector<glm::vec3> with = ShadeWavelet(mesh, t, light, sh_light, true);
    const std::vector<glm::vec3> without = ShadeWavelet(mesh, only_direct, light, sh_light, true);
    const std::vector<glm::vec3> bounce = ShadeVertices(mesh, bounced, sh_light, true);
    double num = 0.0, den = 0.0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) {
        num += std::pow(double(with[v][c]) - without[v][c] - bounce[v][c], 2.0);
        den += double(bounce[v][c]) * bounce[v][c];
      }
    CHECK(den > 0.0);
    CHECK(std::sqrt(num / den) < kFloatSums * 10);
  }

  TEST_CASE("wavelet transport: the same coefficients for any thread count") {
    const Mesh mesh = SunScene();
    TransportOptions sh;
    WaveletOptions w;
    w.face_size = 16;
    w.budget = 100;
    const WaveletTransport one = test::WithThreads(1, [&] { return ComputeWaveletTransport(mesh, sh, w, nullptr); });
    const WaveletTransport two = test::WithThreads(2, [&] { return ComputeWaveletTransport(mesh, sh, w, nullptr); });
    CHECK(one.index == two.index);
    CHECK(one.value == two.value);
    CHECK(one.offsets == two.offsets);
    CHECK(one.means == two.means);
    CHECK(one.scale == two.scale);
    CHECK(one.base == two.base);
    CHECK(one.Kept() == 100 * mesh.vertex_count());
    // Per vertex: 25 base floats (lmax 4), 6 means, 94 details of 4 bytes, a step; an offset.
    CHECK(one.Bytes() == mesh.vertex_count() * (25 * 4 + 6 * 4 + 94 * 4 + 4) + (mesh.vertex_count() + 1) * 8);
  }
}

}  // namespace prt
