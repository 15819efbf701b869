#include "io/obj_writer.h"

#include <cstdio>

namespace prt {
namespace {

void Append(std::string& out, const char* fmt, double a, double b, double c) {
  char line[128];
  std::snprintf(line, sizeof line, fmt, a, b, c);
  out += line;
}

}  // namespace

std::string FormatObj(const std::vector<ObjPart>& parts, const std::string& mtl_name) {
  std::string out = "# written by prt sample-files\nmtllib " + mtl_name + "\n";
  std::size_t base = 1;  // OBJ indices are 1-based and global
  for (const auto& part : parts) {
    out += "o " + part.name + "\nusemtl " + part.name + "\n";
    for (const auto& p : part.mesh.positions) Append(out, "v %.7g %.7g %.7g\n", p.x, p.y, p.z);
    for (const auto& n : part.mesh.normals) Append(out, "vn %.7g %.7g %.7g\n", n.x, n.y, n.z);
    for (const auto& t : part.mesh.triangles) {
      const std::size_t a = base + t[0], b = base + t[1], c = base + t[2];
      out += "f " + std::to_string(a) + "//" + std::to_string(a) + " " + std::to_string(b) + "//" +
             std::to_string(b) + " " + std::to_string(c) + "//" + std::to_string(c) + "\n";
    }
    base += part.mesh.vertex_count();
  }
  return out;
}

std::string FormatMtl(const std::vector<ObjPart>& parts) {
  std::string out = "# written by prt sample-files\n";
  for (const auto& part : parts) {
    out += "newmtl " + part.name + "\n";
    Append(out, "Kd %.6g %.6g %.6g\n\n", part.kd.x, part.kd.y, part.kd.z);
  }
  return out;
}

}  // namespace prt
