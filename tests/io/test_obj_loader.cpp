// OBJ loading: one fixture per failure mode in tests/data/obj, welding rules, materials, the
// messages in prt's words, and the course's mary and bunny when ../shared/data is present.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "geometry/mesh_ops.h"
#include "io/obj_loader.h"
#include "io/obj_scan.h"
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
std::string ExpectError(const std::string& fixture, const std::string& part) {
  const std::string path = test::Fixture("obj/" + fixture);
  const std::string message = test::ErrorMessage([&] { LoadObj(path); });
  CAPTURE(fixture);
  CAPTURE(message);
  CHECK(message.rfind(path + ": ", 0) == 0);
  CHECK(message.find(part) != std::string::npos);
  CHECK((!message.empty() && message.back() == ')'));  // `<path>: <problem> (<expected>)`
  return message;
}

// The vertex at position `p` (the fixtures' coordinates are exact).
std::size_t VertexAt(const Mesh& mesh, const glm::vec3& p) {
  const auto it = std::find(mesh.positions.begin(), mesh.positions.end(), p);
  REQUIRE(it != mesh.positions.end());
  return static_cast<std::size_t>(it - mesh.positions.begin());
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// tinyobjloader's own words, which the loader translates rather than passes on.
bool HasRawTinyobjText(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (Contains(w, "not found in .mtl") || Contains(w, "[ '") || Contains(w, "Material file") ||
        Contains(w, "Failed to load"))
      return true;
  return false;
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

  TEST_CASE("obj: corners with normals weld by (position, normal) pair, creases stay split") {
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

  TEST_CASE("obj: the weld joins corners closer than 1e-6 of the mesh size, and no farther ones") {
    // Box diagonal sqrt(3): the weld radius is 1.7e-6. Corner 7 lies 1e-7 from corner 1 (the
    // same point written differently): one vertex. Corner 4 lies 1e-4 from corner 1: a vertex
    // of its own, as a model's fine detail (a thin slit, a sliver) must be.
    const std::string dir = test::ScratchDir("obj_weld");
    WriteFileAtomic(dir + "/near.obj",
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.0001 0 0\nv 1 0 1\nv 0 1 1\nv 0.0000001 0 0\nv 1 1 0\n"
                    "f 1 2 3\nf 4 5 6\nf 7 8 3\n");
    const LoadedMesh m = LoadObj(dir + "/near.obj");
    CHECK(m.mesh.triangle_count() == 3);
    CHECK(m.mesh.vertex_count() == 7);
    CHECK(m.report.welded_away == 2);  // 9 corners: corner 3 twice, corner 7 onto corner 1
    CHECK(m.mesh.triangles[2][0] == m.mesh.triangles[0][0]);
    CHECK(m.mesh.triangles[1][0] != m.mesh.triangles[0][0]);
  }

  TEST_CASE("obj: each failure mode has its own clear error") {
    ExpectError("does_not_exist.obj", "no such file");
    ExpectError("", "is a directory");
    ExpectError("no_faces.obj", "no faces");
    ExpectError("binary.obj", "no faces; ");  // then how many lines were not understood
    ExpectError("index_out_of_range.obj", "line 6: face uses vertex 7, out of bounds: the file has 3 vertices");
    ExpectError("index_zero.obj", "line 5: face uses vertex 0, a zero value");
    ExpectError("negative_out_of_range.obj",
                "line 4: face uses vertex -5, out of bounds: only 3 vertices precede it (indices 1..3 or -1..-3)");
    ExpectError("normal_out_of_range.obj", "line 6: face uses normal 2, out of bounds: the file has 1 normal");
    ExpectError("bad_corner.obj", "line 5: face corner 'x' is not an index");
    ExpectError("truncated.obj", "line 6: face 'f 2 4' has fewer than 3 vertices");
    ExpectError("polygon_forward_reference.obj", "line 6: polygon uses vertex 4, which is defined only after it");
    ExpectError("nan_coordinate.obj", "line 3: coordinate 'nan' is not finite");
    ExpectError("inf_coordinate.obj", "line 4: coordinate 'inf' is not finite");
    ExpectError("float_overflow.obj", "line 3: coordinate '1e39' is not finite");  // finite as a double
    ExpectError("all_degenerate.obj", "zero area");
  }

  TEST_CASE("obj: an index error quotes the index as written, with the ranges valid on its line") {
    // `f 1 2 -7` on line 9 after 4 vertices, 7 in the file. Resolving first would quote -3 or
    // 4 - 7; checking a negative index against the whole file would accept it.
    const std::string m = ExpectError("index_written.obj", "line 9: face uses vertex -7, out of bounds");
    CHECK(Contains(m, "only 4 vertices precede it (indices 1..7 or -1..-4)"));
  }

  TEST_CASE("obj: a face may use a vertex defined after it") {
    // Positive indices count the whole file, not the lines before the face.
    const LoadedMesh m = LoadObj(test::Fixture("obj/forward_reference.obj"));
    CHECK(m.mesh.triangle_count() == 1);
  }

  TEST_CASE("obj: a vertex or normal without three numbers is an error naming its line") {
    const std::string dir = test::ScratchDir("obj_coordinates");
    const struct {
      const char* text;
      const char* says;
    } cases[] = {
        {"v 0 0 0\nv abc 1 2\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 'abc' is not a number (three numbers x y z)"},
        {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex has 2 coordinates (three numbers x y z)"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 # up\nf 1//1 2//1 3//1\n", "line 4: normal has 2 coordinates"},
        {"v 0 0 0\nv 1 0x1 0\nv 0 1 0\nf 1 2 3\n", "vertex coordinate '0x1' is not a number"},
    };
    for (const auto& c : cases) {
      CAPTURE(c.text);
      WriteFileAtomic(dir + "/m.obj", c.text);
      CHECK_THROWS_WITH_AS(LoadObj(dir + "/m.obj"), doctest::Contains(c.says), Error);
    }
  }

  TEST_CASE("obj: lines that are not OBJ are counted, the first quoted with its line number") {
    const LoadedMesh m = LoadObj(test::Fixture("obj/garbage_lines.obj"));
    // Comments, blank lines and g, s, cstype are OBJ; `hello world`, `bogus ...` and an `mtllib`
    // without a file are not. Text after a vertex's coordinates is no reason to count it.
    CHECK(m.report.skipped_lines == 3);
    CHECK(m.report.first_skipped_line == 5);
    CHECK(m.report.first_skipped_text == "hello world");
    CHECK(DescribeSkippedLines(m.report) == "3 lines not understood, skipped (first: line 5: 'hello world')");
    // The `v` line with text after its coordinates is vertex 4, at (2, 0, 0): the second face.
    CHECK(m.mesh.triangle_count() == 2);
    bool found = false;
    for (const auto& p : m.mesh.positions) found |= p == glm::vec3(2.0f, 0.0f, 0.0f);
    CHECK(found);
    CHECK(m.report.warnings.empty());  // counted for the run summary, not warned line by line
    // Windows line ends: same line numbers, and the \r is no part of the quoted text.
    const LoadedMesh crlf = LoadObj(test::Fixture("obj/crlf_garbage.obj"));
    CHECK(crlf.report.skipped_lines == 1);
    CHECK(crlf.report.first_skipped_line == 3);
    CHECK(crlf.report.first_skipped_text == "not obj");
    // A clean file has none.
    const LoadedMesh quad = LoadObj(test::Fixture("obj/quad.obj"));
    CHECK(quad.report.skipped_lines == 0);
    CHECK(DescribeSkippedLines(quad.report).empty());
  }

  TEST_CASE("obj: quoted lines are cut at a character boundary and show control bytes as '?'") {
    CHECK(QuoteLine("hello world") == "hello world");
    CHECK(QuoteLine(std::string(50, 'x')) == std::string(kQuotedLineLength, 'x') + "...");
    CHECK(QuoteLine("a\x01" "b\x7f") == "a?b?");
    CHECK(QuoteLine("\xff\xfe") == "??");  // not UTF-8
    std::string chinese;  // 材质 is two 3-byte characters; 20 of them are 60 bytes
    for (int i = 0; i < 10; ++i) chinese += "\u6750\u8d28";
    const std::string cut = QuoteLine(chinese);
    CHECK(cut == chinese.substr(0, 39) + "...");  // 13 whole characters, none split
  }

  TEST_CASE("obj: a missing material is one warning in prt's words, with its library and face count") {
    // `ghost` is used by two usemtl lines, three faces (one a quad: four triangles).
    const std::string path = test::Fixture("obj/missing_material.obj");
    const LoadedMesh m = LoadObj(path);
    REQUIRE(m.report.warnings.size() == 1);
    CHECK(m.report.warnings[0] == path + ": material 'ghost' is not defined in missing_material.mtl; "
                                         "its 3 faces use the default albedo 0.8");
    // The defined material still applies: (0, 1, 0) is in two `ghost` faces and the `red` one.
    const float g = kDefaultAlbedo;
    CHECK(Near(m.mesh.albedo[VertexAt(m.mesh, {0, 1, 0})], glm::vec3(2 * g + 1, 2 * g, 2 * g) / 3.0f));
    CHECK(Near(m.mesh.albedo[VertexAt(m.mesh, {2, 0, 0})], glm::vec3(g)));  // only in the quad
    // The library itself missing: said within the material's warning.
    const std::string missing = test::Fixture("obj/missing_mtl.obj");
    const LoadedMesh lib = LoadObj(missing);
    REQUIRE(lib.report.warnings.size() == 1);
    CHECK(lib.report.warnings[0] == missing + ": material 'red' is not defined: does_not_exist.mtl was not found; "
                                              "its 1 face uses the default albedo 0.8");
    // A material used before the mtllib line that defines it.
    const LoadedMesh early = LoadObj(test::Fixture("obj/material_before_library.obj"));
    REQUIRE(early.report.warnings.size() == 1);
    CHECK(Contains(early.report.warnings[0], "material 'red' is used before the mtllib line that defines it"));
    CHECK(!HasRawTinyobjText(early.report.warnings));  // the check above is a substring: no raw text beside it
    CHECK(Near(early.mesh.albedo[VertexAt(early.mesh, {0, 0, 0})], glm::vec3(kDefaultAlbedo)));  // only in face 1
    CHECK(Near(early.mesh.albedo[VertexAt(early.mesh, {2, 0, 0})], glm::vec3(1, 0, 0)));         // only in face 2
  }

  TEST_CASE("obj: normal_from_file says which vertex normals came from the file") {
    using Flags = std::vector<std::uint8_t>;
    CHECK(LoadObj(test::Fixture("obj/quad.obj")).normal_from_file == Flags{1, 1, 1, 1});
    CHECK(LoadObj(test::Fixture("obj/tetra_no_normals.obj")).normal_from_file == Flags{0, 0, 0, 0});
    // Face 1 with normals, face 2 without: 3 + 3 vertices (not one flag per position).
    CHECK(LoadObj(test::Fixture("obj/mixed_normals.obj")).normal_from_file == Flags{1, 1, 1, 0, 0, 0});
    // A zero-length file normal counts as none.
    CHECK(LoadObj(test::Fixture("obj/zero_normal.obj")).normal_from_file == Flags{1, 1, 0});
  }

  TEST_CASE("obj: repairs are counted, missing materials are warnings") {
    const LoadedMesh some = LoadObj(test::Fixture("obj/some_degenerate.obj"));
    CHECK(some.mesh.triangle_count() == 1);
    CHECK(some.report.dropped_degenerate == 1);
    const LoadedMesh zero = LoadObj(test::Fixture("obj/zero_normal.obj"));
    CHECK(zero.report.recomputed_normals == 1);
    for (const auto& n : zero.mesh.normals) CHECK(Near(n, glm::vec3(0, 0, 1)));
    const LoadedMesh missing = LoadObj(test::Fixture("obj/missing_mtl.obj"));
    CHECK(missing.report.warnings.size() == 1);
    for (const auto& a : missing.mesh.albedo) CHECK(Near(a, glm::vec3(kDefaultAlbedo)));
  }

  TEST_CASE("obj: a material name defined twice takes its last definition, colours average") {
    const LoadedMesh m = LoadObj(test::Fixture("obj/duplicate_names.obj"));
    REQUIRE(m.mesh.vertex_count() == 6);
    const glm::vec3 grey(0.8f), blue(0.2f, 0.4f, 0.9f), clamped(1.0f, 0.5f, 0.5f);
    CHECK(Near(m.mesh.albedo[0], grey));                 // only in the unknown-material face
    CHECK(Near(m.mesh.albedo[1], 0.5f * (grey + blue)));  // shared by grey and blue faces
    CHECK(Near(m.mesh.albedo[3], 0.5f * (blue + clamped)));
    CHECK(Near(m.mesh.albedo[5], clamped));
    CHECK(m.report.warnings.size() == 2);  // unknown material, Kd above 1
  }

  TEST_CASE("obj: the course's mary has 7905 vertices and its two colours" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    const std::string path = data + "/games202/mary/mary.obj";
    const LoadedMesh m = LoadObj(path);
    CHECK(m.mesh.vertex_count() == 7905);
    CHECK(m.report.skipped_lines == 0);
    // Its body's material is not in mary.mtl: one warning, translated, with its 9904 faces.
    REQUIRE(m.report.warnings.size() == 1);
    CHECK(m.report.warnings[0] == path + ": material 'MC003_Kozakura_Mari' is not defined in mary.mtl; "
                                         "its 9904 faces use the default albedo 0.8");
    REQUIRE(m.normal_from_file.size() == m.mesh.vertex_count());
    CHECK(static_cast<std::size_t>(std::count(m.normal_from_file.begin(), m.normal_from_file.end(), 0)) ==
          m.report.recomputed_normals);
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

  TEST_CASE("obj: the course's bunny loads: 1016 vertices by their (position, normal) pairs, 2000 triangles, the file's normals" * test::NeedsSharedData()) {
    const std::string path = *test::SharedData() + "/games202/bunny/bunny.obj";
    const LoadedMesh m = LoadObj(path);
    // The file: 1016 v, 1016 vn, 2000 faces "f i//i j//j k//k" (counted by grep).
    CHECK(m.mesh.vertex_count() == 1016);
    CHECK(m.mesh.triangle_count() == 2000);
    CHECK(m.report.dropped_degenerate == 0);
    // Its first position and normal, read here from the text, are vertex 0's.
    std::istringstream text(ReadFile(path));
    std::string line;
    glm::vec3 v0(0.0f), n0(0.0f);
    bool have_v = false, have_n = false;
    while (std::getline(text, line) && !(have_v && have_n)) {
      std::istringstream ls(line);
      std::string tag;
      ls >> tag;
      if (tag == "v" && !have_v) ls >> v0.x >> v0.y >> v0.z, have_v = true;
      if (tag == "vn" && !have_n) ls >> n0.x >> n0.y >> n0.z, have_n = true;
    }
    REQUIRE(have_v);
    REQUIRE(have_n);
    CHECK(m.mesh.positions[0] == v0);
    CHECK(glm::length(m.mesh.normals[0] - glm::normalize(n0)) < 1e-6f);
    CHECK(std::count(m.normal_from_file.begin(), m.normal_from_file.end(), true) == 1016);
  }

}

}  // namespace prt
