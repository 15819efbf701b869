#include "io/transport_txt.h"

#include <cstdio>

namespace prt {

std::string FormatTransportTxt(const Mesh& mesh, const Transport& transport, int channel) {
  const int count = CoeffCount(transport.lmax);
  std::string out = std::to_string(mesh.vertex_count()) + "\n";
  const auto& faces = mesh.file_triangles.empty() ? mesh.triangles : mesh.file_triangles;
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
