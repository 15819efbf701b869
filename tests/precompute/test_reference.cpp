// Ground truth (precompute/reference.h): analytic cases first.
#include <doctest/doctest.h>

#include <cmath>

#include "core/parallel.h"
#include "env/procedural.h"
#include "geometry/procedural.h"
#include "precompute/error_metrics.h"
#include "precompute/reference.h"
#include "precompute/reference_env_sampler.h"

namespace prt {
namespace {

// Furnace (radiance up to 2): the estimator's only noise is that of max(0, n.w) under a
// near-uniform density; with 2048 shifted lattice directions the worst vertex is off by 3.7e-3
// (0.19%), so 1e-2 (0.5%) is a margin of under 3x that still catches a wrong weight or pdf.
constexpr double kFurnaceTolerance = 1e-2;
// The sky's table integral against its Gauss quadrature plus the analytic sun: the table's
// max-of-9 cell weights and the defensive floor overestimate by construction, by at most the
// floor (10% of the mean) plus the within-cell variation; 25% bounds it.
constexpr double kTableTolerance = 0.25;

}  // namespace

TEST_SUITE("precompute") {
  TEST_CASE("reference: furnace gives albedo * C at every vertex, and says how good it is") {
    const auto env = MakeFurnace(2.0);
    const Mesh mesh = MakeSphere(16, 1.0f, glm::vec3(0.f), glm::vec3(0.5f, 0.25f, 1.0f));
    ReferenceOptions o;
    o.mode = TransportMode::kUnshadowed;
    o.samples = 2048;
    o.table_rows = 64, o.table_cols = 128;
    const Reference ref = ComputeReference(mesh, *env, o);
    std::vector<glm::dvec3> exact(mesh.vertex_count());
    for (std::size_t v = 0; v < exact.size(); ++v) exact[v] = 2.0 * glm::dvec3(mesh.albedo[v]);
    const VertexError e = CompareVertices(ref.radiance, exact);
    CHECK(e.max < kFurnaceTolerance);
    CHECK(ref.rms_error < kFurnaceTolerance);
    CHECK(ref.rms_error > 0.0);  // the halves are independent: a zero would mean they are not
  }

  TEST_CASE("reference: a lone convex sphere is never shadowed, and results do not depend on threads") {
    const auto env = MakeSky(SkyParams{});
    const Mesh mesh = MakeSphere(12);
    ReferenceOptions o;
    o.samples = 256;
    o.table_rows = 64, o.table_cols = 128;
    o.mode = TransportMode::kUnshadowed;
    const Reference unshadowed = ComputeReference(mesh, *env, o);
    o.mode = TransportMode::kShadowed;
    SetThreadCount(1);
    const Reference one = ComputeReference(mesh, *env, o);
    SetThreadCount(2);
    const Reference two = ComputeReference(mesh, *env, o);
    SetThreadCount(0);
    CHECK(one.radiance == two.radiance);
    CHECK(one.radiance == unshadowed.radiance);
    CHECK(one.rays > 0);
  }

  TEST_CASE("reference: the environment table integrates the sky with its sun") {
    const SkyParams p;
    const auto env = MakeSky(p);
    const EnvSampler sampler(*env, 128, 256);
    // The sky's luminance integral: band 0 of its projection times sqrt(4 pi).
    const double sun_luminance = 0.2126 * 1.0 + 0.7152 * 0.93 + 0.0722 * 0.82;
    CHECK(sampler.TableIntegral() > p.sun * sun_luminance);  // the sun alone
    CHECK(sampler.TableIntegral() < (1.0 + kTableTolerance) * 4.0 * 3.14159265358979 * 2.0);
  }

  TEST_CASE("error metrics: Neumaier sum and log-log slope") {
    NeumaierSum s;
    s.Add(1.0);
    for (int i = 0; i < 1000; ++i) s.Add(1e-16);
    CHECK(s.Value() - 1.0 == doctest::Approx(1e-13).epsilon(1e-6));
    const std::vector<double> x = {1, 10, 100}, y = {1, 0.1, 0.01};
    CHECK(LogLogSlope(x, y) == doctest::Approx(-1.0));
  }
}

}  // namespace prt
