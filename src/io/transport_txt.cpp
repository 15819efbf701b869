#include "io/transport_txt.h"

#include <cstdio>

namespace prt {

std::string FormatTransportTxt(const Mesh& mesh, const Transport& transport, int channel) {
  const int count = CoeffCount(transport.lmax);
  std::string out = std::to_string(mesh.vertex_count()) + "\n";
  out.reserve(out.size() + (mesh.file_triangles.size() + mesh.triangle_count()) * 3 * count * 14);
  char number[32];
  const auto& faces = mesh.file_triangles.empty() ? mesh.triangles : mesh.file_triangles;
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
