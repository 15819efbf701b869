#include "io/obj_materials.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/common.hpp>

#include "geometry/mesh_ops.h"
#include "io/material_names.h"
#include "material/material.h"

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

// The options a `map_Kd` line writes before its file name (`-s 2 2 1 -bm 1 tex.png`: -s, -bm),
// whatever their values, read as tinyobjloader reads them: each option takes a fixed count of
// words after it (-o, -s, -t three; -mm two; the others one), and the first word that is no
// option starts the file name.
std::vector<std::string> WrittenOptions(std::string_view rest) {
  static const std::map<std::string_view, int> kWords = {
      {"-blendu", 1}, {"-blendv", 1}, {"-clamp", 1}, {"-boost", 1}, {"-bm", 1},     {"-o", 3},         {"-s", 3},
      {"-t", 3},      {"-type", 1},   {"-texres", 1}, {"-imfchan", 1}, {"-mm", 2}, {"-colorspace", 1}};
  std::vector<std::string_view> words;
  for (std::size_t at = 0; at < rest.size();) {
    while (at < rest.size() && (rest[at] == ' ' || rest[at] == '\t')) ++at;
    std::size_t end = at;
    while (end < rest.size() && rest[end] != ' ' && rest[end] != '\t') ++end;
    if (end > at) words.push_back(rest.substr(at, end - at));
    at = end;
  }
  std::vector<std::string> out;
  for (std::size_t w = 0; w < words.size();) {
    const auto option = kWords.find(words[w]);
    if (option == kWords.end()) break;
    out.emplace_back(words[w]);
    w += 1 + static_cast<std::size_t>(option->second);
  }
  return out;
}

}  // namespace

MaterialLibraries::MaterialLibraries(const std::string& obj_path, std::vector<std::string> mtllib_lines)
    : folder_(fs::path(obj_path).parent_path().string()), mtllib_lines_(std::move(mtllib_lines)) {}

bool MaterialLibraries::operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                                   std::map<std::string, int>* names, std::string* /*warn*/, std::string* err) {
  if (name.empty()) return false;  // tinyobjloader's split of "mtllib a.mtl " ends with ""
  // The first word of a line of several: the whole line may be one name with spaces.
  for (const std::string& whole : mtllib_lines_)
    if (whole.size() > name.size() && whole.compare(0, name.size(), name) == 0 &&
        (whole[name.size()] == ' ' || whole[name.size()] == '\t') && Read(whole, materials, names, err, true))
      return true;
  return Read(name, materials, names, err, false);
}

bool MaterialLibraries::Read(const std::string& name, std::vector<tinyobj::material_t>* materials,
                             std::map<std::string, int>* names, std::string* err, bool quiet_if_missing) {
  const fs::path path = fs::path(folder_) / name;
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in && !fs::is_directory(path, ec)) text << in.rdbuf();
  if (!in || fs::is_directory(path, ec) || in.bad()) {
    if (!quiet_if_missing) unread_.push_back(name + (fs::exists(path, ec) ? " could not be read" : " was not found"));
    return false;
  }
  std::string content = text.str();
  // Each statement's keyword, and the options each material's map_Kd line writes (its last one).
  std::map<std::string, std::vector<std::string>> options_by_name;
  std::string material;
  std::istringstream lines(content);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream fields(line);
    std::string keyword;
    if (!(fields >> keyword) || keyword[0] == '#') continue;
    keywords_.insert(keyword);
    const std::string_view rest = std::string_view(line).substr(line.find(keyword) + keyword.size());
    if (keyword == "newmtl") material = std::string(MaterialNameOf(rest));
    if (keyword == "map_Kd") options_by_name[material] = WrittenOptions(rest);
  }
  HideNameBlanks(content, "newmtl");  // as the OBJ's usemtl lines (material_names.h)
  std::istringstream stream(content);
  std::string remarks;
  const std::size_t first = materials->size();
  tinyobj::LoadMtl(names, materials, &stream, &remarks, err);
  material_folders_.resize(materials->size(), path.parent_path().string());
  for (std::size_t m = first; m < materials->size(); ++m)
    map_kd_options_.push_back(options_by_name[ShowNameBlanks((*materials)[m].name)]);
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

MaterialFields FindMaterialFields(const MaterialLibraries& libraries, const std::vector<tinyobj::material_t>& materials,
                                  const std::map<std::string, std::size_t>& faces_by_material) {
  MaterialFields out;
  out.keywords = libraries.keywords();
  std::map<std::string, std::size_t> last_definition;
  for (std::size_t m = 0; m < materials.size(); ++m) last_definition[materials[m].name] = m;
  std::size_t most = 0;
  for (const auto& [name, faces] : faces_by_material) {
    const auto it = last_definition.find(name);
    if (it == last_definition.end() || faces <= most) continue;
    const auto& m = materials[it->second];
    const glm::vec3 ks(m.specular[0], m.specular[1], m.specular[2]);
    if (!(std::max({ks.x, ks.y, ks.z}) > 0.0f) || !std::isfinite(ks.x + ks.y + ks.z + m.shininess)) continue;
    most = faces, out.gloss_material = name, out.ks = ks, out.ns = m.shininess;
  }
  return out;
}

std::string DescribeMaterialFields(const MaterialFields& fields, const MaterialUse& use) {
  if (fields.keywords.empty()) return {};
  std::vector<std::string> used, ignored;
  for (const std::string& k : fields.keywords) {
    if (k == "newmtl") continue;
    const bool colour = k == "Kd" || k == "map_Kd";
    if (colour && !use.colour_replaced && !(k == "map_Kd" && use.texture_replaced)) used.push_back(k);
    else if (colour) ignored.push_back(k + (use.colour_replaced ? " (--albedo)" : " (--texture)"));
    else ignored.push_back(k);
  }
  std::string out = "used " + (used.empty() ? std::string("none") : Join(used, ", "));
  if (!ignored.empty()) out += "; ignored " + Join(ignored, ", ");
  // The gloss the file describes, as the nearest --material (the same exponent and weight).
  if (use.glossy || fields.gloss_material.empty() || !fields.keywords.count("Ns")) return out;
  const int n = static_cast<int>(std::lround(std::clamp(double(fields.ns), double(kMinPhongExponent),
                                                        double(kMaxPhongExponent))));
  // Two decimals: the nearest, or (untextured) the largest that --material accepts beside the
  // brightest Kd (FittingKs; a textured mesh's texels are fitted under the coat instead).
  const double mean_ks = std::clamp((fields.ks.x + fields.ks.y + fields.ks.z) / 3.0, 0.0, 1.0);
  const KsOffer offer = use.textured ? KsOffer{std::round(mean_ks * 100.0) / 100.0, false}
                                     : FittingKs(mean_ks, use.brightest_kd);
  const double ks = offer.ks;
  const std::string fit =
      offer.lowered ? ", KS lowered to fit beside the brightest Kd " + ShortestFloat(use.brightest_kd) : "";
  if (!(ks > 0.0)) return out;
  return out + " (shading comes from --material: material '" + fields.gloss_material + "' (Ks " +
         ShortestFloat(float((fields.ks.x + fields.ks.y + fields.ks.z) / 3.0)) + ", Ns " + ShortestFloat(fields.ns) +
         ") as a glossy coat is --material phong:" + std::to_string(n) + "," + ShortestFloat(float(ks)) + fit + ")";
}

std::vector<std::string> TinyObjLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

}  // namespace prt
