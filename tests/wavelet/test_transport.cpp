// Transport in the Haar wavelet basis (wavelet/transport.h) and its shading
// (wavelet/shade.h): the white furnace exactly, one texel of light, agreement with
// prt reference under a sun, the SH bounces, and the same bytes for any thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

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
#include "sh/coeffs.h"
#include "wavelet/shade.h"
#include "wavelet/transport.h"
#include "tests/test_support.h"
#include "wavelet/cube_grid.h"
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

  TEST_CASE("wavelet transport: a partly blocked texel's open share is weighted by cosine and solid angle") {
    // A vertex facing up above a huge plane of slope 1/8 in x: it blocks exactly the directions
    // with y < x / 8, and that boundary runs along the sub-square lines of the texels just above
    // the horizon on the +X face (face coordinate 1/8 at F 8, 2 rays a side). Each of those
    // texels is half blocked, its lower half, where the cosine is smallest: its transport is
    // (the open half's integral of cos) / pi, which a brute force over 64 x 64 points a texel
    // gives here; an open share counted by rays, not weighted, would give half the texel's.
    Mesh mesh;
    constexpr float kFar = 1e4f;
    const glm::vec3 plane[4] = {{-kFar, -kFar / 8, -kFar}, {kFar, kFar / 8, -kFar}, {kFar, kFar / 8, kFar}, {-kFar, -kFar / 8, kFar}};
    for (const glm::vec3& p : plane) mesh.positions.push_back(p), mesh.normals.push_back(glm::normalize(glm::vec3(-1, 8, 0)));
    mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
    mesh.positions.push_back({0.0f, 1.0f, 0.0f}), mesh.normals.push_back({0, 1, 0});
    mesh.albedo.assign(mesh.positions.size(), glm::vec3(0.8f));
    TransportOptions sh;
    WaveletOptions w;
    w.face_size = 8;
    w.split = 2;
    w.budget = 6 * 8 * 8;
    const WaveletTransport t = ComputeWaveletTransport(mesh, sh, w, nullptr);
    const CubeGrid grid(8);
    std::vector<glm::dvec3> fine;
    std::vector<double> fine_solid;
    grid.SubTexels(64, fine, fine_solid);
    const glm::dvec3 up(0, 1, 0);
    double got = 0.0, weighted = 0.0, counted = 0.0;
    int straddled = 0;
    for (std::size_t texel = 0; texel < grid.texels(); ++texel) {
      double open = 0.0, all = 0.0, open_area = 0.0, area = 0.0;
      for (std::size_t i = texel * 64 * 64; i < (texel + 1) * 64 * 64; ++i) {
        const double c = glm::dot(up, fine[i]);
        if (c <= 0.0) continue;
        const bool blocked = fine[i].y < fine[i].x / 8.0;
        all += c * fine_solid[i], area += fine_solid[i];
        if (!blocked) open += c * fine_solid[i], open_area += fine_solid[i];
      }
      if (all == 0.0 || open == 0.0 || open == all) continue;
      ++straddled;
      CubeRgb rgb;
      for (auto& ch : rgb.c) ch.assign(grid.texels(), 0.0);
      rgb.c[1][texel] = 1.0;
      got += ShadeWavelet(mesh, t, LightOfTexels(rgb, t), {}, false)[4].y;
      weighted += open / kPi;
      counted += all * (open_area / area) / kPi;
    }
    CAPTURE(straddled);
    MESSAGE("half-blocked texels: transport " << got << ", weighted open share " << weighted << ", counted " << counted);
    CHECK(straddled >= 8);  // a row of the +X face's texels (and the corners of its neighbours)
    // The rays' cosines are taken at jittered points inside sub-squares wholly open or blocked:
    // within a few percent of the weighted share, summed over the row.
    constexpr double kJitter = 0.05;
    CHECK(std::abs(got / weighted - 1.0) < kJitter);
    CHECK(std::abs(counted / weighted - 1.0) > 4 * kJitter);  // the test can tell the two apart
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

  TEST_CASE("wavelet transport: vertices no frame shows take the reduced rays, the others exactly the full set") {
    // Every other vertex seen: a seen vertex's transport is bit for bit what it is when every
    // vertex is seen (its rays depend on its index alone), and a hidden one's, traced with one
    // ray a texel instead of four, differs wherever something blocks part of a texel.
    const Mesh mesh = SunScene();
    TransportOptions sh;
    WaveletOptions w;
    w.face_size = 8;
    const WaveletTransport all = ComputeWaveletTransport(mesh, sh, w, nullptr);
    sh.seen.assign(mesh.vertex_count(), 0);
    for (std::size_t v = 0; v < mesh.vertex_count(); v += 2) sh.seen[v] = 1;
    const WaveletTransport some = ComputeWaveletTransport(mesh, sh, w, nullptr);
    REQUIRE(some.base_lmax == all.base_lmax);
    const std::size_t n = CoeffCount(all.base_lmax);
    std::size_t seen_differ = 0, hidden_differ = 0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      const bool same = std::equal(all.base.begin() + v * n, all.base.begin() + (v + 1) * n, some.base.begin() + v * n);
      (sh.seen[v] ? seen_differ : hidden_differ) += !same;
    }
    CHECK(seen_differ == 0);
    CHECK(hidden_differ > mesh.vertex_count() / 20);  // the shadowed ones, at least
    // A quarter of the rays at the hidden half: fewer than all, more than the seen half alone.
    CHECK(some.rays < all.rays);
    CHECK(some.rays > all.rays / 2);
  }

  TEST_CASE("wavelet transport: vertices at one point take different jittered ray sets") {
    // 32 vertices at the same point, facing up, under the edge of a tilted roof: with one set of
    // rays for all they would have the same transport; the pool's sets differ, so several
    // transports differ (each vertex takes one of kJitterSets sets by its index), seen or not.
    Mesh mesh;
    const glm::vec3 roof[4] = {{-3.0f, 0.6f, -3.0f}, {0.4f, 0.9f, -3.0f}, {-0.2f, 0.9f, 3.0f}, {-3.0f, 0.6f, 3.0f}};
    for (const glm::vec3& p : roof) mesh.positions.push_back(p), mesh.normals.push_back({0, -1, 0});
    mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
    constexpr std::size_t kProbes = 32;
    for (std::size_t i = 0; i < kProbes; ++i) mesh.positions.push_back({0.0f, 0.0f, 0.0f}), mesh.normals.push_back({0, 1, 0});
    mesh.albedo.assign(mesh.positions.size(), glm::vec3(0.8f));
    for (const bool seen : {true, false}) {
      CAPTURE(seen);
      TransportOptions sh;
      sh.seen.assign(mesh.vertex_count(), 1);
      if (!seen)
        for (std::size_t i = 4; i < mesh.vertex_count(); ++i) sh.seen[i] = 0;
      WaveletOptions w;
      w.face_size = 8;
      const WaveletTransport t = ComputeWaveletTransport(mesh, sh, w, nullptr);
      const std::size_t n = CoeffCount(t.base_lmax);
      std::set<std::vector<float>> distinct;
      for (std::size_t v = 4; v < mesh.vertex_count(); ++v)
        distinct.insert(std::vector<float>(t.base.begin() + v * n, t.base.begin() + (v + 1) * n));
      CHECK(distinct.size() >= 4);
      CHECK(distinct.size() <= std::size_t(kJitterSets));
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

}

}  // namespace prt
