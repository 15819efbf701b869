#include "geometry/weld.h"

#include <unordered_map>

#include <glm/geometric.hpp>
#include <nanoflann.hpp>

#include "geometry/mesh_ops.h"

namespace prt {
namespace {

// The adaptor nanoflann needs to read points out of a vector of vec3.
struct PointCloud {
  std::vector<glm::vec3> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  float kdtree_get_pt(std::size_t i, std::size_t dim) const { return points[i][static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointCloud>, PointCloud, 3>;

bool HasNormal(const glm::vec3& n) { return n.x != 0.0f || n.y != 0.0f || n.z != 0.0f; }

}  // namespace

WeldedMesh WeldCorners(const CornerSoup& soup, float position_tolerance, MeshReport& report) {
  const std::size_t n = soup.positions.size();
  constexpr std::uint32_t kNone = ~0u;

  // k-d tree over the corners without a normal (local index -> corner index in `bare`).
  PointCloud cloud;
  std::vector<std::uint32_t> bare;
  for (std::size_t i = 0; i < n; ++i)
    if (!HasNormal(soup.normals[i])) bare.push_back(static_cast<std::uint32_t>(i)), cloud.points.push_back(soup.positions[i]);
  KdTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  if (!bare.empty()) tree.buildIndex();

  WeldedMesh out;
  Mesh& mesh = out.mesh;
  std::vector<glm::vec3> normal_sum, albedo_sum;
  std::vector<int> corner_count;
  std::vector<std::uint32_t> vertex_of(n, kNone);
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_id;
  std::vector<std::pair<std::uint32_t, float>> matches;
  const float radius_sq = position_tolerance * position_tolerance;  // L2_Simple works in squares
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t vertex = kNone;
    if (HasNormal(soup.normals[i])) {
      // Same file (position, normal) pair: same vertex.
      const auto it = vertex_of_id.find(soup.ids[i]);
      if (it != vertex_of_id.end()) vertex = it->second;
    } else {
      // The earliest normal-less corner within the tolerance that already has a vertex.
      const float query[3] = {soup.positions[i].x, soup.positions[i].y, soup.positions[i].z};
      matches.clear();
      tree.radiusSearch(query, radius_sq, matches, nanoflann::SearchParams(32, 0.0f, false));
      std::uint32_t earliest = kNone;
      for (const auto& match : matches) {
        const std::uint32_t j = bare[match.first];
        if (j < i && j < earliest) earliest = j;
      }
      if (earliest != kNone) vertex = vertex_of[earliest];
    }
    if (vertex == kNone) {
      vertex = static_cast<std::uint32_t>(mesh.positions.size());
      mesh.positions.push_back(soup.positions[i]);
      normal_sum.emplace_back(0.0f);
      albedo_sum.emplace_back(0.0f);
      corner_count.push_back(0);
      if (HasNormal(soup.normals[i])) vertex_of_id.emplace(soup.ids[i], vertex);
    } else {
      ++report.welded_away;
    }
    vertex_of[i] = vertex;
    normal_sum[vertex] += soup.normals[i];
    albedo_sum[vertex] += soup.albedo[i];
    ++corner_count[vertex];
  }

  // Triangles; a zero-area one, or one with a corner pair welded together, is dropped (but kept
  // in file_triangles, which mirrors the file face for face).
  for (std::size_t t = 0; t + 2 < n; t += 3) {
    const std::array<std::uint32_t, 3> tri = {vertex_of[t], vertex_of[t + 1], vertex_of[t + 2]};
    mesh.file_triangles.push_back(tri);
    const glm::dvec3 p0(soup.positions[t]), p1(soup.positions[t + 1]), p2(soup.positions[t + 2]);
    const bool zero_area = glm::length(glm::cross(p1 - p0, p2 - p0)) == 0.0;
    if (zero_area || tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      ++report.dropped_degenerate;
      continue;
    }
    mesh.triangles.push_back(tri);
    if (!soup.texture.empty()) {
      mesh.triangle_texture.push_back(soup.texture[t / 3]);
      for (std::size_t c = 0; c < 3; ++c) mesh.corner_uv.push_back(soup.uv[t + c]);
    }
  }

  // Normals from the file where given, smooth ones elsewhere; mean albedo.
  const std::size_t nv = mesh.positions.size();
  mesh.normals.resize(nv);
  mesh.albedo.resize(nv);
  out.normal_from_file.assign(nv, 1);
  std::vector<glm::vec3> smooth;
  for (std::size_t v = 0; v < nv; ++v) {
    mesh.albedo[v] = albedo_sum[v] / static_cast<float>(corner_count[v]);
    const float len = glm::length(normal_sum[v]);
    if (len > 0.0f) {
      mesh.normals[v] = normal_sum[v] / len;
      continue;
    }
    if (smooth.empty()) smooth = SmoothNormals(mesh);
    mesh.normals[v] = smooth[v];
    out.normal_from_file[v] = 0;
    ++report.recomputed_normals;
  }
  return out;
}

}  // namespace prt
