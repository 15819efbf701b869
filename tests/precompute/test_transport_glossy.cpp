// Glossy transfer toward a fixed camera (precompute/transport.h, transport_glossy.cpp): the
// white furnace in closed form, and exactness against brute force with the same lobe rays.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "core/parallel.h"
#include "geometry/bvh.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "geometry/ray.h"
#include "material/lobe_transfer.h"
#include "precompute/lobe_rays.h"
#include "precompute/shade.h"
#include "precompute/transport.h"
#include "precompute_io/transport_cache.h"
#include "sh/basis.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("precompute");
using test::BandLimitedLight;
using test::LightAt;
using test::SphereOverPlane;

TEST_CASE("glossy white furnace: albedo + KS times the lobe's cosine integral, in closed form for N = 1") {
  // Constant light 1 (L_00 = sqrt(4 pi)), a lone sphere (nothing occluded). For N = 1 the lobe's
  // cosine-weighted integral is (sin g + (pi - g) cos g) / pi, g the angle between n and the
  // mirrored view (= the angle between n and the view). Tolerance: the lobe table's cubic
  // interpolation (1e-8 here) and float storage.
  constexpr double kTol = 1e-5;
  const double albedo = 0.4, ks = 0.6;
  Mesh sphere = MakeSphere(24);
  for (auto& a : sphere.albedo) a = glm::vec3(float(albedo));
  const glm::dvec3 eye(0.5, 2.0, 6.0);
  ShRgb light(CoeffCount(2), glm::dvec3(0.0));
  light[0] = glm::dvec3(std::sqrt(4.0 * kPi));
  for (TransportMode mode : {TransportMode::kUnshadowed, TransportMode::kShadowed, TransportMode::kInterreflection}) {
    TransportOptions o;
    o.mode = mode;
    o.samples = 256;
    o.material = ParseMaterial("phong:1,0.6");
    o.eye = eye;
    const Transport t = ComputeTransport(sphere, o, nullptr);
    const std::vector<glm::vec3> radiance = ShadeVertices(sphere, t, light);
    double worst = 0.0;
    for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
      const glm::dvec3 n(sphere.normals[v]);
      const double g = std::acos(std::clamp(glm::dot(n, glm::normalize(eye - glm::dvec3(sphere.positions[v]))), -1.0, 1.0));
      const double expected = albedo + ks * (std::sin(g) + (kPi - g) * std::cos(g)) / kPi;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(radiance[v][c] - expected));
    }
    CAPTURE(TransportModeName(mode));
    CHECK(worst < kTol);
  }
}

TEST_CASE("glossy white furnace at normal view is albedo + KS exactly, for any exponent") {
  // The eye straight above the sphere's top vertex: r = n, and the Phong lobe normalised by
  // (N+2)/(2 pi) integrates to 1 against the cosine (the pitfall: a lobe normalised by (N+1)
  // comes out darker than diffuse).
  Mesh sphere = MakeSphere(16);
  std::size_t top = 0;
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v)
    if (sphere.positions[v].y > sphere.positions[top].y) top = v;
  REQUIRE(glm::length(sphere.normals[top] - glm::vec3(0, 1, 0)) < 1e-6f);
  for (auto& a : sphere.albedo) a = glm::vec3(0.3f);
  ShRgb light(CoeffCount(2), glm::dvec3(0.0));
  light[0] = glm::dvec3(std::sqrt(4.0 * kPi));
  for (int exponent : {1, 30, 1000}) {
    TransportOptions o;
    o.mode = TransportMode::kUnshadowed;
    o.material = ParseMaterial("phong:" + std::to_string(exponent) + ",0.7");
    o.eye = glm::dvec3(sphere.positions[top]) + glm::dvec3(0, 5, 0);
    const Transport t = ComputeTransport(sphere, o, nullptr);
    CAPTURE(exponent);
    CHECK(ShadeVertices(sphere, t, light)[top].x == doctest::Approx(1.0).epsilon(1e-5));
  }
}

TEST_CASE("fixed-camera glossy transfer equals brute force with the same lobe rays, for a band-limited light") {
  // B = L . G against KS [integral L h cos by the direct lobe rule on L's values - sum over the
  // same blocked lobe rays of w cos L(s)]. Tolerance: 1e-6 of the largest value (the lobe
  // table's interpolation, 1e-7, and float storage).
  constexpr double kTol = 1e-6;
  const int lmax = 3;
  const Mesh mesh = SphereOverPlane();
  const ShRgb light = BandLimitedLight(lmax);
  const glm::dvec3 eye(4.0, 3.0, 5.0);
  TransportOptions o;
  o.mode = TransportMode::kShadowed;
  o.lmax = lmax;
  o.samples = 256;
  o.material = ParseMaterial("phong:40,0.5");
  o.eye = eye;
  const Transport t = ComputeTransport(mesh, o, nullptr);
  const Bvh bvh = Bvh::Build(mesh);
  const int m = LobeSamplesOf(o.samples);
  LobeRays rays;
  double worst = 0.0, peak = 0.0;
  std::size_t blocked_vertices = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 3) {
    const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
    const glm::dvec3 r = glm::normalize(MirrorView(n, glm::normalize(eye - p)));
    std::vector<double> u(CoeffCount(lmax));
    LobeTransfer(o.material.lobe, n, r, lmax, u.data());
    glm::dvec3 expected(0.0);
    for (std::size_t k = 0; k < u.size(); ++k) expected += u[k] * light[k];
    DrawLobeRays(o.material.lobe, r, m, o.seed, v, rays);
    bool any = false;
    for (int i = 0; i < m; ++i) {
      const double c = glm::dot(n, rays.dirs[i]);
      if (c <= 0.0) continue;
      Ray ray;
      ray.origin = OffsetRayOrigin(mesh.positions[v], mesh.normals[v], bvh.SceneScale());
      ray.dir = glm::vec3(rays.dirs[i]);
      if (!bvh.Occluded(ray)) continue;
      any = true;
      expected -= rays.weights[i] * c * LightAt(light, rays.dirs[i]);
    }
    blocked_vertices += any;
    expected *= o.material.ks;
    for (int c = 0; c < 3; ++c) {
      double b = 0.0;
      const float* g = t.glossy_at(v, c);
      for (std::size_t k = 0; k < u.size(); ++k) b += light[k][c] * g[k];
      worst = std::max(worst, std::abs(b - expected[c]));
      peak = std::max(peak, std::abs(expected[c]));
    }
  }
  CHECK(blocked_vertices > 20);  // the plane under the sphere is in its shadow
  CHECK(worst <= kTol * peak);
}

TEST_CASE("a glossy material leaves the diffuse transfer as it was, and the cache key follows material and eye") {
  const Mesh mesh = SphereOverPlane();
  TransportOptions diffuse;
  diffuse.samples = 128;
  TransportOptions glossy = diffuse;
  glossy.material = ParseMaterial("phong:10,0.3");
  glossy.eye = glm::dvec3(3, 2, 4);
  const Transport a = ComputeTransport(mesh, diffuse, nullptr), b = ComputeTransport(mesh, glossy, nullptr);
  CHECK(a.coeffs == b.coeffs);
  CHECK(a.glossy.empty());
  CHECK(b.glossy.size() == b.coeffs.size());

  const std::uint64_t key = TransportKey(mesh, glossy);
  TransportOptions other = glossy;
  other.eye = glm::dvec3(3, 2, 4.0001);
  CHECK(TransportKey(mesh, other) != key);
  other = glossy;
  other.material = ParseMaterial("phong:11,0.3");
  CHECK(TransportKey(mesh, other) != key);
  other = glossy;
  other.material.ks = 0.31;
  CHECK(TransportKey(mesh, other) != key);
  other = glossy;
  other.material.ks = 0.3 + 1e-12;  // beyond float precision: still another transfer
  CHECK(TransportKey(mesh, other) != key);
  other = glossy;
  other.matrices = true;
  CHECK(TransportKey(mesh, other) != key);
  CHECK(TransportKey(mesh, diffuse) != key);
  // The matrices do not depend on the lobe or the eye: one cache serves every exponent and view.
  TransportOptions matrices = glossy, sharper = glossy;
  matrices.matrices = sharper.matrices = true;
  sharper.material = ParseMaterial("phong:500,0.1");
  sharper.eye = glm::dvec3(-1, 5, 2);
  CHECK(TransportKey(mesh, matrices) == TransportKey(mesh, sharper));
}

TEST_SUITE_END();
