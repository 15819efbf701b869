// The albedo a bounce ray reads at its hit on a textured triangle (geometry/mesh_texture.h: the
// texture at the hit's interpolated texture coordinates), used by the transport's bounces
// (HitAlbedo) and by `prt reference` (SurfaceAlbedo, unfiltered). The wall of the scene below has
// texture coordinates that are an affine function of position, UvOf(p), and a texture whose texels
// are a linear function of (u, v), RampColor(uv); bilinear sampling and 2 x 2 mip means keep a
// linear function linear, so the albedo at a point p of the wall is RampColor(UvOf(p)), computed
// here from the point itself and never through barycentric weights. Checked against that:
//  - rays aimed at known points of the wall, near each triangle's corners, where a permutation of
//    the barycentric weights lands far from the point;
//  - the whole bounce: the same wall untextured, with the ramp as vertex albedo (which barycentric
//    interpolation, a separate code path, reproduces exactly on a planar affine ramp), must give
//    the floor the same bounce light, in the transport and in the reference.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "env/procedural.h"
#include "geometry/bvh.h"
#include "geometry/mesh_texture.h"
#include "geometry/procedural.h"
#include "precompute/hit_light.h"
#include "precompute/reference.h"
#include "precompute/transport.h"
#include "texture/texture.h"

using namespace prt;

TEST_SUITE_BEGIN("texture");

namespace {

// Float barycentrics, texture coordinates and bilinear weights over a 64-texel ramp: measured
// 1.2e-7 at worst; a wrong texel is off by 0.09 or more at the points aimed at.
constexpr float kAlbedoTolerance = 1e-4f;
// Textured against vertex-albedo bounce light: the same rays, albedos that agree to float
// rounding, summed in another order: measured 7e-9 (transport) and 4e-9 (reference); hits that
// read the texture at u and v swapped are off by 1e-2 and 3.5e-2.
constexpr double kSameBounceTolerance = 1e-5;
// Where a ray aimed at a point of the wall meets it: float ray-triangle arithmetic on coordinates
// of size 1, a few 1e-7; far below the 0.3 units that would make it another point.
constexpr float kHitPointTolerance = 1e-5f;
// The floor's bounce light differs per channel (the ramp is coloured): measured 0.019 at most
// in band 0 between red and green; a bounce that lost the texture's colour would show about 0.
constexpr double kColouredBounce = 1e-3;
// The ramp's texels.
constexpr int kRampSize = 64;

// The wall: the plane x = -1 facing +x, y in [0, 1.5], z in [-1, 1], as two triangles.
constexpr float kWallX = -1.f, kWallHeight = 1.5f;

/// The wall's texture coordinates at its point p: u along z, v up.
glm::vec2 UvOf(const glm::vec3& p) { return {0.25f + 0.25f * (p.z + 1.f), 0.25f + 0.3f * p.y}; }

/// The ramp's albedo at (u, v): red u, green v, blue 1 - (u + v)/2.
glm::vec3 RampColor(const glm::vec2& uv) { return {uv.x, uv.y, 1.f - 0.5f * (uv.x + uv.y)}; }

/// A texture whose texel centres hold RampColor of their own (u, v) (row 0 is v = 1).
std::shared_ptr<const Texture> Ramp() {
  ImageF image(kRampSize, kRampSize);
  for (int y = 0; y < kRampSize; ++y)
    for (int x = 0; x < kRampSize; ++x)
      image.at(x, y) = RampColor({(float(x) + 0.5f) / kRampSize, 1.f - (float(y) + 0.5f) / kRampSize});
  return std::make_shared<const Texture>(std::move(image), "ramp");
}

/// A 2 x 2 floor (y = 0, albedo 0.8, 6 x 6 quads) and the wall at its x = -1 edge, which is all
/// the floor sees besides the sky. Textured: the floor a 1 x 1 texture of its albedo, the wall
/// the ramp at UvOf. Untextured: the ramp as the wall's vertex albedo. Both keep the same vertex
/// albedo, so they differ only in where a hit's albedo comes from.
Mesh FloorAndWall(bool textured) {
  Mesh m = MakePlane(2.f, 6, 0.f, glm::vec3(0.8f));
  const std::size_t floor_triangles = m.triangle_count();
  const auto b = static_cast<std::uint32_t>(m.vertex_count());
  for (const glm::vec3& p : {glm::vec3(kWallX, 0, -1), glm::vec3(kWallX, 0, 1), glm::vec3(kWallX, kWallHeight, 1),
                             glm::vec3(kWallX, kWallHeight, -1)}) {
    m.positions.push_back(p);
    m.normals.emplace_back(1, 0, 0);
    m.albedo.push_back(RampColor(UvOf(p)));
  }
  m.triangles.push_back({b, b + 2, b + 1});  // counter-clockwise seen from +x
  m.triangles.push_back({b, b + 3, b + 2});
  if (textured) {
    m.textures = {std::make_shared<const Texture>(Texture::Solid(glm::vec3(0.8f), "floor")), Ramp()};
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const bool wall = t >= floor_triangles;
      m.triangle_texture.push_back(wall ? 1 : 0);
      for (std::uint32_t v : m.triangles[t]) m.corner_uv.push_back(wall ? UvOf(m.positions[v]) : glm::vec2(0.5f));
    }
  }
  return m;
}

bool Near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
  return std::abs(a.x - b.x) < tolerance && std::abs(a.y - b.y) < tolerance && std::abs(a.z - b.z) < tolerance;
}

}  // namespace

TEST_CASE("hit albedo: a ray's hit on a textured wall reads the texel of the hit point's own coordinates") {
  const Mesh mesh = FloorAndWall(true);
  const std::size_t floor_triangles = MakePlane(2.f, 6).triangle_count();
  const Bvh bvh = Bvh::Build(mesh);
  // Points of the wall (y, z), four in each triangle, near its corners (barycentrics such as
  // (0.1, 0.8, 0.1)) and away from u = v: the weights rotated over the corners, or u and v
  // swapped, move each of them 0.3 to 1.75 units, and its albedo by 0.09 to 0.35.
  const glm::vec2 targets[] = {{1.2f, 0.8f},   {0.15f, 0.8f}, {0.45f, -0.2f}, {0.15f, 0.6f},
                               {1.35f, -0.8f}, {1.35f, 0.6f}, {0.6f, -0.4f},  {1.275f, -0.5f}};
  std::size_t checked = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 5) {
    const glm::vec3 from = mesh.positions[v];
    if (from.y != 0.f || from.x < -0.5f) continue;  // floor vertices a little away from the wall
    for (const glm::vec2& yz : targets) {
      const glm::vec3 target(kWallX, yz.x, yz.y);
      Ray ray;
      ray.origin = from + glm::vec3(0, 1e-4f, 0);  // just above the floor, which it must not hit
      ray.dir = target - ray.origin;
      ray.tmin = 1e-6f;
      const auto hit = bvh.Intersect(ray);
      REQUIRE(hit);
      REQUIRE(hit->triangle >= floor_triangles);  // the wall
      REQUIRE(Near(ray.origin + hit->t * ray.dir, target, kHitPointTolerance));
      const glm::vec2 uv = UvOf(target);
      const glm::vec3 expected = RampColor(uv);
      INFO("from (" << from.x << ", " << from.z << ") to (y, z) = (" << yz.x << ", " << yz.y << ")");
      const glm::vec2 got_uv = TriangleUv(mesh, hit->triangle, hit->u, hit->v);
      CHECK(std::abs(got_uv.x - uv.x) < kAlbedoTolerance);
      CHECK(std::abs(got_uv.y - uv.y) < kAlbedoTolerance);
      // The reference's lookup (unfiltered) and the transport's (filtered over the ray's patch,
      // 1024 directions: lod 2.6 at most here, levels where the ramp is still exactly linear).
      CHECK(Near(SurfaceAlbedo(mesh, hit->triangle, hit->u, hit->v, 0.f), expected, kAlbedoTolerance));
      CHECK(Near(HitAlbedo(mesh, v, hit->triangle, hit->u, hit->v, 1024), expected, kAlbedoTolerance));
      ++checked;
    }
  }
  CHECK(checked == 56);  // 7 floor vertices, 8 points each
}

TEST_CASE("hit albedo: a ramp-textured wall bounces onto the floor what the same ramp as vertex albedo does") {
  const Mesh textured = FloorAndWall(true), plain = FloorAndWall(false);
  // Transport: the floor's bounce light, channel by channel (albedos outside T: the receiver's
  // own albedo plays no part).
  TransportOptions o;
  o.mode = TransportMode::kInterreflection;
  o.lmax = 2, o.samples = 1024, o.bounces = 1;
  const Transport a = ComputeTransport(plain, o, nullptr), b = ComputeTransport(textured, o, nullptr);
  REQUIRE(a.channels == 3);
  REQUIRE(b.channels == 3);
  double largest = 0.0, coloured = 0.0;
  for (std::size_t v = 0; v < plain.vertex_count(); ++v) {
    if (plain.positions[v].y != 0.f || plain.positions[v].x == kWallX) continue;  // the floor in front of the wall
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < CoeffCount(o.lmax); ++k) largest = std::max(largest, double(std::abs(a.at(v, c)[k] - b.at(v, c)[k])));
    coloured = std::max(coloured, double(std::abs(b.at(v, 0)[0] - b.at(v, 1)[0])));
  }
  CHECK(largest < kSameBounceTolerance);
  CHECK(coloured > kColouredBounce);  // and the ramp's colours do reach the floor
  // The reference (`prt reference`), under a constant sky: the same paths in both, so the same
  // radiance up to the albedo's float rounding.
  const auto env = MakeFurnace(1.0);
  ReferenceOptions r;
  r.mode = TransportMode::kInterreflection;
  r.samples = 64, r.bounces = 1;
  r.table_rows = 16, r.table_cols = 32;
  const Reference ra = ComputeReference(plain, *env, r), rb = ComputeReference(textured, *env, r);
  double worst = 0.0;
  for (std::size_t v = 0; v < plain.vertex_count(); ++v)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(ra.radiance[v][c] - rb.radiance[v][c]));
  CHECK(worst < kSameBounceTolerance);
}

TEST_SUITE_END();
