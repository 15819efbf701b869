// Material names with blanks (io/material_names.h): `usemtl` and `newmtl` read to the end of
// their line, so a material named with a space keeps its colour, and is named whole when missing.
#include <doctest/doctest.h>

#include <string>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "core/atomic_file.h"
#include "geometry/mesh_ops.h"
#include "io/material_names.h"
#include "io/obj_loader.h"
#include "tests/test_support.h"

namespace prt {
namespace {

// Kd values are parsed from short decimal text into float.
constexpr float kColourTolerance = 1e-6f;

bool Near(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = glm::abs(a - b);
  return d.x <= kColourTolerance && d.y <= kColourTolerance && d.z <= kColourTolerance;
}

/// Three separate triangles, at x = 0, 10 and 20, each after the usemtl line given; `mtl` is the
/// library's text. Returns the OBJ's path.
std::string WriteScene(const std::string& dir, const std::string& mtl, const std::string usemtl[3]) {
  WriteFileAtomic(dir + "/names.mtl", mtl);
  std::string obj = "mtllib names.mtl\n";
  for (int t = 0; t < 3; ++t) {
    const std::string x = std::to_string(10 * t);
    obj += "v " + x + " 0 0\nv " + std::to_string(10 * t + 1) + " 0 0\nv " + x + " 1 0\n" + usemtl[t] + "\n";
    obj += "f " + std::to_string(3 * t + 1) + " " + std::to_string(3 * t + 2) + " " + std::to_string(3 * t + 3) + "\n";
  }
  WriteFileAtomic(dir + "/names.obj", obj);
  return dir + "/names.obj";
}

/// The albedo of the vertex at (x, 0, 0).
glm::vec3 AlbedoAt(const Mesh& mesh, float x) {
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    if (mesh.positions[v] == glm::vec3(x, 0, 0)) return mesh.albedo[v];
  FAIL("no vertex at x = " << x);
  return {};
}

}  // namespace

TEST_SUITE("io") {
  TEST_CASE("material names: usemtl and newmtl both name the whole rest of the line, blanks trimmed") {
    const std::string dir = test::ScratchDir("material_names");
    // "Sphere" is a material of its own: a name cut at its first blank would take its red.
    const std::string mtl =
        "newmtl Sphere\nKd 1 0 0\n"
        "newmtl   Sphere Mat  \r\nKd 0 1 0\r\n"  // extra blanks around it, a CRLF line
        "newmtl Two\tWords\nKd 0 0 1\n";
    const std::string usemtl[3] = {"usemtl Sphere Mat", "  usemtl \tSphere Mat\t ", "usemtl Two\tWords"};
    const LoadedMesh m = LoadObj(WriteScene(dir, mtl, usemtl));
    CHECK(m.report.warnings.empty());
    CHECK(Near(AlbedoAt(m.mesh, 0), glm::vec3(0, 1, 0)));
    CHECK(Near(AlbedoAt(m.mesh, 10), glm::vec3(0, 1, 0)));
    CHECK(Near(AlbedoAt(m.mesh, 20), glm::vec3(0, 0, 1)));
  }

  TEST_CASE("material names: a missing name with a space is named whole, with its faces") {
    const std::string dir = test::ScratchDir("material_names_missing");
    const std::string usemtl[3] = {"usemtl Ghost Mat", "usemtl Sphere", "usemtl Ghost Mat"};
    const std::string path = WriteScene(dir, "newmtl Sphere\nKd 1 0 0\nnewmtl Ghost\nKd 0 1 0\n", usemtl);
    const LoadedMesh m = LoadObj(path);
    REQUIRE(m.report.warnings.size() == 1);
    CHECK(m.report.warnings[0] == path + ": material 'Ghost Mat' is not defined in names.mtl; "
                                         "its 2 faces use the default albedo 0.8");
    CHECK(Near(AlbedoAt(m.mesh, 0), glm::vec3(kDefaultAlbedo)));  // not Ghost's green
    CHECK(Near(AlbedoAt(m.mesh, 10), glm::vec3(1, 0, 0)));
  }

  TEST_CASE("material names: only a statement's own name is rewritten, in place and at the same length") {
    std::string text =
        "usemtl A B\n"           // rewritten
        "# usemtl C D\n"         // a comment
        "g usemtl E F\n"         // a group named so
        "xusemtl G H\r"          // another keyword; a lone \r ends the line
        "\tusemtl  I J \r\n"     // rewritten: indented, blanks before and after
        "usemtl K\n"             // one word: left as it is
        "usemtl";                // no name, at the end of the text
    const std::string before = text;
    HideNameBlanks(text, "usemtl");
    REQUIRE(text.size() == before.size());
    // The rewritten lines read, to a parser that stops at the first blank, as one word that
    // ShowNameBlanks turns back into the name.
    const std::size_t a = text.find("usemtl ") + 7;
    CHECK(ShowNameBlanks(text.substr(a, 3)) == "A B");
    CHECK(text.substr(a, 3) != "A B");
    const std::size_t i = text.find("\tusemtl ") + 8;
    CHECK(ShowNameBlanks(text.substr(i, 3)) == "I J");
    CHECK(text.substr(i, 6) != "I J   ");
    CHECK(text.substr(i + 3, 3) == "  \r");  // the line's other blanks, moved after the name
    // Everything else byte for byte.
    for (const char* kept : {"# usemtl C D\n", "g usemtl E F\n", "xusemtl G H\r", "usemtl K\nusemtl"})
      CHECK(text.find(kept) != std::string::npos);
    CHECK(MaterialNameOf(" \tSphere Mat \t") == "Sphere Mat");
    CHECK(MaterialNameOf("   ").empty());
  }
}

}  // namespace prt
