// SplitLongEdges: every edge ends short, the surface is unchanged (area, plane, winding), it stays
// conforming (no T-junctions, closed meshes stay closed), attributes are interpolated, and
// EstimateSplitTriangles bounds the result.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "geometry/mesh_ops.h"
#include "geometry/position_ids.h"
#include "geometry/procedural.h"
#include "geometry/subdivide.h"

namespace prt {
namespace {

// Sums of float areas over a few thousand triangles: a few float ulps each.
constexpr double kAreaTolerance = 1e-5;  // relative
// Midpoints are rounded to float: a tilted plane's new vertices leave it by a few ulps of the
// coordinates (size 10 here, ulp ~1e-6).
constexpr float kPlaneTolerance = 1e-5f;
// Normalising a float vector leaves its length within a few ulps of 1.
constexpr float kUnitLengthTolerance = 1e-5f;
// Albedo midpoints are rounded once per level of splitting: a few float ulps.
constexpr float kAlbedoTolerance = 1e-5f;
// The estimate is exact while a triangle's three edges are long, then allows 4^P: P can exceed
// the passes left by one (x4), and a pass can split one edge, making two triangles, not four
// (x2). These quads, boxes and knots measure 1 to 8.
constexpr double kEstimateFactor = 8.0;

double TotalArea(const Mesh& m) {
  double a = 0.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) a += 0.5 * static_cast<double>(TriangleDoubleArea(m, t));
  return a;
}

float LongestEdge(const Mesh& m) {
  float longest = 0.0f;
  for (const auto& t : m.triangles)
    for (int c = 0; c < 3; ++c)
      longest = std::max(longest, glm::length(m.positions[t[c]] - m.positions[t[(c + 1) % 3]]));
  return longest;
}

// A parallelogram of area 100 (one quad, two triangles): the square of side 10 sheared by
// x += shear * z, then turned so that +Y becomes `normal`. Red along one side, blue along the
// opposite one.
Mesh TwoColourQuad(const glm::vec3& normal, float shear) {
  Mesh m = MakePlane(10.0f, 1);
  const glm::vec3 n = glm::normalize(normal);
  // Rotation taking +Y to n (Rodrigues), applied to positions and normals.
  const glm::vec3 axis = glm::cross(glm::vec3(0, 1, 0), n);
  const float s = glm::length(axis), c = n.y;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    m.albedo[v] = m.positions[v].x < 0.0f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    m.positions[v].x += shear * m.positions[v].z;
    if (s == 0.0f) continue;
    const glm::vec3 k = axis / s, p = m.positions[v];
    m.positions[v] = p * c + glm::cross(k, p) * s + k * glm::dot(k, p) * (1.0f - c);
    m.normals[v] = n;
  }
  return m;
}

// Splits `quad` (from TwoColourQuad) and checks the result against the original surface.
void CheckSplitQuad(const Mesh& quad, float max_edge) {
  Mesh m = quad;
  m.file_triangles = m.triangles;  // as loaded from a file: a split must clear it
  const std::size_t estimate = EstimateSplitTriangles(m, max_edge);
  const SplitReport r = SplitLongEdges(m, max_edge);
  CHECK(r.triangles_before == 2);
  CHECK(r.triangles_after == m.triangle_count());
  CHECK(r.vertices_added == m.vertex_count() - 4);
  CHECK(r.passes > 0);
  CHECK(LongestEdge(m) <= max_edge);
  CHECK(std::abs(TotalArea(m) - 100.0) / 100.0 < kAreaTolerance);
  CHECK(estimate >= m.triangle_count());
  CHECK(static_cast<double>(estimate) <= kEstimateFactor * static_cast<double>(m.triangle_count()));
  CHECK(m.file_triangles.empty());
  // One vertex per position: edges are split once, their midpoints shared.
  const std::vector<std::uint32_t> ids = PositionIds(m);
  CHECK(*std::max_element(ids.begin(), ids.end()) + 1 == m.vertex_count());

  // Every vertex on the plane, unit normal, albedo linear from the red side (v0 v2) to the blue
  // one (v1 v3); every triangle wound like the original (face normal along the plane's normal).
  const glm::vec3 n = quad.normals[0], o = quad.positions[0];
  const glm::vec3 along = quad.positions[1] - o, across = quad.positions[2] - o;
  const glm::vec3 dual = glm::cross(across, glm::cross(along, across));  // dot(dual, along) > 0
  std::size_t off_plane = 0, bad_normal = 0, bad_albedo = 0, reversed = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    off_plane += std::abs(glm::dot(m.positions[v], n)) <= kPlaneTolerance ? 0 : 1;
    bad_normal += std::abs(glm::length(m.normals[v]) - 1.0f) <= kUnitLengthTolerance ? 0 : 1;
    const float u = glm::dot(m.positions[v] - o, dual) / glm::dot(along, dual);
    const glm::vec3 expected = (1.0f - u) * glm::vec3(1, 0, 0) + u * glm::vec3(0, 0, 1);
    bad_albedo += glm::length(m.albedo[v] - expected) <= kAlbedoTolerance ? 0 : 1;
  }
  for (const auto& t : m.triangles) {
    const glm::vec3 a = m.positions[t[0]];
    reversed += glm::dot(glm::cross(m.positions[t[1]] - a, m.positions[t[2]] - a), n) > 0.0f ? 0 : 1;
  }
  CHECK(off_plane == 0);
  CHECK(bad_normal == 0);
  CHECK(bad_albedo == 0);
  CHECK(reversed == 0);

  // No T-junction: every edge is shared by two triangles in opposite directions, except edges
  // along the quad's border, used once.
  std::vector<glm::vec3> position_of(m.vertex_count());
  for (std::size_t v = 0; v < m.vertex_count(); ++v) position_of[ids[v]] = m.positions[v];
  const int border[4][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}};  // MakePlane's corners, in order
  auto on_border = [&](const glm::vec3& a, const glm::vec3& b) {
    for (const auto& side : border) {
      const glm::vec3 p = quad.positions[side[0]], dir = glm::normalize(quad.positions[side[1]] - p);
      if (glm::length(glm::cross(a - p, dir)) < kPlaneTolerance && glm::length(glm::cross(b - p, dir)) < kPlaneTolerance)
        return true;
    }
    return false;
  };
  std::size_t bad_edges = 0;
  for (const PositionEdge& e : PositionEdges(m, ids)) {
    const bool shared = e.uses == 2 && e.balance == 0;
    bad_edges += shared || (e.uses == 1 && on_border(position_of[e.lo], position_of[e.hi])) ? 0 : 1;
  }
  CHECK(bad_edges == 0);
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("subdivide: a quad of side 10 ends with every edge short, on the same surface") {
    // Max edge 1 on the square makes four copies of every triangle at every pass (k = 3); the
    // other cases also split one edge (k = 1), two (k = 2), or both, in some triangles.
    const glm::vec3 up(0, 1, 0), tilted(0.3f, 1.0f, -0.6f);
    SUBCASE("square, max edge 1") { CheckSplitQuad(TwoColourQuad(up, 0.0f), 1.0f); }
    SUBCASE("tilted square, max edge 1.3") { CheckSplitQuad(TwoColourQuad(tilted, 0.0f), 1.3f); }
    SUBCASE("parallelogram, max edge 0.7") { CheckSplitQuad(TwoColourQuad(up, 0.6f), 0.7f); }
    SUBCASE("tilted parallelogram, max edge 1.3") { CheckSplitQuad(TwoColourQuad(tilted, 1.0f), 1.3f); }
  }

  TEST_CASE("subdivide: a box with split normals stays closed and keeps its volume") {
    Mesh box = MakeBox(glm::vec3(-1, -2, -3), glm::vec3(1, 2, 3));
    const std::size_t estimate = EstimateSplitTriangles(box, 0.7f);
    const SplitReport r = SplitLongEdges(box, 0.7f);
    CHECK(estimate >= r.triangles_after);
    CHECK(static_cast<double>(estimate) <= kEstimateFactor * static_cast<double>(r.triangles_after));
    CHECK(r.triangles_after > 100);
    CHECK(LongestEdge(box) <= 0.7f);
    std::size_t open = 0;
    for (const PositionEdge& e : PositionEdges(box, PositionIds(box))) open += e.uses == 2 && e.balance == 0 ? 0 : 1;
    CHECK(open == 0);
    CHECK(std::abs(TotalArea(box) - 88.0) / 88.0 < kAreaTolerance);
  }

  TEST_CASE("subdivide: short edges are left alone, output is deterministic, bad limits are refused") {
    Mesh sphere = MakeSphere(32);
    sphere.file_triangles = sphere.triangles;
    const Mesh before = sphere;
    CHECK(EstimateSplitTriangles(sphere, 10.0f) == sphere.triangle_count());
    const SplitReport r = SplitLongEdges(sphere, 10.0f);
    CHECK(r.passes == 0);
    CHECK(r.vertices_added == 0);
    CHECK(sphere.triangles == before.triangles);
    CHECK(sphere.positions == before.positions);
    CHECK(sphere.file_triangles == before.file_triangles);

    Mesh a = MakeTorusKnot(2, 3, 0.16f, 64, 8), b = a;
    const std::size_t estimate = EstimateSplitTriangles(a, 0.05f);
    SplitLongEdges(a, 0.05f);
    SplitLongEdges(b, 0.05f);
    CHECK(estimate >= a.triangle_count());
    CHECK(static_cast<double>(estimate) <= kEstimateFactor * static_cast<double>(a.triangle_count()));
    CHECK(LongestEdge(a) <= 0.05f);
    CHECK(a.triangles == b.triangles);
    CHECK(a.positions == b.positions);

    CHECK_THROWS_AS(SplitLongEdges(a, 0.0f), Error);
    CHECK_THROWS_AS(SplitLongEdges(a, -1.0f), Error);
    // Finer than float positions resolve: refused by both.
    CHECK(EstimateSplitTriangles(a, 1e-30f) == std::numeric_limits<std::size_t>::max());
    CHECK_THROWS_AS(SplitLongEdges(a, 1e-30f), Error);
    // MinimumMaxEdge is that limit: refused just below it, resolvable just above (a triangle
    // is enough to ask; the estimate says whether a split would run).
    Mesh one;
    one.positions = {{0, 0, 0}, {1e-4f, 0, 0}, {0, 1e-4f, 0}, {1, 1, 1}};  // largest coordinate 1
    one.normals.assign(4, glm::vec3(0, 0, 1));
    one.albedo.assign(4, glm::vec3(0.5f));
    one.triangles = {{0, 1, 2}};
    const double limit = MinimumMaxEdge(one);
    CHECK(limit == doctest::Approx(std::ldexp(1.0, -20) / (1.0 - std::sqrt(2.0 / 3.0))));
    CHECK(EstimateSplitTriangles(one, static_cast<float>(0.99 * limit)) == std::numeric_limits<std::size_t>::max());
    CHECK(EstimateSplitTriangles(one, static_cast<float>(1.01 * limit)) < std::numeric_limits<std::size_t>::max());
  }

  TEST_CASE("subdivide: zero-area triangles terminate") {
    Mesh m;
    m.positions = {{0, 0, 0}, {5, 0, 0}, {10, 0, 0}, {3, 3, 3}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.albedo.assign(4, glm::vec3(0.5f));
    m.triangles = {{0, 1, 2}, {0, 0, 3}};  // collinear, and collapsed
    const std::size_t estimate = EstimateSplitTriangles(m, 1.0f);
    SplitLongEdges(m, 1.0f);
    CHECK(LongestEdge(m) <= 1.0f);
    CHECK(m.triangle_count() <= estimate);
  }
}

}  // namespace prt
