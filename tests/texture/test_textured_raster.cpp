// Drawing textured meshes: perspective-correct texture coordinates against ray casting (also on
// triangles the near plane cuts), mip filtering of a distant checker, the checker under the
// furnace reproduced exactly through the command line, the bounce's albedo read from the texture,
// the cache key, and goldens.
#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "env/load_environment.h"
#include "env/procedural.h"
#include "geometry/mesh_ops.h"
#include "geometry/mesh_texture.h"
#include "geometry/procedural.h"
#include "io/obj_loader.h"
#include "precompute/light.h"
#include "precompute/transport.h"
#include "precompute_io/transport_cache.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"
#include "render/render_frames.h"
#include "sh/axis_rotation.h"
#include "sh_basis/frame_light.h"
#include "tests/golden.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("texture");

namespace {

// Texture coordinates are interpolated in float from planes: a few 1e-4 of error over a frame.
// Affine (not perspective-correct) interpolation misses by about 0.1 on the tilted floor below.
constexpr float kPerspectiveTolerance = 2e-3f;

// A 2 x 2 quad in the plane y = 0 (two triangles, facing +y), texture coordinates (x+1)/2, (1-z)/2.
Mesh TexturedFloor(std::shared_ptr<const Texture> texture) {
  Mesh m;
  m.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.albedo.assign(4, glm::vec3(0.5f));
  m.triangles = {{0, 2, 1}, {0, 3, 2}};
  for (const auto& t : m.triangles)
    for (std::uint32_t v : t) m.corner_uv.emplace_back((m.positions[v].x + 1) / 2, (1 - m.positions[v].z) / 2);
  m.triangle_texture = {0, 0};
  m.textures = {std::move(texture)};
  return m;
}

RasterImage DrawFloor(const Mesh& m, const Camera& camera, int size) {
  RasterTexturing texturing{&m.corner_uv, &m.triangle_texture, &m.textures, nullptr};
  RasterOptions o;
  o.texturing = &texturing;
  return Rasterize(camera, size, size, m.positions, m.triangles, std::vector<glm::vec3>(4, glm::vec3(1.f)), o);
}

// A linear ramp: red = u, green = v at the texel centres (so bilinear sampling returns (u, v)).
std::shared_ptr<const Texture> Ramp(int n) {
  ImageF image(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) image.at(x, y) = glm::vec3((float(x) + 0.5f) / float(n), 1.f - (float(y) + 0.5f) / float(n), 0.f);
  return std::make_shared<const Texture>(std::move(image), "ramp");
}

std::shared_ptr<const Texture> Checker(int n, int square, const glm::vec3& a, const glm::vec3& b) {
  ImageF image(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) image.at(x, y) = (x / square + y / square) % 2 ? a : b;
  return std::make_shared<const Texture>(std::move(image), "checker");
}

}  // namespace

/// Pixels of `frame` (drawn by `camera`) whose texture coordinates differ from a ray cast to
/// the floor by more than kPerspectiveTolerance; `compared` counts the pixels checked: those
/// showing the floor beyond the near plane, away from the coordinates' wrap.
int WrongTexturePixels(const RasterImage& frame, const Camera& camera, int size, int& compared) {
  const ViewRays rays = MakeViewRays(camera, 1.f);
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  int wrong = 0;
  compared = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float s = static_cast<float>(size);
      const glm::vec3 d = rays.Direction((float(x) + 0.5f) / s * 2 - 1, 1 - (float(y) + 0.5f) / s * 2);
      if (d.y >= 0.f) continue;
      const glm::vec3 p = camera.eye + (-camera.eye.y / d.y) * d;
      if (std::fabs(p.x) > 1.f || std::fabs(p.z) > 1.f) continue;  // beside the floor
      // Clipped away (in front of the near plane), or at its edge, where pixel centres straddle it.
      if (glm::dot(p - camera.eye, forward) < 1.05f * camera.near_plane) continue;
      const glm::vec2 uv((p.x + 1) / 2, (1 - p.z) / 2);
      // Away from the wrap: coordinates repeat, so the coarse levels blend the ramp's two ends.
      if (uv.x < 0.15f || uv.x > 0.85f || uv.y < 0.15f || uv.y > 0.85f) continue;
      ++compared;
      const glm::vec3 c = frame.image.at(x, y);
      wrong += std::fabs(c.x - uv.x) > kPerspectiveTolerance || std::fabs(c.y - uv.y) > kPerspectiveTolerance;
    }
  return wrong;
}

TEST_CASE("textured raster: texture coordinates are perspective-correct (against a ray cast per pixel)") {
  const Mesh m = TexturedFloor(Ramp(64));
  Camera camera;
  camera.eye = {0.f, 0.6f, 2.2f}, camera.target = {0.f, 0.f, 0.f}, camera.fov_deg = 60.f;
  camera.near_plane = 0.1f, camera.far_plane = 10.f;
  const int size = 64;
  int compared = 0;
  CHECK(WrongTexturePixels(DrawFloor(m, camera, size), camera, size, compared) == 0);
  CHECK(compared > 300);
}

TEST_CASE("textured raster: triangles cut by the near plane keep their texture coordinates") {
  // The eye stands low over the floor looking along it: the floor's triangles reach behind the
  // near plane, so every drawn pixel comes from a clipped polygon.
  const Mesh m = TexturedFloor(Ramp(64));
  Camera camera;
  camera.eye = {0.f, 0.3f, 0.6f}, camera.target = {0.f, 0.f, -1.f}, camera.fov_deg = 60.f;
  camera.near_plane = 0.6f, camera.far_plane = 10.f;
  const int size = 64;
  int compared = 0;
  CHECK(WrongTexturePixels(DrawFloor(m, camera, size), camera, size, compared) == 0);
  CHECK(compared > 300);
}

TEST_CASE("textured raster: a distant fine checker is filtered to its mean (mip levels), not aliased") {
  // 256 x 256 texels of one-texel squares, about 7 texels to a pixel.
  const Mesh m = TexturedFloor(Checker(256, 1, glm::vec3(1.f), glm::vec3(0.f)));
  Camera camera;
  camera.eye = {0.f, 20.f, 0.01f}, camera.target = {0.f, 0.f, 0.f}, camera.fov_deg = 10.f;
  camera.near_plane = 1.f, camera.far_plane = 100.f;
  const RasterImage frame = DrawFloor(m, camera, 64);
  int covered = 0, off = 0;
  for (int y = 22; y < 42; ++y)
    for (int x = 22; x < 42; ++x) {
      ++covered;
      off += std::fabs(frame.image.at(x, y).x - 0.5f) > 0.05f;
    }
  CHECK(covered == 400);
  CHECK(off == 0);
}

TEST_CASE("textured transport: the bounce takes the albedo from the texture at the hit point") {
  // The floor-and-wall scene, once with a red Kd wall and once with a white Kd wall textured red
  // (and every vertex albedo set to grey, so only the texture can make the floor's bounce red).
  const std::string dir = test::ScratchDir("textured_bounce");
  const Mesh plain = LoadObj(test::WriteFloorAndWall(dir, glm::vec3(0.9f), glm::vec3(1.f, 0.f, 0.f))).mesh;
  Mesh textured = plain;
  const auto red = std::make_shared<const Texture>(Texture::Solid(glm::vec3(1.f, 0.f, 0.f), "red"));
  const auto white = std::make_shared<const Texture>(Texture::Solid(glm::vec3(0.9f), "floor"));
  textured.textures = {white, red};
  textured.corner_uv.assign(3 * textured.triangle_count(), glm::vec2(0.5f));
  textured.triangle_texture.assign(textured.triangle_count(), 0);
  for (std::size_t t = test::FloorTriangles(); t < textured.triangle_count(); ++t) textured.triangle_texture[t] = 1;
  textured.albedo.assign(textured.vertex_count(), glm::vec3(0.5f));
  TransportOptions o;
  o.mode = TransportMode::kInterreflection;
  o.lmax = 2, o.samples = 256, o.bounces = 2;
  const Transport a = ComputeTransport(plain, o, nullptr), b = ComputeTransport(textured, o, nullptr);
  REQUIRE(a.channels == 3);
  REQUIRE(b.channels == 3);
  // Floor vertices (their albedo stays outside T): the same bounce light, channel by channel.
  double largest = 0.0, red_bounce = 0.0;
  for (std::size_t v = 0; v < plain.vertex_count(); ++v) {
    if (plain.positions[v].y != 0.f) continue;
    for (int c = 0; c < 3; ++c) largest = std::max(largest, double(std::fabs(a.at(v, c)[0] - b.at(v, c)[0])));
    red_bounce += b.at(v, 0)[0] - b.at(v, 1)[0];
  }
  CHECK(largest < 1e-5);     // the same albedos in float: sums in another order at most
  CHECK(red_bounce > 0.01);  // and the wall's red does reach the floor
}

TEST_CASE("textured transport: the cache key changes with the texels and the texture coordinates") {
  Mesh m = TexturedFloor(Checker(8, 1, glm::vec3(1.f), glm::vec3(0.f)));
  TransportOptions o;
  const std::uint64_t key = TransportKey(m, o);
  Mesh other_texels = m;
  other_texels.textures = {Checker(8, 1, glm::vec3(1.f), glm::vec3(0.25f))};
  CHECK(TransportKey(other_texels, o) != key);
  Mesh other_uv = m;
  other_uv.corner_uv[0].x += 0.125f;
  CHECK(TransportKey(other_uv, o) != key);
  CHECK(TransportKey(m, o) == key);
}

namespace {

// A checker-textured sphere (uv from longitude and latitude, the seam's triangles unwrapped) on a
// checker-textured floor, under the sky, shadowed: a procedural golden that needs no file.
Mesh CheckerSphereOnFloor() {
  Mesh sphere = MakeSphere(24, 1.0f, glm::vec3(0.f, 1.f, 0.f));
  const float pi = static_cast<float>(kPi);
  for (const auto& t : sphere.triangles) {
    glm::vec2 uv[3];
    for (int c = 0; c < 3; ++c) {
      const glm::vec3 d = sphere.positions[t[c]] - glm::vec3(0.f, 1.f, 0.f);
      uv[c] = glm::vec2(0.5f + std::atan2(d.x, d.z) / (2 * pi), std::acos(std::clamp(d.y, -1.f, 1.f)) / pi);
    }
    for (int c = 0; c < 3; ++c)
      if (std::max({uv[0].x, uv[1].x, uv[2].x}) - uv[c].x > 0.5f) uv[c].x += 1.f;  // across the seam
    for (const glm::vec2& c : uv) sphere.corner_uv.push_back(c);
  }
  sphere.triangle_texture.assign(sphere.triangle_count(), 0);
  sphere.textures = {Checker(64, 8, glm::vec3(0.8f, 0.2f, 0.1f), glm::vec3(0.9f))};
  Mesh floor = MakePlane(5.0f, 8);
  for (const auto& t : floor.triangles)
    for (std::uint32_t v : t) floor.corner_uv.emplace_back(floor.positions[v].x / 5.f, floor.positions[v].z / 5.f);
  floor.triangle_texture.assign(floor.triangle_count(), 0);
  floor.textures = {Checker(32, 4, glm::vec3(0.1f, 0.3f, 0.7f), glm::vec3(0.7f))};
  AppendMesh(sphere, floor);
  SetVertexAlbedoFromTextures(sphere);
  return sphere;
}

Image8 DrawScene(const Mesh& mesh, const Environment& env, const RenderOptions& o, TransportMode mode, int samples) {
  TransportOptions t;
  t.mode = mode;
  t.samples = samples;
  const Transport transport = ComputeTransport(mesh, t, nullptr);
  const ShRgb light = ProjectLight(env, 2);
  Rasterizer r;
  return DrawFrame(r, mesh, *MakeShFrameLight(transport, light, o.axis), env, ChooseCamera(mesh, o), o, 0.0, *o.exposure)
      .image;
}

}  // namespace

TEST_CASE("golden frame: a checker-textured sphere on a checker-textured floor under the sky") {
  SkyParams sky;
  sky.sun = 6.0;
  const auto env = MakeSky(sky);
  test::CheckGolden("textured_checker_sphere", DrawScene(CheckerSphereOnFloor(), *env, test::GoldenFrame(),
                                                          TransportMode::kShadowed, 128));
}

TEST_CASE("golden frame: textured mary (the course's texture) under Grace Cathedral" * test::NeedsSharedData()) {
  const std::string data = *test::SharedData();
  const Mesh mary = LoadObj(data + "/games202/mary/mary.obj", data + "/games202/mary/MC003_Kozakura_Mari.png").mesh;
  REQUIRE(mary.textured());
  const auto env = LoadEnvironment(data + "/games202/cubemap/GraceCathedral", CubeLayout::kStandard);
  RenderOptions o = test::GoldenFrame();
  o.width = 72, o.height = 96;
  o.env_background = false;
  o.eye = glm::dvec3(0, 8, 22) * 0.45, o.target = glm::dvec3(0, 1.7, 0), o.fov = 30.0;
  test::CheckGolden("textured_mary_gracecathedral", DrawScene(mary, *env, o, TransportMode::kShadowed, 64));
}

TEST_SUITE_END();
