// OBJ loading: one fixture per failure mode in tests/data/obj, welding rules, materials, and the
// course's mary and bunny when ../shared/data is present.
#include <doctest/doctest.h>

#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "geometry/mesh_ops.h"
#include "io/obj_loader.h"
#include "tests/test_support.h"

namespace prt {
namespace {

// Kd values are parsed from 6-decimal text into float.
constexpr float kColourTolerance = 1e-6f;

bool Near(const glm::vec3& a, const glm::vec3& b, float tol = kColourTolerance) {
  const glm::vec3 d = glm::abs(a - b);
  return d.x <= tol && d.y <= tol && d.z <= tol;
}

// The error message of loading `fixture`, which must start with its path and contain `part`.
void ExpectError(const std::string& fixture, const std::string& part) {
  const std::string path = test::Fixture("obj/" + fixture);
  std::string message;
  try {
    LoadObj(path);
  } catch (const Error& e) {
    message = e.what();
  }
  CAPTURE(fixture);
  CAPTURE(message);
  CHECK(message.rfind(path + ": ", 0) == 0);
  CHECK(message.find(part) != std::string::npos);
  CHECK(message.back() == ')');  // `<path>: <problem> (<expected>)`
}

}  // namespace

TEST_SUITE("io") {
  TEST_CASE("obj: a polygon is triangulated and keeps its file normal") {
    const LoadedMesh m = LoadObj(test::Fixture("obj/quad.obj"));
    CHECK(m.mesh.triangle_count() == 2);
    CHECK(m.mesh.vertex_count() == 4);
    for (const auto& n : m.mesh.normals) CHECK(Near(n, glm::vec3(0, 0, 1)));
    for (const auto& a : m.mesh.albedo) CHECK(Near(a, glm::vec3(kDefaultAlbedo)));
    CHECK(m.report.recomputed_normals == 0);
    CHECK(m.report.warnings.empty());
  }

  TEST_CASE("obj: without normals, smooth normals point out of a closed tetrahedron") {
    const LoadedMesh m = LoadObj(test::Fixture("obj/tetra_no_normals.obj"));
    REQUIRE(m.mesh.vertex_count() == 4);
    CHECK(m.report.recomputed_normals == 4);
    const glm::vec3 centre(0.25f);
    for (std::size_t v = 0; v < 4; ++v) CHECK(glm::dot(m.mesh.normals[v], m.mesh.positions[v] - centre) > 0.0f);
    // The origin corner sees three mutually perpendicular faces of equal area and angle.
    CHECK(Near(m.mesh.normals[0], -glm::normalize(glm::vec3(1.0f)), 1e-6f));
  }

  TEST_CASE("obj: corners with normals weld by (position, normal) pair; creases stay split") {
    const LoadedMesh m = LoadObj(test::Fixture("obj/crease.obj"));
    CHECK(m.mesh.vertex_count() == 7);
    CHECK(m.mesh.triangle_count() == 3);
    CHECK(m.report.welded_away == 2);
  }

  TEST_CASE("obj: corners without normals weld by position within the tolerance") {
    // The tetrahedron's 12 corners reference 4 positions: 4 vertices, 8 welded away.
    const LoadedMesh m = LoadObj(test::Fixture("obj/tetra_no_normals.obj"));
    CHECK(m.mesh.vertex_count() == 4);
    CHECK(m.report.welded_away == 8);
  }

  TEST_CASE("obj: each failure mode has its own clear error") {
    ExpectError("does_not_exist.obj", "no such file");
    ExpectError("", "is a directory");
    ExpectError("no_faces.obj", "no faces");
    ExpectError("index_out_of_range.obj", "out of bounds");
    ExpectError("index_zero.obj", "zero value for face index");
    ExpectError("nan_coordinate.obj", "line 3: coordinate 'nan' is not finite");
    ExpectError("inf_coordinate.obj", "line 4: coordinate 'inf' is not finite");
    ExpectError("all_degenerate.obj", "zero area");
  }

  TEST_CASE("obj: repairs are counted, missing materials are warnings") {
    const LoadedMesh some = LoadObj(test::Fixture("obj/some_degenerate.obj"));
    CHECK(some.mesh.triangle_count() == 1);
    CHECK(some.report.dropped_degenerate == 1);
    const LoadedMesh zero = LoadObj(test::Fixture("obj/zero_normal.obj"));
    CHECK(zero.report.recomputed_normals == 1);
    for (const auto& n : zero.mesh.normals) CHECK(Near(n, glm::vec3(0, 0, 1)));
    const LoadedMesh missing = LoadObj(test::Fixture("obj/missing_mtl.obj"));
    CHECK(!missing.report.warnings.empty());
    for (const auto& a : missing.mesh.albedo) CHECK(Near(a, glm::vec3(kDefaultAlbedo)));
  }

  TEST_CASE("obj: a material name defined twice takes its last definition; colours average") {
    const LoadedMesh m = LoadObj(test::Fixture("obj/duplicate_names.obj"));
    REQUIRE(m.mesh.vertex_count() == 6);
    const glm::vec3 grey(0.8f), blue(0.2f, 0.4f, 0.9f), clamped(1.0f, 0.5f, 0.5f);
    CHECK(Near(m.mesh.albedo[0], grey));                 // only in the unknown-material face
    CHECK(Near(m.mesh.albedo[1], 0.5f * (grey + blue)));  // shared by grey and blue faces
    CHECK(Near(m.mesh.albedo[3], 0.5f * (blue + clamped)));
    CHECK(Near(m.mesh.albedo[5], clamped));
    CHECK(m.report.warnings.size() == 2);  // unknown material, Kd above 1
  }

  TEST_CASE("obj: the course's mary has 7905 vertices and its two colours") {
    PRT_SHARED_DATA_OR_SKIP(data);
    const LoadedMesh m = LoadObj(data + "/games202/mary/mary.obj");
    CHECK(m.mesh.vertex_count() == 7905);
    CHECK(m.report.dropped_degenerate == 2);  // two zero-area faces in the file
    CHECK(m.mesh.triangle_count() == 10174 - 2);
    std::set<std::array<float, 3>> colours;
    for (const auto& a : m.mesh.albedo) colours.insert({a.x, a.y, a.z});
    const glm::vec3 grey(0.8f), blue(0.270588f, 0.552941f, 0.874510f);
    std::size_t n_grey = 0, n_blue = 0;
    for (const auto& a : m.mesh.albedo) n_grey += Near(a, grey) ? 1 : 0, n_blue += Near(a, blue) ? 1 : 0;
    MESSAGE("mary: " << n_grey << " grey and " << n_blue << " blue vertices, " << colours.size() << " colours");
    CHECK(n_grey > 7000);
    CHECK(n_blue > 100);
    const Bounds3 b = MeshBounds(m.mesh);
    CHECK(b.lo.y == doctest::Approx(0.0).epsilon(0.01));
    CHECK(b.hi.y == doctest::Approx(3.41).epsilon(0.01));
  }

  TEST_CASE("obj: the course's bunny loads") {
    PRT_SHARED_DATA_OR_SKIP(data);
    const LoadedMesh m = LoadObj(data + "/games202/bunny/bunny.obj");
    CHECK(m.mesh.triangle_count() > 1000);
    CHECK(m.mesh.normals.size() == m.mesh.vertex_count());
    MESSAGE("bunny: " << m.mesh.vertex_count() << " vertices, " << m.mesh.triangle_count() << " triangles, "
                      << m.report.dropped_degenerate << " dropped, " << m.report.warnings.size() << " warnings");
  }
}

}  // namespace prt
