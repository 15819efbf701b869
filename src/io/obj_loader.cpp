#include "io/obj_loader.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "core/error.h"
#include "geometry/mesh_ops.h"
#include "geometry/weld.h"

namespace prt {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& problem, const std::string& expected) {
  throw Error(path + ": " + problem + " (" + expected + ")");
}

// tinyobjloader reads "nan" or "inf" as 0 without a word, so coordinates are checked on the
// text first: every number of a `v` or `vn` line must be finite.
void CheckFiniteCoordinates(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.rfind("v ", 0) != 0 && line.rfind("vn ", 0) != 0) continue;
    std::istringstream tokens(line);
    std::string token;
    tokens >> token;  // "v" or "vn"
    while (tokens >> token) {
      char* end = nullptr;
      const double x = std::strtod(token.c_str(), &end);
      if (end != token.c_str() && !std::isfinite(x))
        Fail(path, "line " + std::to_string(number) + ": coordinate '" + token + "' is not finite",
             "finite numbers");
    }
  }
}

// Trims tinyobjloader's multi-line messages into one line each.
std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

}  // namespace

LoadedMesh LoadObj(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) Fail(path, "no such file", "an OBJ mesh");
  if (fs::is_directory(path, ec)) Fail(path, "is a directory", "an OBJ file");
  CheckFiniteCoordinates(path);

  // Parse and triangulate.
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = fs::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    const auto lines = Lines(reader.Error());
    Fail(path, lines.empty() ? "cannot be read" : lines.front(), "a Wavefront OBJ file");
  }
  LoadedMesh out;
  for (const std::string& w : Lines(reader.Warning())) {
    if (w.find("out of bounds") != std::string::npos) Fail(path, w, "indices within the file's vertex list");
    // A face of one or two vertices: tinyobjloader drops it with a warning; most often the
    // file was cut off in its last line, so it is an error, not a silently smaller mesh.
    if (w.find("Degenerated face") != std::string::npos)
      Fail(path, "a face with fewer than 3 vertices (truncated file?)", "faces of at least 3 vertices");
    out.report.warnings.push_back(path + ": " + w + " (using albedo 0.8 where no material applies)");
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto& materials = reader.GetMaterials();

  // A material name defined several times means its last definition (see the header).
  std::map<std::string, int> last_definition;
  for (std::size_t m = 0; m < materials.size(); ++m) last_definition[materials[m].name] = static_cast<int>(m);
  auto albedo_of = [&](int id) {
    if (id < 0 || static_cast<std::size_t>(id) >= materials.size()) return glm::vec3(kDefaultAlbedo);
    const auto& kd = materials[static_cast<std::size_t>(last_definition[materials[id].name])].diffuse;
    return glm::vec3(kd[0], kd[1], kd[2]);
  };
  // Kd must be a reflectance in [0, 1]; anything else is clamped (NaN -> default) with a warning.
  for (const auto& m : materials) {
    const glm::vec3 kd(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    if (kd == glm::clamp(kd, glm::vec3(0.0f), glm::vec3(1.0f))) continue;
    out.report.warnings.push_back(path + ": material '" + m.name + "' has Kd outside [0, 1] (clamped)");
  }
  auto checked_albedo = [&](int id) {
    const glm::vec3 kd = albedo_of(id);
    if (!std::isfinite(kd.x) || !std::isfinite(kd.y) || !std::isfinite(kd.z)) return glm::vec3(kDefaultAlbedo);
    return glm::clamp(kd, glm::vec3(0.0f), glm::vec3(1.0f));
  };

  // Gather corners, validating indices and dropping zero-area triangles.
  const auto vertex_count = static_cast<int>(attrib.vertices.size() / 3);
  const auto normal_count = static_cast<int>(attrib.normals.size() / 3);
  CornerSoup soup;
  std::size_t faces = 0, zero_normals = 0;
  for (const auto& shape : reader.GetShapes()) {
    const auto& idx = shape.mesh.indices;
    for (std::size_t f = 0; f * 3 + 2 < idx.size(); ++f) {
      ++faces;
      glm::dvec3 p[3];
      for (int c = 0; c < 3; ++c) {
        const tinyobj::index_t& i = idx[f * 3 + c];
        if (i.vertex_index < 0 || i.vertex_index >= vertex_count)
          Fail(path, "face " + std::to_string(faces) + " uses vertex " + std::to_string(i.vertex_index + 1) +
                         " of " + std::to_string(vertex_count), "indices 1.." + std::to_string(vertex_count));
        if (i.normal_index < -1 || i.normal_index >= normal_count)
          Fail(path, "face " + std::to_string(faces) + " uses normal " + std::to_string(i.normal_index + 1) +
                         " of " + std::to_string(normal_count), "indices 1.." + std::to_string(normal_count));
        p[c] = glm::dvec3(attrib.vertices[3 * i.vertex_index], attrib.vertices[3 * i.vertex_index + 1],
                          attrib.vertices[3 * i.vertex_index + 2]);
      }
      // Zero-area faces go on into the soup: the welder drops them from the triangles but
      // keeps them in file_triangles, so per-face outputs still have a row for every face.
      const glm::vec3 albedo = checked_albedo(shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[f]);
      for (int c = 0; c < 3; ++c) {
        const tinyobj::index_t& i = idx[f * 3 + c];
        soup.positions.emplace_back(p[c]);
        glm::vec3 n(0.0f);
        if (i.normal_index >= 0) {
          n = glm::vec3(attrib.normals[3 * i.normal_index], attrib.normals[3 * i.normal_index + 1],
                        attrib.normals[3 * i.normal_index + 2]);
          const float len = glm::length(n);
          if (len > 0.0f) n /= len;
          else zero_normals += 1;  // recomputed by the welder as a corner without a normal
        }
        soup.normals.push_back(n);
        soup.ids.push_back(static_cast<std::uint64_t>(i.vertex_index) << 32 | static_cast<std::uint32_t>(i.normal_index));
        soup.albedo.push_back(albedo);
      }
    }
  }
  if (faces == 0) Fail(path, "no faces", "at least one triangle");
  if (zero_normals > 0)
    out.report.warnings.push_back(path + ": " + std::to_string(zero_normals) +
                                  " corners have zero-length normals (recomputed)");

  // Weld (normal-less corners within a tolerance relative to the mesh size).
  Bounds3 box;
  for (const glm::vec3& q : soup.positions) box.Extend(q);
  const float tolerance = kWeldRelativeTolerance * glm::length(box.hi - box.lo);
  out.mesh = WeldCorners(soup, tolerance, out.report);
  if (out.mesh.triangles.empty())
    Fail(path, "all " + std::to_string(faces) + " faces have zero area or collapse when welding",
         "at least one non-degenerate triangle");
  return out;
}

}  // namespace prt
