// Procedural meshes: sizes, orientation (outward normals, counter-clockwise triangles) and the
// closed-form volume of the sphere and box.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"

namespace prt {
namespace {

// Signed volume by the divergence theorem: sum over triangles of a . (b x c) / 6.
double SignedVolume(const Mesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) {
    const glm::dvec3 a(m.positions[t[0]]), b(m.positions[t[1]]), c(m.positions[t[2]]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

// Fraction of triangles whose winding normal agrees with the mean of their vertex normals.
double AgreeingFraction(const Mesh& m) {
  std::size_t agree = 0;
  for (const auto& t : m.triangles) {
    const glm::vec3 a = m.positions[t[0]];
    const glm::vec3 face = glm::cross(m.positions[t[1]] - a, m.positions[t[2]] - a);
    const glm::vec3 vn = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
    agree += glm::dot(face, vn) > 0.0f ? 1 : 0;
  }
  return static_cast<double>(agree) / static_cast<double>(m.triangle_count());
}

// Unit normals are normalised in float: their length is 1 to a few ulps.
constexpr float kUnitLengthTolerance = 1e-5f;

void CheckComplete(const Mesh& m) {
  REQUIRE(m.normals.size() == m.positions.size());
  REQUIRE(m.albedo.size() == m.positions.size());
  std::size_t bad_index = 0, bad_normal = 0;
  for (const auto& t : m.triangles)
    for (auto i : t) bad_index += i < m.positions.size() ? 0 : 1;
  for (const auto& n : m.normals) bad_normal += std::abs(glm::length(n) - 1.0f) < kUnitLengthTolerance ? 0 : 1;
  CHECK(bad_index == 0);
  CHECK(bad_normal == 0);
}

// A polyhedron inscribed in the sphere: its volume is below 4/3 pi r^3 by O(1/segments^2).
constexpr double kSphereVolumeTolerance = 2e-3;  // relative, for 128 segments

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("procedural sphere: size, outward winding and volume") {
    const Mesh s = MakeSphere(128, 2.0f);
    CheckComplete(s);
    CHECK(s.triangle_count() == 2u * 128u * 63u);
    CHECK(AgreeingFraction(s) == 1.0);
    const double exact = 4.0 / 3.0 * kPi * 8.0;
    CHECK(std::abs(SignedVolume(s) - exact) / exact < kSphereVolumeTolerance);
    CHECK(MakeSphere(320).triangle_count() >= 100000u);
  }

  TEST_CASE("procedural box: closed, outward and inward") {
    const Mesh out = MakeBox(glm::vec3(-1, -2, -3), glm::vec3(1, 2, 3), BoxFacing::kOutward, 3);
    CheckComplete(out);
    CHECK(out.triangle_count() == 6u * 9u * 2u);
    CHECK(AgreeingFraction(out) == 1.0);
    CHECK(SignedVolume(out) == doctest::Approx(2.0 * 4.0 * 6.0));
    const Mesh in = MakeBox(glm::vec3(-1, -2, -3), glm::vec3(1, 2, 3), BoxFacing::kInward);
    CHECK(AgreeingFraction(in) == 1.0);
    CHECK(SignedVolume(in) == doctest::Approx(-48.0));
  }

  TEST_CASE("procedural plane and torus knot are oriented") {
    const Mesh p = MakePlane(4.0f, 5, 1.0f);
    CheckComplete(p);
    CHECK(p.triangle_count() == 50u);
    CHECK(AgreeingFraction(p) == 1.0);
    const Mesh k = MakeTorusKnot(2, 3, 0.16f, 256, 24);
    CheckComplete(k);
    CHECK(AgreeingFraction(k) == 1.0);
    CHECK(SignedVolume(k) > 0.0);
  }

  TEST_CASE("demo scene stands on the ground plane") {
    const Mesh d = MakeDemoScene();
    CheckComplete(d);
    const Bounds3 b = MeshBounds(d);
    CHECK(b.lo.y == doctest::Approx(0.0).epsilon(1e-6));
    CHECK(b.hi.y == doctest::Approx(3.4).epsilon(1e-3));
  }

  TEST_CASE("knot over ground: the ground's and the knot's vertices in the order asked, each where it stands") {
    KnotOverGround s;
    s.segments = 40, s.sides = 6, s.ground_quads = 5, s.ground_size = 8.0f;
    s.height = 2.0f, s.lift = 0.05f;
    s.knot_albedo = glm::vec3(0.8f, 0.3f, 0.2f), s.ground_albedo = glm::vec3(0.75f);
    const std::size_t ground = MakePlane(8.0f, 5, 0.0f).vertex_count();
    const std::size_t knot = MakeTorusKnot(2, 3, 0.16f, 40, 6).vertex_count();
    for (const bool ground_first : {true, false}) {
      CAPTURE(ground_first);
      s.ground_first = ground_first;
      const Mesh m = MakeKnotOverGround(s);
      REQUIRE(m.vertex_count() == ground + knot);
      REQUIRE(m.triangles.size() == MakePlane(8.0f, 5, 0.0f).triangles.size() + 2u * 40 * 6);
      const std::size_t ground_begin = ground_first ? 0 : knot, knot_begin = ground_first ? ground : 0;
      float lo = 1e9f, hi = -1e9f;
      for (std::size_t v = 0; v < ground; ++v) {
        CHECK(m.positions[ground_begin + v].y == 0.0f);
        CHECK(std::abs(m.positions[ground_begin + v].x) <= 4.0f);
        CHECK(m.albedo[ground_begin + v] == s.ground_albedo);
      }
      for (std::size_t v = 0; v < knot; ++v) {
        lo = std::min(lo, m.positions[knot_begin + v].y), hi = std::max(hi, m.positions[knot_begin + v].y);
        CHECK(m.albedo[knot_begin + v] == s.knot_albedo);
      }
      CHECK(lo == doctest::Approx(0.05f).epsilon(1e-5));  // standing `lift` above the ground
      CHECK(hi - lo == doctest::Approx(2.0f).epsilon(1e-5));
      // Every triangle joins vertices of one part: the two are merged, not welded.
      for (const auto& t : m.triangles) {
        const bool in_ground = t[0] >= ground_begin && t[0] < ground_begin + ground;
        for (int j = 1; j < 3; ++j) CHECK((t[j] >= ground_begin && t[j] < ground_begin + ground) == in_ground);
      }
    }
  }

  TEST_CASE("knot over ground: the demo scene is the builder's defaults, a 3.4-unit knot on a 12 x 12 ground") {
    const Mesh demo = MakeDemoScene();
    const Mesh built = MakeKnotOverGround(KnotOverGround{});
    REQUIRE(demo.vertex_count() == built.vertex_count());
    CHECK(demo.positions == built.positions);
    CHECK(demo.triangles == built.triangles);
    CHECK(demo.positions.front().y == 0.0f);  // the ground first
    CHECK(demo.vertex_count() == MakePlane(12.0f, 96, 0.0f).vertex_count() + MakeTorusKnot(2, 3, 0.16f, 512, 48).vertex_count());
  }
}

}  // namespace prt
