#include "io/obj_materials.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/common.hpp>

#include "geometry/mesh_ops.h"

#include "core/text.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// "a", "a or b", "a, b or c" (with `last` = " or ").
std::string Join(const std::vector<std::string>& items, const char* last) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i == 0 ? "" : i + 1 == items.size() ? last : ", ") + items[i];
  return out;
}

}  // namespace

MaterialLibraries::MaterialLibraries(const std::string& obj_path)
    : folder_(fs::path(obj_path).parent_path().string()) {}

bool MaterialLibraries::operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                                   std::map<std::string, int>* names, std::string* /*warn*/, std::string* err) {
  if (name.empty()) return false;  // tinyobjloader's split of "mtllib a.mtl " ends with ""
  const fs::path path = fs::path(folder_) / name;
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in && !fs::is_directory(path, ec)) text << in.rdbuf();
  if (!in || fs::is_directory(path, ec) || in.bad()) {
    unread_.push_back(name + (fs::exists(path, ec) ? " could not be read" : " was not found"));
    return false;
  }
  std::istringstream stream(text.str());
  std::string remarks;
  tinyobj::LoadMtl(names, materials, &stream, &remarks, err);
  material_folders_.resize(materials->size(), path.parent_path().string());
  for (const std::string& r : TinyObjLines(remarks)) remarks_.push_back(path.string() + ": " + r);
  read_.push_back(name);
  read_paths_.push_back(path.string());
  return true;
}

std::vector<glm::vec3> MaterialAlbedos(const std::vector<tinyobj::material_t>& materials, const std::string& path,
                                       std::vector<std::string>& warnings) {
  std::map<std::string, std::size_t> last_definition;
  for (std::size_t m = 0; m < materials.size(); ++m) last_definition[materials[m].name] = m;
  std::vector<glm::vec3> albedo(materials.size(), glm::vec3(kDefaultAlbedo));
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const auto& kd = materials[last_definition[materials[m].name]].diffuse;
    const glm::vec3 k(kd[0], kd[1], kd[2]);
    if (!std::isfinite(k.x) || !std::isfinite(k.y) || !std::isfinite(k.z)) continue;
    albedo[m] = glm::clamp(k, glm::vec3(0.0f), glm::vec3(1.0f));
  }
  // Kd must be a reflectance in [0, 1]: one warning per definition outside it.
  for (const auto& m : materials) {
    const glm::vec3 k(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
    if (k != glm::clamp(k, glm::vec3(0.0f), glm::vec3(1.0f)))
      warnings.push_back(path + ": material '" + m.name + "' has Kd outside [0, 1] (clamped)");
  }
  return albedo;
}

void WarnMissingMaterials(const std::string& path, const std::map<std::string, std::size_t>& faces_by_material,
                          const std::vector<tinyobj::material_t>& materials, const MaterialLibraries& libraries,
                          const std::set<std::string>& used_before_definition, std::vector<std::string>& warnings) {
  std::set<std::string> defined;
  for (const auto& m : materials) defined.insert(m.name);
  // Where the material was looked for: the libraries read, and why others were not.
  std::string where;
  if (!libraries.read().empty()) where = " in " + Join(libraries.read(), " or ");
  if (!libraries.unread().empty()) where += (where.empty() ? ": " : ", and ") + Join(libraries.unread(), " and ");
  if (libraries.read().empty() && libraries.unread().empty()) where = ": the file names no material library (mtllib)";
  const std::string albedo = "the default albedo " + ShortestFloat(kDefaultAlbedo);
  for (const auto& [name, faces] : faces_by_material) {
    if (defined.count(name)) {
      if (used_before_definition.count(name))
        warnings.push_back(path + ": material '" + name + "' is used before the mtllib line that defines it; " +
                           "its faces before that line use " + albedo);
      continue;
    }
    warnings.push_back(path + ": material '" + name + "' is not defined" + where + "; " +
                       (faces == 1 ? "its 1 face uses " : "its " + std::to_string(faces) + " faces use ") + albedo);
  }
}

std::vector<std::string> TinyObjLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

}  // namespace prt
