// Transfer matrices (precompute/transfer_matrix.h): the unshadowed matrix against closed forms,
// and the matrix path's glossy radiance against brute force when the lobe is band-limited (the
// case where the matrix path is exact), with the same visibility rays.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "geometry/bvh.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "geometry/ray.h"
#include "material/lobe_transfer.h"
#include "precompute/direction_pool.h"
#include "precompute/transfer_matrix.h"
#include "precompute/transport.h"
#include "sh/basis.h"
#include "sh/zonal.h"
#include "tests/precompute/glossy_test_util.h"

using namespace prt;

TEST_SUITE_BEGIN("precompute");
using test::BandLimitedLight;
using test::LightAt;
using test::SphereOverPlane;

namespace {

Material RaisedCosine(int degree, double ks) { return GlossyMaterial(Lobe{LobeKind::kRaisedCosine, degree}, ks); }

}  // namespace

TEST_CASE("the unshadowed transfer matrix is symmetric and its first column is the clamped-cosine closed form") {
  // Tolerance: the product rule is exact for Y_i Y_j z; what is left is rounding.
  constexpr double kTol = 1e-13;
  const int lmax = 4, n = CoeffCount(lmax);
  for (const glm::dvec3& normal : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(0.3, -0.8, 0.5)), glm::dvec3(0, -1, 0)}) {
    std::vector<double> m(n * n), t(n);
    UnshadowedTransferMatrix(normal, lmax, m.data());
    UnshadowedTransfer(lmax, normal, t.data());  // (1/pi) integral Y max(0, n.s)
    const double y00 = 0.5 / std::sqrt(kPi);
    for (int i = 0; i < n; ++i) {
      CHECK(std::abs(m[i * n] - y00 * kPi * t[i]) < kTol);
      for (int j = 0; j < n; ++j) CHECK(std::abs(m[i * n + j] - m[j * n + i]) < kTol);
    }
    // Trace: sum_i integral Y_i^2 cos = (n / 4 pi) * pi (the addition theorem: sum_m Y_lm^2 = (2l+1)/(4 pi)).
    double trace = 0.0;
    for (int i = 0; i < n; ++i) trace += m[i * n + i];
    CHECK(trace == doctest::Approx(n / 4.0).epsilon(1e-13));
  }
}

TEST_CASE("matrix path: exact for a band-limited lobe, unoccluded and with the same visibility rays") {
  // Tolerance: both sides are exact sums of the same terms in a different order (and floats for
  // the stored matrices): 1e-6 relative.
  constexpr double kTol = 1e-6;
  const int lmax = 3;
  const Mesh mesh = SphereOverPlane();
  const ShRgb light = BandLimitedLight(lmax);
  const Material material = RaisedCosine(3, 0.4);  // band-limited to 3 = lmax
  const glm::dvec3 eye(4.0, 3.0, 5.0);
  for (TransportMode mode : {TransportMode::kUnshadowed, TransportMode::kShadowed}) {
    TransportOptions o;
    o.mode = mode;
    o.lmax = lmax;
    o.samples = 256;
    o.material = material;
    o.matrices = true;
    const Transport transport = ComputeTransport(mesh, o, nullptr);
    REQUIRE(transport.matrices.size() == mesh.vertex_count() * CoeffCount(lmax) * CoeffCount(lmax));
    const std::vector<glm::vec3> glossy = GlossyFromMatrices(mesh, transport, material, light, eye);

    // Brute force: KS [integral L h cos (unshadowed, by the lobe quadrature applied to L's values)
    // minus (4 pi / N) sum over the same blocked pool directions of L(s) h(r.s) cos].
    const Bvh bvh = Bvh::Build(mesh);
    const DirectionPool pool = MakeDirectionPool(o.sampler, o.samples, o.direction_sets, o.seed);
    std::vector<std::uint8_t> blocked;
    double worst = 0.0, peak = 0.0;
    for (std::size_t v = 0; v < mesh.vertex_count(); v += 7) {
      const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
      const glm::dvec3 r = glm::normalize(MirrorView(n, glm::normalize(eye - p)));
      std::vector<double> t(CoeffCount(lmax));
      LobeTransfer(material.lobe, n, r, lmax, t.data());
      glm::dvec3 expected(0.0);
      for (std::size_t k = 0; k < t.size(); ++k) expected += t[k] * light[k];
      if (mode == TransportMode::kShadowed) {
        const std::size_t set = pool.SetOf(v);
        bvh.OccludedFan(pool.fans[set], OffsetRayOrigin(mesh.positions[v], mesh.normals[v], bvh.SceneScale()),
                        mesh.normals[v], std::numeric_limits<float>::infinity(), blocked);
        for (std::size_t i = 0; i < pool.sets[set].size(); ++i) {
          const glm::dvec3& s = pool.sets[set][i];
          const double c = glm::dot(n, s);
          if (c > 0.0 && blocked[i])
            expected -= (4.0 * kPi / double(pool.size())) * c * material.lobe.Value(glm::dot(r, s)) * LightAt(light, s);
        }
      }
      expected *= material.ks;
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(double(glossy[v][c]) - expected[c]));
        peak = std::max(peak, std::abs(expected[c]));
      }
    }
    CAPTURE(TransportModeName(mode));
    CHECK(peak > 0.01);
    CHECK(worst <= kTol * peak);
  }
}

TEST_CASE("matrix path with interreflection: the hit points' diffuse light, per colour channel, as brute force") {
  // For a band-limited lobe the matrices are exact, so the glossy radiance must equal, with the
  // same pool directions and hits: KS [integral L h cos - sum over blocked s of w L(s)
  // + sum over blocked s hitting a lit side of w albedo(h) (T(h) . L)], w = (4 pi/N) cos h(r.s),
  // T(h) the direct (bounce 0) transfer at the hit with one bounce. Coloured albedo: three
  // channels. Tolerance: float storage of M and T, 1e-5 of the largest value.
  constexpr double kTol = 1e-5;
  const int lmax = 3, n = CoeffCount(lmax);
  // Edges short enough that interreflection bounces off the mesh itself (bounce_senders.h), so
  // the brute force below can gather from its triangles.
  Mesh mesh = SphereOverPlane({4.0f, 60, 96});
  for (auto& a : mesh.albedo) a = glm::vec3(0.6f, 0.3f, 0.1f);
  const ShRgb light = BandLimitedLight(lmax);
  const glm::dvec3 eye(4.0, 3.0, 5.0);
  const Material material = RaisedCosine(3, 0.3);
  TransportOptions o;
  o.mode = TransportMode::kInterreflection;
  o.lmax = lmax;
  o.samples = 256;
  o.material = material;
  o.matrices = true;
  TransportReport report;
  const Transport t = ComputeTransport(mesh, o, &report);
  REQUIRE_FALSE(report.senders.needed);
  REQUIRE(t.channels == 3);
  TransportOptions s = o;
  s.mode = TransportMode::kShadowed;
  s.material = Material{};
  s.matrices = false;
  const Transport direct = ComputeTransport(mesh, s, nullptr);  // what a hit sends with one bounce
  const std::vector<glm::vec3> glossy = GlossyFromMatrices(mesh, t, material, light, eye);
  const Bvh bvh = Bvh::Build(mesh);
  const DirectionPool pool = MakeDirectionPool(o.sampler, o.samples, o.direction_sets, o.seed);
  std::vector<std::optional<Hit>> hits;
  double worst = 0.0, peak = 0.0;
  std::size_t gathered = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 2) {
    const glm::dvec3 p(mesh.positions[v]), normal(mesh.normals[v]);
    const glm::dvec3 r = glm::normalize(MirrorView(normal, glm::normalize(eye - p)));
    std::vector<double> u(n);
    LobeTransfer(material.lobe, normal, r, lmax, u.data());
    glm::dvec3 expected(0.0);
    for (int k = 0; k < n; ++k) expected += u[k] * light[k];
    const std::size_t set = pool.SetOf(v);
    bvh.IntersectFan(pool.fans[set], OffsetRayOrigin(mesh.positions[v], mesh.normals[v], bvh.SceneScale()),
                     mesh.normals[v], std::numeric_limits<float>::infinity(), hits);
    for (std::size_t i = 0; i < pool.sets[set].size(); ++i) {
      const glm::dvec3& d = pool.sets[set][i];
      const double c = glm::dot(normal, d);
      if (c <= 0.0 || !hits[i]) continue;
      const double w = 4.0 * kPi / double(pool.size()) * c * material.lobe.Value(glm::dot(r, d));
      expected -= w * LightAt(light, d);
      const auto& tri = mesh.triangles[hits[i]->triangle];
      glm::vec3 g = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]], mesh.positions[tri[2]] - mesh.positions[tri[0]]);
      if (glm::dot(g, mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]]) < 0.0f) g = -g;
      if (glm::dot(g, glm::vec3(d)) >= 0.0f) continue;  // the unlit back sends nothing
      const double b[3] = {1.0 - hits[i]->u - hits[i]->v, hits[i]->u, hits[i]->v};
      glm::dvec3 rho(0.0), sent(0.0);
      for (int j = 0; j < 3; ++j) {
        rho += b[j] * glm::dvec3(mesh.albedo[tri[j]]);
        for (int k = 0; k < n; ++k) sent += b[j] * double(direct.at(tri[j], 0)[k]) * light[k];
      }
      expected += w * rho * sent;
      ++gathered;
    }
    expected *= material.ks;
    for (int ch = 0; ch < 3; ++ch) {
      worst = std::max(worst, std::abs(double(glossy[v][ch]) - expected[ch]));
      peak = std::max(peak, std::abs(expected[ch]));
    }
  }
  CHECK(gathered > 100);
  CHECK(worst <= kTol * peak);
}

TEST_CASE("matrix path seen from any eye equals the fixed-camera vector toward that eye, for a band-limited lobe") {
  // Unshadowed, the two paths are both exact for a lobe of bands <= lmax: the matrices shaded
  // for an eye must give what the vector computed for that eye gives. Catches shading that
  // ignores the eye it is given. Tolerance: the lobe table's interpolation (1e-7) and floats.
  constexpr double kTol = 1e-5;
  const int lmax = 3;
  const Mesh mesh = SphereOverPlane();
  const ShRgb light = BandLimitedLight(lmax);
  const Material material = RaisedCosine(2, 0.4);
  TransportOptions o;
  o.mode = TransportMode::kUnshadowed;
  o.lmax = lmax;
  o.material = material;
  o.matrices = true;
  const Transport matrices = ComputeTransport(mesh, o, nullptr);
  for (const glm::dvec3& eye : {glm::dvec3(4, 3, 5), glm::dvec3(-5, 2, 1), glm::dvec3(0.5, 8, -3)}) {
    TransportOptions f = o;
    f.matrices = false;
    f.eye = eye;
    const Transport fixed = ComputeTransport(mesh, f, nullptr);
    const std::vector<glm::vec3> a = GlossyFromMatrices(mesh, matrices, material, light, eye);
    double worst = 0.0, peak = 0.0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) {
        double b = 0.0;
        for (int k = 0; k < CoeffCount(lmax); ++k) b += light[k][c] * fixed.glossy_at(v, c)[k];
        worst = std::max(worst, std::abs(a[v][c] - b));
        peak = std::max(peak, std::abs(b));
      }
    CHECK(worst <= kTol * peak);
  }
}

TEST_CASE("shadowed matrices: column 0 is pi Y00 times the diffuse transfer at every vertex, with two direction counts") {
  // M_k0 = integral Y_k Y_00 V max(0, n.s) ds = pi Y_00 T_k: the same integral as the diffuse
  // transfer, estimated from the same blocked directions with the same weights, so the two agree
  // to rounding at every vertex, whether it drew the camera's count or the smaller one. Both
  // are stored as float: 1e-6 is a few float steps of their size (at most about 1).
  constexpr double kFloatTolerance = 1e-6;
  constexpr double kY00 = 0.28209479177387814;
  const int lmax = 2, n = CoeffCount(lmax);
  const Mesh mesh = SphereOverPlane();
  TransportOptions o;
  o.mode = TransportMode::kShadowed;
  o.lmax = lmax;
  o.samples = 256;
  o.hidden_samples = 32;
  o.seen.resize(mesh.vertex_count());
  for (std::size_t v = 0; v < o.seen.size(); ++v) o.seen[v] = v % 3 == 0;
  o.material = RaisedCosine(2, 0.3);
  o.matrices = true;
  TransportReport r;
  const Transport t = ComputeTransport(mesh, o, &r);
  REQUIRE(r.hidden_directions == 32);
  REQUIRE(t.matrices.size() == mesh.vertex_count() * std::size_t(n) * n);
  double worst = 0.0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int k = 0; k < n; ++k)
      worst = std::max(worst, std::abs(double(t.matrices[(v * n + k) * n]) - kPi * kY00 * double(t.at(v, 0)[k])));
  MESSAGE("column 0 against pi Y00 T: " << worst);
  CHECK(worst < kFloatTolerance);
}

TEST_SUITE_END();
