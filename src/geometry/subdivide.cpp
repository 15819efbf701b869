#include "geometry/subdivide.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "geometry/position_ids.h"

namespace prt {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The bound of the header is proved in exact arithmetic, but midpoints are rounded to float, so
// every edge length is off by up to a couple of float ulps of the coordinates. Decisions the
// estimate must be sure of keep this margin from max_edge: 2^-20 of the largest |coordinate|,
// about eight ulps.
constexpr double kMarginOfScale = 1.0 / 1048576.0;  // 2^-20

// Squared length of the edge a b, in double; symmetric in a and b bit for bit (a - b is exactly
// -(b - a)), so both triangles on an edge take the same decision.
double LengthSq(const glm::vec3& a, const glm::vec3& b) {
  const glm::dvec3 d = glm::dvec3(a) - glm::dvec3(b);
  return glm::dot(d, d);
}

// Thresholds on squared edge lengths for max_edge e and the rounding margin m.
struct Limits {
  double long_sq = 0.0;     // e^2: longer edges are split
  double done_sq = 0.0;     // (e - m)^2: below it an edge stays short after rounding
  double certain_sq = 0.0;  // (e + m)^2: above it an edge is long after rounding too
  bool resolvable = false;  // e > FinestEdge(m): done_sq above the bound's fixed point 2 e^2 / 3
};

double RoundingMargin(const Mesh& mesh) {
  double scale = 0.0;
  for (const glm::vec3& p : mesh.positions)
    scale = std::max(scale, static_cast<double>(std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z)))));
  return kMarginOfScale * scale;
}

// The smallest max_edge that the rounding margin m leaves resolvable: (e - m)^2 > 2 e^2 / 3.
double FinestEdge(double m) { return m / (1.0 - std::sqrt(2.0 / 3.0)); }

Limits MakeLimits(const Mesh& mesh, float max_edge) {
  const double e = max_edge, m = RoundingMargin(mesh);
  Limits limits;
  limits.long_sq = e * e;
  limits.done_sq = e > m ? (e - m) * (e - m) : 0.0;
  limits.certain_sq = (e + m) * (e + m);
  limits.resolvable = std::isinf(e) || e > FinestEdge(m);
  return limits;
}

// Passes a triangle whose longest edge has squared length `longest_sq` can need at most:
// iterate the bound L'^2 <= L^2 / 4 + e^2 / 2 of the header until it is surely short.
int PassBound(double longest_sq, const Limits& limits) {
  int passes = 0;
  for (double x = longest_sq; x > limits.done_sq; x = 0.25 * x + 0.5 * limits.long_sq) ++passes;
  return passes;
}

// log4 of the bound on a triangle's descendants. While all three edges are surely long, each
// pass makes four half-size copies (k = 3), and the count is exact; from the first pass that
// may split fewer edges on, 4^P with P from PassBound.
int DescendantsLog4(const Mesh& mesh, const Triangle& t, const Limits& limits) {
  const double a = LengthSq(mesh.positions[t[0]], mesh.positions[t[1]]);
  const double b = LengthSq(mesh.positions[t[1]], mesh.positions[t[2]]);
  const double c = LengthSq(mesh.positions[t[2]], mesh.positions[t[0]]);
  double shortest = std::min(a, std::min(b, c)), longest = std::max(a, std::max(b, c));
  int halvings = 0;
  for (; shortest > limits.certain_sq; shortest *= 0.25, longest *= 0.25) ++halvings;
  return halvings + PassBound(longest, limits);
}

// Edge midpoints of one pass, one vertex per vertex pair: appended to the mesh on first use.
class Midpoints {
 public:
  explicit Midpoints(Mesh& mesh) : mesh_(mesh) {}
  /// The midpoint of a and b if this pass made it, else kNoMidpoint (nothing is added).
  static constexpr std::uint32_t kNoMidpoint = 0xffffffffu;
  std::uint32_t Find(std::uint32_t a, std::uint32_t b) const {
    const auto it = cache_.find(PositionEdgeKey(a, b));
    return it == cache_.end() ? kNoMidpoint : it->second;
  }
  std::uint32_t Of(std::uint32_t a, std::uint32_t b) {
    const auto [it, inserted] = cache_.emplace(PositionEdgeKey(a, b), 0u);  // packs the vertex pair
    std::uint32_t& id = it->second;
    if (!inserted) return id;
    const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
    // a + b rounds the same in either order, so coincident edges get coincident midpoints.
    const glm::vec3 position = 0.5f * (mesh_.positions[lo] + mesh_.positions[hi]);
    const glm::vec3 sum = mesh_.normals[lo] + mesh_.normals[hi];
    const float length = glm::length(sum);
    const glm::vec3 normal = length > 0.0f ? sum / length : mesh_.normals[lo];  // opposite normals
    const glm::vec3 albedo = 0.5f * (mesh_.albedo[lo] + mesh_.albedo[hi]);
    id = static_cast<std::uint32_t>(mesh_.positions.size());
    mesh_.positions.push_back(position);
    mesh_.normals.push_back(normal);
    mesh_.albedo.push_back(albedo);
    return id;
  }

 private:
  Mesh& mesh_;
  std::unordered_map<std::uint64_t, std::uint32_t> cache_;
};

// Appends the texture coordinates and texture of children out[first_child ...] of triangle
// `parent`: each child corner is a parent corner or the midpoint of a parent edge.
void AddChildCoordinates(const Mesh& mesh, std::size_t parent, const Midpoints& midpoints,
                         const std::vector<Triangle>& out, std::size_t first_child, std::vector<glm::vec2>& out_uv,
                         std::vector<std::uint32_t>& out_texture) {
  const Triangle& v = mesh.triangles[parent];
  const glm::vec2* uv = &mesh.corner_uv[3 * parent];
  const auto coordinate = [&](std::uint32_t id) {
    for (int i = 0; i < 3; ++i)
      if (id == v[i]) return uv[i];
    for (int i = 0; i < 3; ++i)
      if (id == midpoints.Find(v[i], v[(i + 1) % 3])) return 0.5f * (uv[i] + uv[(i + 1) % 3]);
    return uv[0];  // unreachable: children are made of corners and edge midpoints
  };
  for (std::size_t child = first_child; child < out.size(); ++child) {
    for (std::uint32_t id : out[child]) out_uv.push_back(coordinate(id));
    out_texture.push_back(mesh.triangle_texture[parent]);
  }
}

}  // namespace

double MinimumMaxEdge(const Mesh& mesh) { return FinestEdge(RoundingMargin(mesh)); }

std::size_t EstimateSplitTriangles(const Mesh& mesh, float max_edge) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  const Limits limits = MakeLimits(mesh, max_edge);
  if (!(max_edge > 0.0f) || !limits.resolvable) return kMax;
  std::size_t total = 0;
  for (const Triangle& t : mesh.triangles) {
    const int log4 = DescendantsLog4(mesh, t, limits);
    if (2 * log4 >= std::numeric_limits<std::size_t>::digits) return kMax;  // 4^32 overflows
    const std::size_t descendants = std::size_t{1} << (2 * log4);
    if (descendants > kMax - total) return kMax;
    total += descendants;
  }
  return total;
}

SplitReport SplitLongEdges(Mesh& mesh, float max_edge) {
  const Limits limits = MakeLimits(mesh, max_edge);
  if (!(max_edge > 0.0f))
    throw Error("split long edges: max_edge must be positive (got " + std::to_string(max_edge) + ")");
  if (!limits.resolvable)
    throw Error("split long edges: max_edge " + std::to_string(max_edge) +
                " is finer than float positions resolve at the mesh's coordinates (expected a larger max_edge)");
  SplitReport report;
  report.triangles_before = mesh.triangle_count();
  const std::size_t vertices_before = mesh.vertex_count();
  // The bound of the header caps the passes, so rounding can never make the loop endless.
  int max_passes = 0;
  for (const Triangle& t : mesh.triangles) max_passes = std::max(max_passes, DescendantsLog4(mesh, t, limits));

  for (int pass = 0; pass <= max_passes; ++pass) {
    Midpoints midpoints(mesh);
    std::vector<Triangle> out;
    out.reserve(mesh.triangles.size());
    // A textured mesh's children take their corners' coordinates from the parent's: a corner at
    // a midpoint gets the mean of the edge's two corner coordinates (per triangle, so a seam
    // stays a seam).
    const bool textured = mesh.textured();
    std::vector<glm::vec2> out_uv;
    std::vector<std::uint32_t> out_texture;
    bool split = false;
    for (std::size_t parent = 0; parent < mesh.triangles.size(); ++parent) {
      const Triangle& v = mesh.triangles[parent];
      const std::size_t first_child = out.size();
      // Edge i runs from v[i] to v[i + 1].
      bool long_edge[3];
      int k = 0;
      for (int i = 0; i < 3; ++i) {
        long_edge[i] = LengthSq(mesh.positions[v[i]], mesh.positions[v[(i + 1) % 3]]) > limits.long_sq;
        k += long_edge[i] ? 1 : 0;
      }
      if (k == 0) {
        out.push_back(v);
        if (textured) AddChildCoordinates(mesh, parent, midpoints, out, first_child, out_uv, out_texture);
        continue;
      }
      split = true;
      if (k == 1) {
        // Join the long edge's midpoint to the opposite corner.
        const int i = long_edge[0] ? 0 : long_edge[1] ? 1 : 2;
        const std::uint32_t a = v[i], b = v[(i + 1) % 3], c = v[(i + 2) % 3], m = midpoints.Of(a, b);
        out.push_back({a, m, c});
        out.push_back({m, b, c});
      } else if (k == 2) {
        // Short edge c -> a; cut off corner b, then split the quadrilateral a p q c.
        const int s = !long_edge[0] ? 0 : !long_edge[1] ? 1 : 2;
        const std::uint32_t c = v[s], a = v[(s + 1) % 3], b = v[(s + 2) % 3];
        const std::uint32_t p = midpoints.Of(a, b), q = midpoints.Of(b, c);
        out.push_back({p, b, q});
        if (LengthSq(mesh.positions[a], mesh.positions[q]) <= LengthSq(mesh.positions[p], mesh.positions[c])) {
          out.push_back({a, p, q});
          out.push_back({a, q, c});
        } else {
          out.push_back({a, p, c});
          out.push_back({p, q, c});
        }
      } else {
        // Four half-size copies.
        const std::uint32_t p = midpoints.Of(v[0], v[1]), q = midpoints.Of(v[1], v[2]), r = midpoints.Of(v[2], v[0]);
        out.push_back({v[0], p, r});
        out.push_back({p, v[1], q});
        out.push_back({r, q, v[2]});
        out.push_back({p, q, r});
      }
      if (textured) AddChildCoordinates(mesh, parent, midpoints, out, first_child, out_uv, out_texture);
    }
    if (!split) break;
    mesh.triangles.swap(out);
    if (textured) mesh.corner_uv.swap(out_uv), mesh.triangle_texture.swap(out_texture);
    ++report.passes;
  }

  if (report.passes > 0) mesh.file_triangles.clear();
  report.triangles_after = mesh.triangle_count();
  report.vertices_added = mesh.vertex_count() - vertices_before;
  return report;
}

}  // namespace prt
