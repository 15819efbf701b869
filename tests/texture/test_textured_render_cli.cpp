// Drawing textured meshes: perspective-correct texture coordinates against ray casting (also on
// triangles the near plane cuts), mip filtering of a distant checker, the checker under the
// furnace reproduced exactly through the command line, the bounce's albedo read from the texture,
// the cache key, and goldens.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "core/atomic_file.h"
#include "core/constants.h"
#include "env/load_environment.h"
#include "env/procedural.h"
#include "geometry/mesh_ops.h"
#include "geometry/mesh_texture.h"
#include "geometry/procedural.h"
#include "io/obj_loader.h"
#include "io/png_io.h"
#include "precompute/light.h"
#include "precompute/transport.h"
#include "precompute_io/transport_cache.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"
#include "render/render_frames.h"
#include "sh/axis_rotation.h"
#include "sh_basis/frame_light.h"
#include "tests/golden.h"
#include "tests/test_process.h"

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

TEST_CASE("textured render: a checker under the furnace comes out as its own texels (albedo x 1), in SH and in wavelets") {
  const std::string dir = test::ScratchDir("textured_furnace");
  // Four quadrants of distinct colours (a flipped v, swapped channels or a lost texture show).
  const std::uint8_t colours[4][3] = {{200, 30, 30}, {30, 200, 30}, {30, 30, 200}, {240, 240, 240}};
  Image8 texture(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) texture.rgb[3 * (y * 16 + x) + c] = colours[(y / 8) * 2 + x / 8][c];
  WritePng(dir + "/quadrants.png", texture);
  WriteFileAtomic(dir + "/square.obj",
                  "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                  "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
  // In either basis: the wavelets' white furnace is exact too.
  for (const std::string basis : {"sh", "wavelet --cube-size 8"}) {
    CAPTURE(basis);
    const test::RunResult r = test::RunPrt(
        "render --mesh " + test::Q(dir + "/square.obj") + " --texture " + test::Q(dir + "/quadrants.png") +
        " --env furnace --transport unshadowed --exposure 0 --tonemap srgb --ssaa 1 --frames 1 --size 64x64"
        " --eye 0,0,3 --target 0,0,0 --fov 30 --basis " + basis + " --out " + test::Q(dir + "/out"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
    // Quadrant centres (x, y = +-0.5) are 20 pixels from the image centre; a 5 x 5 block around
    // each lies well inside its quadrant, where the texture is one colour.
    const int centres[4][2] = {{12, 12}, {52, 12}, {12, 52}, {52, 52}};
    for (int q = 0; q < 4; ++q)
      for (int y = centres[q][1] - 2; y <= centres[q][1] + 2; ++y)
        for (int x = centres[q][0] - 2; x <= centres[q][0] + 2; ++x)
          CHECK(test::PixelAt(frame, x, y) == glm::ivec3(colours[q][0], colours[q][1], colours[q][2]));
  }
}

