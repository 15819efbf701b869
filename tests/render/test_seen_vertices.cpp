// The vertices a render shows (render/seen_vertices.h) against scenes whose answer is known by
// construction: a wall hides a sphere, an orbit uncovers it, and a triangle whose corners all lie
// outside the frame still shows its middle.
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "render/render_frames.h"
#include "render/seen_vertices.h"

namespace prt {
namespace {

/// Counts the marked vertices among [first, last).
std::size_t Marked(const std::vector<std::uint8_t>& seen, std::size_t first, std::size_t last) {
  std::size_t n = 0;
  for (std::size_t v = first; v < last; ++v) n += seen[v] != 0;
  return n;
}

/// A camera at +Z looking at the origin, 160 x 120, one frame.
RenderOptions FrontView() {
  RenderOptions o;
  o.frames = 1;
  o.width = 160;
  o.height = 120;
  o.eye = glm::dvec3(0.0, 0.0, 8.0);
  o.target = glm::dvec3(0.0);
  return o;
}

/// A wall facing +Z at z = 1 (a plane turned upright, 4 x 4 quads), wider than the view.
Mesh Wall(float size) {
  Mesh wall = MakePlane(size, 4, 0.0f);
  for (auto& p : wall.positions) p = glm::vec3(p.x, -p.z, 1.0f);
  for (auto& n : wall.normals) n = glm::vec3(0.0f, 0.0f, 1.0f);
  return wall;
}

}  // namespace

TEST_SUITE("render") {
  TEST_CASE("seen vertices: a sphere behind a wall is hidden, and an orbit round the back shows it") {
    Mesh scene = Wall(40.0f);
    const std::size_t wall_vertices = scene.vertex_count();
    AppendMesh(scene, MakeSphere(16, 0.5f, glm::vec3(0.0f, 0.0f, -1.0f)));
    const std::size_t all = scene.vertex_count();
    RenderOptions o = FrontView();
    const Camera camera = ChooseCamera(scene, o);
    const std::vector<std::uint8_t> front = SeenVertices(scene, camera, o);
    REQUIRE(front.size() == all);
    CHECK(Marked(front, wall_vertices, all) == 0);   // the wall covers the whole frame
    CHECK(Marked(front, 0, wall_vertices) > 0);
    // Half a turn over 8 frames: the later frames look from behind the wall at the sphere.
    o.frames = 8;
    o.orbit = 180.0;
    const std::vector<std::uint8_t> orbit = SeenVertices(scene, camera, o);
    CHECK(Marked(orbit, wall_vertices, all) > (all - wall_vertices) / 3);
    // And the light's turn alone moves nothing: eight frames without an orbit show what one does.
    o.orbit = 0.0;
    CHECK(SeenVertices(scene, camera, o) == front);
  }

  TEST_CASE("seen vertices: a triangle whose three corners lie outside the frame still shows its vertices") {
    // One big triangle around the view: every corner is off screen (a test of the corners'
    // own visibility would call them all hidden), yet every pixel shows the triangle.
    Mesh tri;
    tri.positions = {{-50.f, -50.f, 0.f}, {50.f, -50.f, 0.f}, {0.f, 60.f, 0.f}};
    tri.normals.assign(3, glm::vec3(0.f, 0.f, 1.f));
    tri.albedo.assign(3, glm::vec3(0.5f));
    tri.triangles = {{0, 1, 2}};
    Mesh scene = tri;
    // A second triangle that no frame shows: behind the camera.
    Mesh behind = tri;
    for (auto& p : behind.positions) p = glm::vec3(p.x * 0.01f, p.y * 0.01f, 20.0f);
    AppendMesh(scene, behind);
    const RenderOptions o = FrontView();
    const std::vector<std::uint8_t> seen = SeenVertices(scene, ChooseCamera(scene, o), o);
    CHECK(seen == std::vector<std::uint8_t>{1, 1, 1, 0, 0, 0});
  }

  TEST_CASE("seen vertices: triangle numbers beyond 4096 decode to their own triangle") {
    // Many small triangles side by side across the frame: each column of pixels shows exactly
    // one, so a number decoded wrongly (the high bits lost) would mark a triangle off screen.
    const int n = 5000;
    Mesh strip;
    for (int i = 0; i < n; ++i) {
      const float x0 = -4.0f + 8.0f * float(i) / n, x1 = -4.0f + 8.0f * float(i + 1) / n;
      const bool on_screen = i >= n - 64;  // only the last few lie in the frame (moved there below)
      const float shift = on_screen ? 0.0f : 100.0f;
      const auto base = static_cast<std::uint32_t>(strip.positions.size());
      for (const glm::vec3& p : {glm::vec3(x0, -1.f + shift, 0.f), glm::vec3(x1, -1.f + shift, 0.f), glm::vec3(x0, 1.f + shift, 0.f)}) {
        strip.positions.push_back(p);
        strip.normals.emplace_back(0.f, 0.f, 1.f);
        strip.albedo.emplace_back(0.5f);
      }
      strip.triangles.push_back({base, base + 1, base + 2});
    }
    RenderOptions o = FrontView();
    o.eye = glm::dvec3(3.9, 0.0, 3.0);
    o.target = glm::dvec3(3.9, 0.0, 0.0);
    const std::vector<std::uint8_t> seen = SeenVertices(strip, ChooseCamera(strip, o), o);
    CHECK(Marked(seen, 0, 3 * (n - 64)) == 0);
    CHECK(Marked(seen, 3 * (n - 64), 3 * n) > 0);
  }
}

}  // namespace prt
