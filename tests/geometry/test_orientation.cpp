// OrientMesh: inside-out closed parts are turned outward (winding and normals), correct meshes
// are left bit for bit, open surfaces are only warned about, degenerate input is harmless.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "geometry/mesh_ops.h"
#include "geometry/orientation.h"
#include "geometry/procedural.h"

namespace prt {
namespace {

void ReverseWinding(Mesh& m) {
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
}

void NegateNormals(Mesh& m) {
  for (glm::vec3& n : m.normals) n = -n;
}

double Volume(const Mesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) {
    const glm::dvec3 a(m.positions[t[0]]), b(m.positions[t[1]]), c(m.positions[t[2]]);
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return v;
}

// Vertices whose normal does not point away from `centre` (a convex mesh's outward test).
std::size_t InwardNormals(const Mesh& m, const glm::vec3& centre) {
  std::size_t inward = 0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    inward += glm::dot(m.normals[v], m.positions[v] - centre) > 0.0f ? 0 : 1;
  return inward;
}

template <class T>
bool SameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool SameBits(const Mesh& a, const Mesh& b) {
  return SameBits(a.positions, b.positions) && SameBits(a.normals, b.normals) && SameBits(a.albedo, b.albedo) &&
         SameBits(a.triangles, b.triangles) && SameBits(a.file_triangles, b.file_triangles);
}

std::vector<std::uint8_t> AllFromFile(const Mesh& m) { return std::vector<std::uint8_t>(m.vertex_count(), 1); }

// A closed tetrahedron, counter-clockwise seen from outside, normals from SmoothNormals.
Mesh Tetrahedron() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  m.normals = SmoothNormals(m);
  SetUniformAlbedo(m, glm::vec3(kDefaultAlbedo));
  return m;
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("orientation: an inside-out closed mesh with computed normals is turned outward") {
    for (Mesh m : {MakeSphere(48, 2.0f), MakeBox(glm::vec3(-1, -2, -3), glm::vec3(1, 2, 3), BoxFacing::kOutward, 2)}) {
      ReverseWinding(m);
      m.normals = SmoothNormals(m);  // what the loader computes: inward
      REQUIRE(InwardNormals(m, glm::vec3(0.0f)) == m.vertex_count());
      const OrientationReport r = OrientMesh(m, {});
      CHECK(r.closed);
      CHECK(r.signed_volume < 0.0);
      CHECK(r.normals_against_winding == 0.0);  // computed normals follow the winding
      CHECK(r.flipped_triangles == m.triangle_count());
      CHECK(r.flipped_normals == m.vertex_count());
      CHECK(!r.fixed.empty());
      CHECK(r.warning.empty());
      CHECK(Volume(m) > 0.0);
      CHECK(InwardNormals(m, glm::vec3(0.0f)) == 0);
      CHECK(m.normals == SmoothNormals(m));  // equal values (negation may give -0 for +0)
    }
  }

  TEST_CASE("orientation: a nearly closed part is repaired only when its holes cannot decide") {
    // A sphere missing the ring of triangles around one pole (a scan open at its base): the rim
    // is short, the volume large, so the inside is clear. A hemisphere is as open as it gets.
    const auto remove_pole = [](Mesh m, float below_y) {
      std::vector<std::array<std::uint32_t, 3>> kept;
      for (const auto& t : m.triangles)
        if (m.positions[t[0]].y > below_y || m.positions[t[1]].y > below_y || m.positions[t[2]].y > below_y)
          kept.push_back(t);
      m.triangles = kept;
      return m;
    };
    Mesh holed = remove_pole(MakeSphere(48), -0.99f);
    REQUIRE(holed.triangle_count() < MakeSphere(48).triangle_count());
    ReverseWinding(holed);
    holed.normals = SmoothNormals(holed);
    const OrientationReport r = OrientMesh(holed, {});
    CHECK_FALSE(r.closed);
    CHECK(r.flipped_triangles == holed.triangle_count());
    CHECK(r.fixed.find("closed but for small holes") != std::string::npos);
    CHECK(Volume(holed) > 0.0);

    Mesh hemisphere = remove_pole(MakeSphere(48), 0.0f);
    ReverseWinding(hemisphere);
    hemisphere.normals = SmoothNormals(hemisphere);
    const Mesh before = hemisphere;
    const OrientationReport open = OrientMesh(hemisphere, {});
    CHECK(open.flipped_triangles == 0);
    CHECK(open.fixed.empty());
    CHECK(SameBits(hemisphere, before));
  }

  TEST_CASE("orientation: inside-out winding and inward file normals are both repaired") {
    Mesh m = MakeSphere(48);
    ReverseWinding(m);
    NegateNormals(m);
    const OrientationReport r = OrientMesh(m, AllFromFile(m));
    CHECK(r.normals_against_winding == 0.0);  // both inside out: they agree with each other
    CHECK(r.flipped_triangles == m.triangle_count());
    CHECK(r.flipped_normals == m.vertex_count());
    CHECK(Volume(m) > 0.0);
    CHECK(InwardNormals(m, glm::vec3(0.0f)) == 0);
    CHECK(SameBits(m.normals, MakeSphere(48).normals));
  }

  TEST_CASE("orientation: reversed winding with outward file normals keeps the normals") {
    const Mesh original = MakeSphere(48);
    Mesh m = original;
    ReverseWinding(m);
    const OrientationReport r = OrientMesh(m, AllFromFile(m));
    CHECK(r.normals_against_winding == 1.0);
    CHECK(r.flipped_triangles == m.triangle_count());
    CHECK(r.flipped_normals == 0);
    CHECK(Volume(m) > 0.0);
    CHECK(SameBits(m.normals, original.normals));
  }

  TEST_CASE("orientation: inward file normals on a correctly wound sphere are negated") {
    const Mesh original = MakeSphere(48);
    Mesh m = original;
    NegateNormals(m);
    const OrientationReport r = OrientMesh(m, AllFromFile(m));
    CHECK(r.closed);
    CHECK(r.signed_volume > 0.0);
    CHECK(r.normals_against_winding == 1.0);
    CHECK(r.flipped_triangles == 0);
    CHECK(r.flipped_normals == m.vertex_count());
    CHECK(!r.fixed.empty());
    CHECK(SameBits(m, original));
  }

  TEST_CASE("orientation: correct meshes are left bit for bit") {
    for (const Mesh& original : {MakeSphere(32), MakeBox(glm::vec3(-1), glm::vec3(2), BoxFacing::kOutward, 3),
                                 MakeTorusKnot(2, 3, 0.16f, 128, 12), MakeDemoScene(), MakePlane(3.0f, 4),
                                 Tetrahedron()}) {
      for (bool file : {false, true}) {
        Mesh m = original;
        const OrientationReport r = OrientMesh(m, file ? AllFromFile(m) : std::vector<std::uint8_t>{});
        CHECK(r.flipped_triangles == 0);
        CHECK(r.flipped_normals == 0);
        CHECK(r.fixed.empty());
        CHECK(r.warning.empty());
        CHECK(r.normals_against_winding == 0.0);
        CHECK(SameBits(m, original));
      }
    }
  }

  TEST_CASE("orientation: an open plane with normals against its winding is warned about, not changed") {
    Mesh m = MakePlane(2.0f, 4);
    NegateNormals(m);
    const Mesh before = m;
    const OrientationReport r = OrientMesh(m, AllFromFile(m));
    CHECK(!r.closed);
    CHECK(r.normals_against_winding == 1.0);
    CHECK(r.fixed.empty());
    CHECK(r.warning.find("re-export") != std::string::npos);
    CHECK(SameBits(m, before));
    // Wound the other way with computed normals there is nothing to say: a floor has no inside.
    Mesh flipped = MakePlane(2.0f, 4);
    ReverseWinding(flipped);
    flipped.normals = SmoothNormals(flipped);
    const Mesh flipped_before = flipped;
    const OrientationReport q = OrientMesh(flipped, {});
    CHECK(q.fixed.empty());
    CHECK(q.warning.empty());
    CHECK(SameBits(flipped, flipped_before));
  }

  TEST_CASE("orientation: a box with split normals at its creases is closed") {
    // MakeBox gives each face its own vertices: 24 vertices at 8 positions.
    const Mesh box = MakeBox(glm::vec3(-1), glm::vec3(1));
    REQUIRE(box.vertex_count() == 24);
    Mesh m = box;
    const OrientationReport r = OrientMesh(m, AllFromFile(m));
    CHECK(r.closed);
    CHECK(r.signed_volume == doctest::Approx(8.0));
    // The inward room is closed too; its file normals agree with its (inward) winding, so the
    // whole part is inside out and both are turned.
    Mesh room = MakeBox(glm::vec3(-1), glm::vec3(1), BoxFacing::kInward);
    const OrientationReport q = OrientMesh(room, AllFromFile(room));
    CHECK(q.closed);
    CHECK(q.signed_volume == doctest::Approx(-8.0));
    CHECK(q.flipped_triangles == room.triangle_count());
    CHECK(InwardNormals(room, glm::vec3(0.0f)) == 0);
    CHECK(Volume(room) == doctest::Approx(8.0));
  }

  TEST_CASE("orientation: each connected part is judged on its own") {
    Mesh good = MakeSphere(24, 1.0f, glm::vec3(-3, 0, 0));
    Mesh bad = MakeSphere(24, 1.0f, glm::vec3(3, 0, 0));
    ReverseWinding(bad);
    bad.normals = SmoothNormals(bad);
    Mesh m = MakePlane(20.0f, 2, -2.0f);  // an open floor under both
    AppendMesh(m, good);
    AppendMesh(m, bad);
    const std::size_t bad_first = m.triangle_count() - bad.triangle_count();
    const Mesh before = m;
    const OrientationReport r = OrientMesh(m, {});
    CHECK(!r.closed);  // the floor is open
    CHECK(r.flipped_triangles == bad.triangle_count());
    // The floor cannot be judged, but one part of its file was inside out: it is pointed at.
    CHECK(r.warning.find(std::to_string(MakePlane(20.0f, 2).triangle_count()) +
                         " triangles of open parts without normals were left as wound") != std::string::npos);
    std::size_t changed = 0, inward = 0;
    for (std::size_t t = 0; t < bad_first; ++t) changed += m.triangles[t] == before.triangles[t] ? 0 : 1;
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      const glm::vec3 p = m.positions[v];
      const bool outward = p.y == -2.0f ? m.normals[v] == glm::vec3(0, 1, 0)
                                        : glm::dot(m.normals[v], p - glm::vec3(p.x < 0.0f ? -3 : 3, 0, 0)) > 0.0f;
      inward += outward ? 0 : 1;
    }
    CHECK(changed == 0);
    CHECK(inward == 0);
  }

  TEST_CASE("orientation: degenerate, tiny and tangled meshes are harmless") {
    Mesh empty;
    const OrientationReport e = OrientMesh(empty, {});
    CHECK(!e.closed);
    CHECK(e.fixed.empty());
    // One triangle, a collapsed one and a collinear one: open, nothing to do, no NaN.
    Mesh bits;
    bits.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    bits.triangles = {{0, 1, 2}, {0, 0, 2}, {0, 1, 3}};
    bits.normals = SmoothNormals(bits);
    SetUniformAlbedo(bits, glm::vec3(1.0f));
    const OrientationReport b = OrientMesh(bits, {});
    CHECK(!b.closed);
    CHECK(std::isfinite(b.signed_volume));
    CHECK(std::isfinite(b.normals_against_winding));
    CHECK(b.flipped_triangles == 0);
    // A reversed tetrahedron carrying a collapsed triangle is still closed and is repaired.
    Mesh tet = Tetrahedron();
    ReverseWinding(tet);
    tet.triangles.push_back({1, 1, 3});
    tet.normals = SmoothNormals(tet);
    const OrientationReport t = OrientMesh(tet, {});
    CHECK(t.closed);
    CHECK(Volume(tet) == doctest::Approx(1.0 / 6.0));
    // A triangle sealed onto itself (it and its reverse) encloses nothing: left alone.
    Mesh sheet = bits;
    sheet.triangles = {{0, 1, 2}, {0, 2, 1}};
    const Mesh sheet_before = sheet;
    const OrientationReport s = OrientMesh(sheet, AllFromFile(sheet));
    CHECK(s.closed);
    CHECK(s.fixed.empty());
    CHECK(SameBits(sheet, sheet_before));
    // So is an inside-out slab 1e-7 of its width thick (its sides a few ulps apart), while one
    // 1e-3 thick is repaired.
    for (float half_thickness : {1e-7f, 1e-3f}) {
      Mesh slab = MakeBox(glm::vec3(-1, -half_thickness, -1), glm::vec3(1, half_thickness, 1));
      ReverseWinding(slab);
      slab.normals = SmoothNormals(slab);
      const OrientationReport q = OrientMesh(slab, {});
      CHECK(q.closed);
      CHECK(q.fixed.empty() == (half_thickness < 1e-6f));
    }
    // A closed sphere with one triangle turned over: watertight but inconsistent, so warned.
    Mesh tangled = MakeSphere(16);
    std::swap(tangled.triangles[5][1], tangled.triangles[5][2]);
    const Mesh tangled_before = tangled;
    const OrientationReport g = OrientMesh(tangled, {});
    CHECK(!g.closed);
    CHECK(g.fixed.empty());
    CHECK(g.warning.find("inconsistently") != std::string::npos);
    CHECK(SameBits(tangled, tangled_before));
  }
}

}  // namespace prt
