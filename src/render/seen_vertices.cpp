#include "render/seen_vertices.h"

#include <algorithm>
#include <cmath>

#include "geometry/mesh_ops.h"
#include "raster/rasterizer.h"

namespace prt {
namespace {

/// Triangle numbers as colours: the low and high 12 bits in red and green, each exact in float
/// and interpolated from three equal corner values, so rounding recovers it (up to 2^24
/// triangles). The background is -1.
constexpr int kIdBits = 12;

/// An orbit of more frames is drawn at this many of them (1 degree apart or less for a full
/// turn), so the pass stays a fraction of the render it serves.
constexpr int kMaxOrbitViews = 360;

}  // namespace

std::vector<std::uint8_t> SeenVertices(const Mesh& mesh, const Camera& camera, const RenderOptions& o) {
  // Every triangle with corners of its own, coloured by its number.
  const std::size_t nt = mesh.triangle_count();
  std::vector<glm::vec3> positions(3 * nt), colors(3 * nt);
  std::vector<std::array<std::uint32_t, 3>> triangles(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const glm::vec3 id(float(t & ((1u << kIdBits) - 1)), float(t >> kIdBits), 0.f);
    for (int c = 0; c < 3; ++c) {
      positions[3 * t + c] = mesh.positions[mesh.triangles[t][c]];
      colors[3 * t + c] = id;
    }
    triangles[t] = {std::uint32_t(3 * t), std::uint32_t(3 * t + 1), std::uint32_t(3 * t + 2)};
  }
  // The frame's samples one by one: its size times its supersampling, within the target's limit.
  int k = o.ssaa;
  while (k > 1 && (o.width * k > kMaxTargetSide || o.height * k > kMaxTargetSide)) --k;
  RasterOptions ro;
  ro.background.color = glm::vec3(-1.f);

  std::vector<std::uint8_t> seen(mesh.vertex_count(), 0);
  std::vector<std::uint8_t> shown(nt, 0);
  const Bounds3 bounds = MeshBounds(mesh);
  Rasterizer rasterizer;
  // The light's turn moves nothing; an orbit is drawn at every frame's camera, or at
  // kMaxOrbitViews of them spread evenly when there are more.
  const int views = o.orbit != 0.0 ? std::min(o.frames, kMaxOrbitViews) : 1;
  for (int j = 0; j < views; ++j) {
    const long long i = static_cast<long long>(j) * o.frames / views;
    const Camera view = Orbit(camera, o.orbit * double(i) / double(o.frames), bounds.lo, bounds.hi);
    const RasterImage& frame = rasterizer.Draw(view, o.width * k, o.height * k, positions, triangles, colors, ro);
    for (const glm::vec3& p : frame.image.pixels) {
      if (p.x < 0.f) continue;
      const std::size_t t = std::size_t(std::lround(p.x)) | (std::size_t(std::lround(p.y)) << kIdBits);
      if (t < nt) shown[t] = 1;
    }
  }
  for (std::size_t t = 0; t < nt; ++t)
    if (shown[t])
      for (std::uint32_t v : mesh.triangles[t]) seen[v] = 1;
  return seen;
}

}  // namespace prt
