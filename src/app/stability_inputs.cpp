#include "app/stability_inputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glm/geometric.hpp>

#include "env/equirect.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "io/image_load.h"
#include "precompute/light.h"
#include "precompute/transport.h"

namespace prt {
namespace {

constexpr double kY00 = 0.28209479177387814;  // 1 / (2 sqrt(pi))
constexpr double kPi = 3.14159265358979323846;

std::string F(const char* fmt, double v) {
  char b[64];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

StabilityCase Make(std::string name, std::string checks, double figure, double limit, std::string note) {
  StabilityCase c{std::move(name), std::move(checks), figure, limit, false, false, std::move(note)};
  c.pass = std::isfinite(figure) && figure <= limit;
  return c;
}

/// A box with flat faces (normals exactly on the axes) plus degenerate, sliver and duplicated
/// triangles and a few grazing vertex normals.
Mesh AwkwardMesh() {
  Mesh m = MakeBox(glm::vec3(-1.0f), glm::vec3(1.0f), BoxFacing::kOutward, 4);
  const std::size_t n = m.triangle_count();
  for (std::size_t t = 0; t < n; t += 7) m.triangles.push_back(m.triangles[t]);  // duplicates
  const auto base = static_cast<std::uint32_t>(m.vertex_count());
  // A zero-area triangle (collinear) and a sliver 1e-7 wide, standing on the top face.
  const glm::vec3 pts[6] = {{0.1f, 1.0f, 0.1f}, {0.2f, 1.0f, 0.1f}, {0.3f, 1.0f, 0.1f},
                            {0.1f, 1.0f, 0.3f}, {0.6f, 1.0f, 0.3f}, {0.35f, 1.0f, 0.3f + 1e-7f}};
  for (const auto& p : pts) {
    m.positions.push_back(p);
    m.normals.push_back(glm::vec3(0, 1, 0));
    m.albedo.push_back(glm::vec3(0.8f));
  }
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base + 3, base + 4, base + 5});
  // Grazing normals: a few vertices' normals tilted to 89.9 degrees from their face.
  const float tilt = std::cos(89.9f * float(kPi) / 180.0f);
  for (std::size_t v = 0; v < m.vertex_count(); v += 11) {
    const glm::vec3 n0 = m.normals[v];
    const glm::vec3 side = std::abs(n0.x) < 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    m.normals[v] = glm::normalize(tilt * n0 + std::sqrt(1 - tilt * tilt) * glm::normalize(glm::cross(n0, side)));
  }
  return m;
}

}  // namespace

void ExtremeMeshes(std::vector<StabilityCase>& out) {
  const Mesh m = AwkwardMesh();
  for (TransportMode mode : {TransportMode::kShadowed, TransportMode::kInterreflection}) {
    TransportOptions o;
    o.mode = mode;
    o.lmax = 4;
    o.samples = 512;
    const Transport t = ComputeTransport(m, o, nullptr);
    std::size_t bad = 0;
    double worst_t00 = 0.0;
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      const float* tv = t.at(v, 0);
      for (int k = 0; k < CoeffCount(4); ++k) bad += !std::isfinite(tv[k]);
      worst_t00 = std::max(worst_t00, double(tv[0]) / kY00);
    }
    // Shadowed: T_00 <= Y_00 exactly by construction; interreflection adds bounces, bounded by
    // Y_00 / (1 - albedo) in a furnace.
    const double bound = mode == TransportMode::kShadowed ? 1.0 + 1e-6 : 1.0 / (1.0 - 0.8);
    const double violations = double(bad) + (worst_t00 > bound ? 1.0 : 0.0);
    out.push_back(Make(std::string("extreme_mesh_") + TransportModeName(mode),
                       "box with duplicated, zero-area and sliver triangles, axis and grazing normals: "
                       "non-finite transport values plus bound violations (count)",
                       violations, 0.0, "largest T_00 / Y_00 " + F("%.4g", worst_t00) + " (bound " + F("%.3g", bound) + ")"));
  }
}

void DeepConcavity(std::vector<StabilityCase>& out) {
  // An open well 1 x 1 x 6, seen from inside: a closed inward box without its top face.
  Mesh room = MakeBox(glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 6.0f, 0.5f), BoxFacing::kInward, 6);
  std::vector<std::array<std::uint32_t, 3>> kept;
  for (const auto& tri : room.triangles)
    if (!(room.positions[tri[0]].y == 6.0f && room.positions[tri[1]].y == 6.0f && room.positions[tri[2]].y == 6.0f))
      kept.push_back(tri);
  room.triangles = kept;
  const float albedo = 0.99f;
  SetUniformAlbedo(room, glm::vec3(albedo));
  TransportOptions o;
  o.mode = TransportMode::kInterreflection;
  o.lmax = 2;
  o.samples = 512;
  o.bounces = 64;
  o.bounce_tolerance = 0.0;
  TransportReport r;
  const Transport t = ComputeTransport(room, o, &r);
  // Furnace (constant radiance 1): outgoing radiance = albedo * 2 sqrt(pi) T_00 <= albedo.
  double worst = 0.0, lowest = 1e30;
  for (std::size_t v = 0; v < room.vertex_count(); ++v) {
    const double radiance = albedo * 2.0 * std::sqrt(kPi) * t.at(v, 0)[0];
    worst = std::max(worst, radiance / albedo);
    lowest = std::min(lowest, radiance);
  }
  const double last = r.bounce_share.empty() ? 0.0 : r.bounce_share.back();
  // Monte Carlo noise at 512 directions can lift a vertex a little above the bound.
  out.push_back(Make("deep_well_albedo_0.99_64_bounces",
                     "open well 1x1x6, albedo 0.99, constant light, 64 bounces: largest radiance / albedo (energy "
                     "bound 1, plus 1% for sampling noise)",
                     worst, 1.01,
                     "lowest radiance " + F("%.3g", lowest) + "; bounce 1 added " +
                         F("%.3g", r.bounce_share.empty() ? 0.0 : r.bounce_share.front()) + " of the direct energy, bounce 64 " +
                         F("%.3g", last) + " (geometric decay)"));
}

void BadTexels(std::vector<StabilityCase>& out) {
  ImageF image(64, 32);
  for (auto& p : image.pixels) p = glm::vec3(1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  image.at(3, 3) = glm::vec3(nan, 1, 1);
  image.at(4, 3) = glm::vec3(inf, -inf, 1);
  image.at(5, 3) = glm::vec3(-5.0f);
  image.at(6, 3) = glm::vec3(1e30f);
  const SanitizeCounts fixed = SanitizeRadiance(image);
  const EquirectEnvironment env(std::move(image), "bad texels");
  const ShRgb light = ProjectLight(env, 8);
  double non_finite = 0;
  for (const auto& c : light) non_finite += !std::isfinite(c.x) + !std::isfinite(c.y) + !std::isfinite(c.z);
  out.push_back(Make("bad_texels", "NaN, +-Inf, negative and 1e30 texels through the loaders' sanitiser, then "
                                   "projected to lmax 8: non-finite coefficients (count)",
                     non_finite, 0.0, "sanitised: " + DescribeSanitized(fixed)));
}

}  // namespace prt
