#include "io/transport_txt.h"

#include <cstdio>

namespace prt {

namespace {

/// The corners `FormatTransportTxt` and `FormatVertexRadianceTxt` write: every face of the file.
const std::vector<std::array<std::uint32_t, 3>>& FileFaces(const Mesh& mesh) {
  return mesh.file_triangles.empty() ? mesh.triangles : mesh.file_triangles;
}

}  // namespace

std::string FormatVertexRadianceTxt(const Mesh& mesh, const std::vector<glm::vec3>& radiance) {
  std::string out = std::to_string(mesh.vertex_count()) + "\n";
  const auto& faces = FileFaces(mesh);
  out.reserve(out.size() + faces.size() * 3 * 48);
  char row[96];
  for (const auto& tri : faces)
    for (std::uint32_t v : tri) {
      const glm::vec3& c = radiance[v];
      std::snprintf(row, sizeof row, "%.9g %.9g %.9g\n", double(c.x), double(c.y), double(c.z));
      out += row;
    }
  return out;
}

std::string FormatTransportTxt(const Mesh& mesh, const Transport& transport, int channel) {
  const int count = CoeffCount(transport.lmax);
  std::string out = std::to_string(mesh.vertex_count()) + "\n";
  const auto& faces = FileFaces(mesh);
  out.reserve(out.size() + faces.size() * 3 * count * 14);
  char number[32];
  for (const auto& tri : faces) {
    for (std::uint32_t v : tri) {
      const float* t = transport.at(v, channel);
      for (int k = 0; k < count; ++k) {
        std::snprintf(number, sizeof number, k + 1 < count ? "%.7g " : "%.7g\n", double(t[k]));
        out += number;
      }
    }
  }
  return out;
}

}  // namespace prt
