// Textured meshes from OBJ files: map_Kd found relative to its .mtl, a plain Kd beside it, texture
// coordinates per corner through welding (UV seams), orientation repair and edge splitting, the
// usual messages for missing and bad textures, and the bounce taking the texture's albedo.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "geometry/mesh_texture.h"
#include "geometry/orientation.h"
#include "geometry/subdivide.h"
#include "io/obj_loader.h"
#include "io/png_io.h"
#include "precompute/transport.h"
#include "texture/texture.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("texture");

namespace {

// Corner coordinates are copied or averaged from the file's floats: float rounding only.
constexpr float kUvTolerance = 1e-6f;

void WriteSolidPng(const std::string& path, int r, int g, int b, int size = 4) {
  Image8 image(size, size);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    image.rgb[i] = std::uint8_t(r), image.rgb[i + 1] = std::uint8_t(g), image.rgb[i + 2] = std::uint8_t(b);
  WritePng(path, image);
}

// A unit square at y = 0 made of two quads, x in [0, 2], z in [0, 1]: the left quad of material
// `left` (textured by map_Kd textures/red.png, relative to the .mtl in mtl/), the right one of
// `right` (Kd 0 0 1, no texture). One normal for all corners, so the six positions weld into six
// vertices; the middle column's corners have different vt on either side (a UV seam).
std::string WriteSeamStrip(const std::string& dir) {
  std::filesystem::create_directories(dir + "/mtl/textures");
  WriteSolidPng(dir + "/mtl/textures/red.png", 255, 0, 0);
  WriteFileAtomic(dir + "/mtl/strip.mtl",
                  "newmtl left\nKd 0.8 0.8 0.8\nmap_Kd textures/red.png\n"
                  "newmtl right\nKd 0 0 1\n");
  WriteFileAtomic(dir + "/strip.obj",
                  "mtllib mtl/strip.mtl\n"
                  "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 1\nv 1 0 1\nv 2 0 1\n"
                  "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"           // the left quad: 1..4
                  "vt 0.25 0.5\nvt 0.75 0.5\nvt 0.25 0.9\nvt 0.75 0.9\n"  // the right quad: 5..8
                  "vn 0 1 0\n"
                  "usemtl left\nf 1/1/1 4/3/1 5/4/1 2/2/1\n"
                  "usemtl right\nf 2/5/1 5/7/1 6/8/1 3/6/1\n");
  return dir + "/strip.obj";
}

glm::vec2 CornerUv(const Mesh& m, std::size_t t, int c) { return m.corner_uv[3 * t + c]; }

}  // namespace

TEST_CASE("textured OBJ: map_Kd relative to the .mtl, a plain Kd beside it, and a UV seam that welding keeps") {
  const std::string obj = WriteSeamStrip(test::ScratchDir("textured_strip"));
  const LoadedMesh loaded = LoadObj(obj);
  const Mesh& m = loaded.mesh;
  REQUIRE(m.textured());
  CHECK(m.vertex_count() == 6);  // welded across the seam: one transport per position
  REQUIRE(m.triangle_count() == 4);
  REQUIRE(m.corner_uv.size() == 12);
  REQUIRE(m.textures.size() == 2);
  // The left quad's texture is the red file (replacing Kd 0.8), the right one a 1 x 1 of its Kd.
  const Texture& left = *m.textures[m.triangle_texture[0]];
  const Texture& right = *m.textures[m.triangle_texture[2]];
  CHECK(left.width() == 4);
  CHECK(left.mean() == glm::vec3(1.f, 0.f, 0.f));
  CHECK(right.width() == 1);
  CHECK(right.mean() == glm::vec3(0.f, 0.f, 1.f));
  CHECK(std::find(loaded.texture_files.begin(), loaded.texture_files.end(),
                  (std::filesystem::path(obj).parent_path() / "mtl/textures/red.png").string()) != loaded.texture_files.end());
  // Vertex 1 (position 2 of the file, x = 1, z = 0) is a corner on both sides with its own vt.
  std::vector<glm::vec2> seen;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c)
      if (m.positions[m.triangles[t][c]] == glm::vec3(1, 0, 0)) seen.push_back(CornerUv(m, t, c));
  CHECK(std::find(seen.begin(), seen.end(), glm::vec2(1, 0)) != seen.end());
  CHECK(std::find(seen.begin(), seen.end(), glm::vec2(0.25f, 0.5f)) != seen.end());
  // The vertex albedo: the mean over its corners of the textures (red on the left, blue on the right).
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const float x = m.positions[v].x;
    const glm::vec3 expected = x == 0.f ? glm::vec3(1, 0, 0) : x == 2.f ? glm::vec3(0, 0, 1) : glm::vec3(-1);
    if (expected.x >= 0.f) CHECK(m.albedo[v] == expected);
    else CHECK((m.albedo[v].x > 0.f && m.albedo[v].z > 0.f));  // the seam column mixes both
  }
}

TEST_CASE("textured OBJ: --texture applies one file to every face; a file without vt is refused") {
  const std::string dir = test::ScratchDir("textured_override");
  const std::string obj = WriteSeamStrip(dir);
  WriteSolidPng(dir + "/green.png", 0, 255, 0);
  const Mesh m = LoadObj(obj, dir + "/green.png").mesh;
  REQUIRE(m.textured());
  for (std::uint32_t t : m.triangle_texture) CHECK(m.textures[t]->mean() == glm::vec3(0.f, 1.f, 0.f));
  try {
    LoadObj(test::Fixture("obj/tetra_no_normals.obj"), dir + "/green.png");
    FAIL("no error for an OBJ without texture coordinates");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("no texture coordinates") != std::string::npos);
  }
}

TEST_CASE("textured OBJ: a missing map_Kd is a warning (Kd kept), a corrupt one an error") {
  const std::string dir = test::ScratchDir("textured_missing");
  const std::string obj = WriteSeamStrip(dir);
  std::filesystem::remove(dir + "/mtl/textures/red.png");
  const LoadedMesh missing = LoadObj(obj);
  bool warned = false;
  for (const std::string& w : missing.report.warnings) warned = warned || w.find("red.png' of material 'left' was not found") != std::string::npos;
  CHECK(warned);
  CHECK(missing.mesh.textures[missing.mesh.triangle_texture[0]]->mean() == glm::vec3(0.8f));
  WriteFileAtomic(dir + "/mtl/textures/red.png", "\x89PNG but not really");
  CHECK_THROWS_WITH_AS(LoadObj(obj), doctest::Contains("red.png:"), Error);
}

TEST_CASE("textured mesh: splitting long edges and turning inside-out parts keep each corner's coordinates") {
  // Every corner's coordinates are a fixed affine function of its position: that must stay so.
  const auto uv_of = [](const glm::vec3& p) { return glm::vec2(0.5f + 0.25f * p.x, 0.1f + 0.3f * p.z + 0.2f * p.y); };
  const auto check_affine = [&](const Mesh& m) {
    REQUIRE(m.corner_uv.size() == 3 * m.triangle_count());
    REQUIRE(m.triangle_texture.size() == m.triangle_count());
    std::size_t bad = 0;
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
      for (int c = 0; c < 3; ++c) {
        const glm::vec2 d = CornerUv(m, t, c) - uv_of(m.positions[m.triangles[t][c]]);
        bad += std::fabs(d.x) > kUvTolerance || std::fabs(d.y) > kUvTolerance;
      }
    CHECK(bad == 0);
  };
  // An inside-out tetrahedron (faces wound inward, no normals) with vt = uv_of(v).
  const std::string dir = test::ScratchDir("textured_edits");
  WriteSolidPng(dir + "/t.png", 200, 100, 50);
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
    const glm::vec2 uv = uv_of(p);
    text += "vt " + std::to_string(uv.x) + " " + std::to_string(uv.y) + "\n";
  }
  text += "f 1/1 2/2 3/3\nf 1/1 4/4 2/2\nf 1/1 3/3 4/4\nf 2/2 4/4 3/3\n";  // inward
  WriteFileAtomic(dir + "/inside_out.obj", text);
  LoadedMesh loaded = LoadObj(dir + "/inside_out.obj", dir + "/t.png");
  // std::to_string keeps 6 decimals: compare against what the file holds.
  for (std::size_t t = 0; t < loaded.mesh.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c) loaded.mesh.corner_uv[3 * t + c] = uv_of(loaded.mesh.positions[loaded.mesh.triangles[t][c]]);
  const OrientationReport report = OrientMesh(loaded.mesh, loaded.normal_from_file);
  CHECK(report.flipped_triangles == 4);
  check_affine(loaded.mesh);
  SplitLongEdges(loaded.mesh, 0.3f);
  CHECK(loaded.mesh.triangle_count() > 16);
  check_affine(loaded.mesh);
}

TEST_SUITE_END();
