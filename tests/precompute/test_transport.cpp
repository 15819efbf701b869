#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/parallel.h"
#include "core/rng.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "precompute/samplers.h"
#include "precompute/transport.h"
#include "sh/zonal.h"
#include "tests/test_support.h"

using namespace prt;

namespace {

constexpr double kY00 = 0.28209479177387814;

/// RMS over coefficients and over `trials` random normals of MC-unshadowed minus closed form.
double UnshadowedRms(Sampler sampler, int n, int trials, int lmax) {
  Pcg32 rng(99, static_cast<std::uint64_t>(n));
  double sum = 0.0;
  int terms = 0;
  for (int t = 0; t < trials; ++t) {
    const auto dirs = SampleSphere(sampler, n, rng);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(rng.NextDouble() - 0.5, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5));
    const auto mc = EstimateUnshadowed(dirs, normal, lmax);
    std::vector<double> exact(mc.size());
    UnshadowedTransfer(lmax, normal, exact.data());
    for (std::size_t k = 0; k < mc.size(); ++k, ++terms) sum += (mc[k] - exact[k]) * (mc[k] - exact[k]);
  }
  return std::sqrt(sum / terms);
}

/// Least-squares slope of log(rms) against log(n).
double Slope(const std::vector<double>& n, const std::vector<double>& rms) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = double(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double x = std::log(n[i]), y = std::log(rms[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

Mesh Concat(Mesh a, const Mesh& b) {
  AppendMesh(a, b);
  return a;
}

/// The white furnace: albedo 1 under constant radiance 1 gives outgoing radiance
/// rho L00 T00 = 2 sqrt(pi) T00, exactly 1 everywhere; the discrete bounce series has that as its
/// fixed point and converges geometrically. Measured worst after 64 bounces: 5.2e-8 (one
/// count) and 5.4e-8 (two counts), so the tolerance leaves room for any sampler or seed.
constexpr double kFurnaceTolerance = 0.01;

/// A knotted mesh of albedo 1, which shades and lights itself everywhere; scaled under a
/// sanitizer (tests/README.md) to 80 x 12 segments (1,053 vertices, not 2,737).
Mesh WhiteKnot() {
  Mesh knot = test::kSanitized ? MakeTorusKnot(2, 3, 0.25f, 80, 12) : MakeTorusKnot(2, 3, 0.25f, 160, 16);
  SetUniformAlbedo(knot, glm::vec3(1.0f));
  return knot;
}

/// Worst |radiance - 1| over the vertices of `mesh` in the white furnace after 64 bounces with
/// `o`'s directions (its mode and bounces set here).
double FurnaceWorst(const Mesh& mesh, TransportOptions o, TransportReport& r) {
  o.mode = TransportMode::kInterreflection;
  o.bounces = 64;
  o.bounce_tolerance = 0.0;
  const Transport t = ComputeTransport(mesh, o, &r);
  REQUIRE(r.bounce_share.size() == 64);
  double worst = 0.0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    worst = std::max(worst, std::abs(2 * std::sqrt(kPi) * t.at(v, 0)[0] - 1.0));
  return worst;
}

}  // namespace

TEST_SUITE("precompute") {
  TEST_CASE("Monte Carlo unshadowed transfer converges to the closed form at each sampler's rate") {
    // Expected RMS slopes (CONVENTIONS.md): iid -0.5, stratified about -1 (the clamped cosine
    // has a kink, so a little less), spherical Fibonacci steeper still. The bands allow for
    // the finite number of trials (40 normals per N).
    struct Expect { Sampler s; double lo, hi; };
    for (const Expect& e : {Expect{Sampler::kUniform, -0.62, -0.38}, Expect{Sampler::kStratified, -1.25, -0.8},
                            Expect{Sampler::kFibonacci, -1.8, -1.1}}) {
      std::vector<double> ns, rms;
      for (int n : {64, 256, 1024, 4096}) {
        ns.push_back(n);
        rms.push_back(UnshadowedRms(e.s, n, 40, 2));
      }
      const double slope = Slope(ns, rms);
      MESSAGE(std::string(SamplerName(e.s)) << ": RMS at N=64.." << ns.back() << ": " << rms.front() << " -> " << rms.back()
                               << ", slope " << slope);
      CHECK(slope > e.lo);
      CHECK(slope < e.hi);
      // Unbiased and within noise: at N = 4096 every sampler is within 1e-2 RMS.
      CHECK(rms.back() < 1e-2);
    }
  }

  TEST_CASE("unshadowed transport is the closed form, with no BVH and no rays") {
    const Mesh sphere = MakeSphere(24);
    TransportOptions o;
    o.mode = TransportMode::kUnshadowed;
    o.lmax = 3;
    TransportReport r;
    const Transport t = ComputeTransport(sphere, o, &r);
    CHECK_FALSE(r.bvh_built);
    CHECK(r.rays == 0);
    CHECK(r.closed_form_vertices == sphere.vertex_count());
    std::vector<double> exact(CoeffCount(3));
    UnshadowedTransfer(3, glm::dvec3(sphere.normals[5]), exact.data());
    for (int k = 0; k < CoeffCount(3); ++k) CHECK(t.at(5, 0)[k] == doctest::Approx(exact[k]).epsilon(1e-6));
  }

  TEST_CASE("a lone convex mesh: shadowed equals unshadowed at every vertex and every scale") {
    // Nothing of a convex mesh hides any of its own sky: the shadowed transport of every vertex
    // must be the closed-form unshadowed transfer of its normal (float rounding apart), at
    // scales where a ray offset or epsilon tuned to size 1 would shadow or leak.
    for (float scale : {1e-4f, 1.0f, 1e4f}) {
      const Mesh sphere = MakeSphere(32, scale, glm::vec3(0.3f, -0.2f, 0.1f) * scale);
      TransportOptions o;
      o.samples = 256;
      TransportReport r;
      const Transport t = ComputeTransport(sphere, o, &r);
      CAPTURE(scale);
      CHECK(r.bvh_built);
      CHECK(r.rays > 0);
      REQUIRE(t.vertices == sphere.vertex_count());
      double worst = 0.0;
      std::vector<double> exact(CoeffCount(o.lmax));
      for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
        UnshadowedTransfer(o.lmax, glm::dvec3(sphere.normals[v]), exact.data());
        for (int k = 0; k < CoeffCount(o.lmax); ++k) worst = std::max(worst, std::abs(t.at(v, 0)[k] - exact[k]));
      }
      // Stored as float: T00 = 0.28 rounds within 3e-8.
      CHECK(worst < 1e-6);
    }
  }

  TEST_CASE("a point at the bottom of a deep closed box receives nothing") {
    // A closed room seen from inside: every direction from the floor hits a wall.
    const Mesh room = MakeBox(glm::vec3(-1, 0, -1), glm::vec3(1, 10, 1), BoxFacing::kInward, 4);
    TransportOptions o;
    o.samples = 256;
    const Transport t = ComputeTransport(room, o, nullptr);
    // Vertices on the room's edges lie in a wall's plane and see along it; the floor's
    // interior vertices are the points "at the bottom".
    int checked = 0;
    for (std::size_t v = 0; v < room.vertex_count(); ++v) {
      const glm::vec3 p = room.positions[v];
      if (p.y != 0.0f || std::abs(p.x) > 0.99f || std::abs(p.z) > 0.99f) continue;
      ++checked;
      for (int k = 0; k < CoeffCount(2); ++k) REQUIRE(t.at(v, 0)[k] == 0.0f);
    }
    CHECK(checked == 9);
  }

  TEST_CASE("white furnace: albedo 1, constant light, 64 bounces on a knotted mesh tend to 1") {
    const Mesh knot = WhiteKnot();
    TransportOptions o;
    o.samples = 256;
    TransportReport r;
    const double worst = FurnaceWorst(knot, o, r);
    MESSAGE("furnace: worst |radiance - 1| after 64 bounces = " << worst << "; first bounce share "
                                                                  << r.bounce_share.front());
    CHECK(worst < kFurnaceTolerance);
  }

  TEST_CASE("white furnace with two direction counts: the vertices the camera sees and the others each weigh their own") {
    // Every other vertex "hidden", with 16 times fewer directions: each vertex's bounce and
    // its direct estimate must weigh its own directions (4 pi / N of its own set), so the series
    // still tends to 1 at every vertex, whatever set it drew.
    const Mesh knot = WhiteKnot();
    TransportOptions o;
    o.samples = 512;
    o.hidden_samples = 32;
    o.seen.resize(knot.vertex_count());
    for (std::size_t v = 0; v < o.seen.size(); ++v) o.seen[v] = v % 2;
    TransportReport r;
    const double worst = FurnaceWorst(knot, o, r);
    CHECK(r.directions_per_vertex == 512);
    CHECK(r.hidden_directions == 32);
    CHECK(r.hidden_vertices == knot.vertex_count() / 2);
    MESSAGE("furnace, two counts: worst |radiance - 1| after 64 bounces = " << worst);
    CHECK(worst < kFurnaceTolerance);
    // The seen vertices are exactly what a single pool of 512 gives them in their direct
    // transfer (pool 0 is that pool), and the hidden ones are not.
    TransportOptions shadowed = o;
    shadowed.mode = TransportMode::kShadowed;
    TransportOptions single = shadowed;
    single.hidden_samples = 0;
    single.seen.clear();
    const Transport split = ComputeTransport(knot, shadowed, nullptr), whole = ComputeTransport(knot, single, nullptr);
    std::size_t same_seen = 0, same_hidden = 0;
    for (std::size_t v = 0; v < knot.vertex_count(); ++v) {
      const bool same = std::equal(split.at(v, 0), split.at(v, 0) + CoeffCount(o.lmax), whole.at(v, 0));
      (o.seen[v] ? same_seen : same_hidden) += same;
    }
    CHECK(same_seen == knot.vertex_count() / 2);
    CHECK(same_hidden < knot.vertex_count() / 4);  // those that agree see everything (the closed form)
  }

  TEST_CASE("one bounce under a ceiling matches the analytic view-factor value") {
    // A tiny upward receiver at the origin under a downward-facing square ceiling of half-side
    // s at height 1, constant light 1, albedo rho everywhere. The ceiling sees only the tiny
    // receiver, so its outgoing radiance is rho; the receiver sees the ceiling with the view
    // factor F = (4/pi) (s/sqrt(1+s^2)) atan(s/sqrt(1+s^2)) (point to parallel rectangle) and
    // the sky with 1 - F, so its radiance after one bounce is rho (1 - F + rho F).
    const double s = 1.0, rho = 0.7;
    Mesh ceiling = MakePlane(float(2 * s), 16, 1.0f);
    for (auto& n : ceiling.normals) n = -n;
    for (auto& tri : ceiling.triangles) std::swap(tri[1], tri[2]);
    Mesh scene = Concat(MakePlane(0.01f, 1, 0.0f), ceiling);
    SetUniformAlbedo(scene, glm::vec3(float(rho)));
    TransportOptions o;
    o.mode = TransportMode::kInterreflection;
    o.samples = 4096;
    o.bounces = 1;
    const Transport t = ComputeTransport(scene, o, nullptr);
    const double a = s / std::sqrt(1 + s * s);
    const double F = 4.0 / kPi * a * std::atan(a);
    const double expected = rho * (1 - F + rho * F);
    // Spherical Fibonacci on binary visibility: RMS about N^-0.75, 2e-3 at N = 4096.
    constexpr double kViewFactorTolerance = 1e-2;
    for (std::size_t v = 0; v < 4; ++v) {
      const double radiance = rho * 2 * std::sqrt(kPi) * t.at(v, 0)[0];
      CHECK(radiance == doctest::Approx(expected).epsilon(kViewFactorTolerance));
    }
  }

  TEST_CASE("coloured albedo gives three transport vectors, grey gives one") {
    Mesh scene = Concat(MakeSphere(16, 1.0f, glm::vec3(0, 1.2f, 0)), MakePlane(6.0f, 4));
    TransportOptions o;
    o.mode = TransportMode::kInterreflection;
    o.samples = 64;
    CHECK(ComputeTransport(scene, o, nullptr).channels == 1);
    scene.albedo[0] = glm::vec3(0.9f, 0.1f, 0.1f);
    CHECK(ComputeTransport(scene, o, nullptr).channels == 3);
  }

  TEST_CASE("a lone convex mesh needs no bounce pass") {
    TransportOptions o;
    o.mode = TransportMode::kInterreflection;
    o.samples = 64;
    o.bounces = 3;
    TransportReport r;
    ComputeTransport(MakeSphere(16), o, &r);
    CHECK(r.bounce_share.empty());
    CHECK(r.bounce_stop.find("no bounce pass") != std::string::npos);
  }
}
