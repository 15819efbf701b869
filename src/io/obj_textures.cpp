#include "io/obj_textures.h"

#include <algorithm>
#include <filesystem>

#include "geometry/mesh_ops.h"
#include "io/load_texture.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

bool IsFile(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec) && !fs::is_directory(p, ec);
}

/// Where map_Kd `name` of a library in `folder` is (the file comment's order); `how` says which
/// fallback found it (empty: as written). Empty when none exists.
std::string FindTextureFile(const std::string& folder, const std::string& name, std::string& how) {
  how.clear();
  if (IsFile(fs::path(folder) / name)) return (fs::path(folder) / name).string();
  std::string slashed = name;
  for (char& c : slashed) c = c == '\\' ? '/' : c;
  const std::size_t cut = slashed.find_last_of('/');
  const std::string file = cut == std::string::npos ? slashed : slashed.substr(cut + 1);
  const bool windows_drive = slashed.size() > 1 && slashed[1] == ':';
  if (slashed != name && !windows_drive && IsFile(fs::path(folder) / slashed)) {
    how = "with '\\' read as '/'";
    return (fs::path(folder) / slashed).string();
  }
  if (file.empty()) return {};
  if (IsFile(fs::path(folder) / file)) {
    how = "beside the .mtl";
    return (fs::path(folder) / file).string();
  }
  if (IsFile(fs::path(folder) / "textures" / file)) {
    how = "in textures/ beside the .mtl";
    return (fs::path(folder) / "textures" / file).string();
  }
  // An option tinyobjloader does not know (`-foo 1 tex.png`) reaches here as part of the name:
  // the longest tail after a blank that names a file is the file, the words before it ignored.
  if (name[0] == '-')
    for (std::size_t blank = name.find(' '); blank != std::string::npos; blank = name.find(' ', blank + 1)) {
      const std::string tail = name.substr(blank + 1);
      if (!tail.empty() && IsFile(fs::path(folder) / tail)) {
        how = "after the unknown option '" + name.substr(0, blank) + "' (ignored)";
        return (fs::path(folder) / tail).string();
      }
    }
  return {};
}

/// The options prt ignores, in the order the file comment lists them, of those a map_Kd line
/// writes: every option but -s and -o.
std::vector<std::string> IgnoredOptions(const std::vector<std::string>& written) {
  static const char* const kIgnored[] = {"-clamp",  "-mm",    "-boost", "-t",    "-texres",     "-imfchan",
                                         "-blendu", "-blendv", "-type",  "-colorspace", "-bm"};
  std::vector<std::string> out;
  for (const char* option : kIgnored)
    if (std::find(written.begin(), written.end(), option) != written.end()) out.push_back(option);
  return out;
}

}  // namespace

ObjTextures::ObjTextures(const std::vector<tinyobj::material_t>& materials, const std::vector<std::string>& folders,
                         const std::vector<glm::vec3>& albedos,
                         const std::vector<std::vector<std::string>>& map_kd_options,
                         const std::string& override_path, const std::string& obj_path)
    : materials_(materials), folders_(folders), albedos_(albedos), override_(override_path), obj_path_(obj_path) {
  std::map<std::string, int> last;
  for (std::size_t m = 0; m < materials.size(); ++m) last[materials[m].name] = static_cast<int>(m);
  for (const auto& m : materials) last_definition_.push_back(last[m.name]);
  active_ = !override_.empty();
  for (int m : last_definition_) active_ = active_ || !materials[static_cast<std::size_t>(m)].diffuse_texname.empty();
  if (override_.empty()) WarnIgnoredOptions(map_kd_options);
}

void ObjTextures::WarnIgnoredOptions(const std::vector<std::vector<std::string>>& map_kd_options) {
  std::string list;
  for (std::size_t m = 0; m < materials_.size(); ++m) {
    if (last_definition_[m] != static_cast<int>(m) || materials_[m].diffuse_texname.empty()) continue;
    const std::vector<std::string> ignored = IgnoredOptions(m < map_kd_options.size() ? map_kd_options[m] : std::vector<std::string>{});
    if (ignored.empty()) continue;
    std::string names;
    for (const std::string& o : ignored) names += (names.empty() ? "" : " ") + o;
    list += (list.empty() ? "" : ", ") + names + " of material '" + materials_[m].name + "'";
  }
  if (!list.empty())
    warnings_.push_back(obj_path_ + ": map_Kd options ignored (prt reads -s and -o): " + list);
}

glm::vec2 ObjTextures::MapUv(int id, glm::vec2 uv) const {
  if (!override_.empty() || id < 0 || static_cast<std::size_t>(id) >= materials_.size()) return uv;
  const auto& o = materials_[static_cast<std::size_t>(last_definition_[static_cast<std::size_t>(id)])].diffuse_texopt;
  return glm::vec2(o.scale[0] * uv.x + o.origin_offset[0], o.scale[1] * uv.y + o.origin_offset[1]);
}

const std::string& ObjTextures::FileOf(int m) {
  const auto [it, inserted] = file_of_.emplace(m, std::string());
  if (!inserted) return it->second;
  const auto& material = materials_[static_cast<std::size_t>(m)];
  std::string how;
  it->second = FindTextureFile(folders_[static_cast<std::size_t>(m)], material.diffuse_texname, how);
  if (!it->second.empty() && !how.empty())
    warnings_.push_back(obj_path_ + ": texture '" + material.diffuse_texname + "' of material '" + material.name +
                        "' is not at that path; using " + fs::path(it->second).filename().string() + " " + how +
                        " (" + it->second + ")");
  return it->second;
}

std::uint32_t ObjTextures::Add(std::shared_ptr<const Texture> texture) {
  textures_.push_back(std::move(texture));
  return static_cast<std::uint32_t>(textures_.size() - 1);
}

std::uint32_t ObjTextures::Solid(const glm::vec3& albedo, const std::string& name) {
  const auto [it, inserted] = index_of_.emplace("solid:" + name, 0u);
  if (inserted) it->second = Add(std::make_shared<const Texture>(Texture::Solid(albedo, name)));
  return it->second;
}

std::uint32_t ObjTextures::ForFace(int id, bool has_uv) {
  const bool known = id >= 0 && static_cast<std::size_t>(id) < materials_.size();
  const int m = known ? last_definition_[static_cast<std::size_t>(id)] : -1;
  const glm::vec3 kd = known ? albedos_[static_cast<std::size_t>(id)] : glm::vec3(kDefaultAlbedo);
  const std::string material = known ? materials_[static_cast<std::size_t>(m)].name : std::string("(default)");
  // The file this face's texture comes from, if any.
  std::string path = override_;
  if (path.empty() && m >= 0 && !materials_[static_cast<std::size_t>(m)].diffuse_texname.empty()) {
    path = FileOf(m);
    if (path.empty()) {
      const std::string& name = materials_[static_cast<std::size_t>(m)].diffuse_texname;
      ++missing_[(fs::path(folders_[static_cast<std::size_t>(m)]) / name).string() + "' of material '" + material];
      return Solid(kd, "Kd of material " + material);
    }
  }
  if (path.empty()) return Solid(kd, "Kd of material " + material);
  auto& file = files_[path];
  std::vector<std::string> load_warnings;
  if (!file) {
    file = std::make_shared<const Texture>(LoadTexture(path, load_warnings));
    for (auto& w : load_warnings) warnings_.push_back(std::move(w));
  }
  if (!has_uv) {
    ++faces_without_uv_;
    return Solid(file->mean(), "mean of " + path);
  }
  const auto [it, inserted] = index_of_.emplace("file:" + path, 0u);
  if (inserted) it->second = Add(file);
  return it->second;
}

std::vector<std::string> ObjTextures::Warnings() const {
  std::vector<std::string> out = warnings_;
  for (const auto& [what, faces] : missing_)
    out.push_back(obj_path_ + ": texture '" + what + "' was not found (nor its file name beside the .mtl or in " +
                  "textures/ there); its " + std::to_string(faces) +
                  (faces == 1 ? " face uses" : " faces use") + " the material's Kd");
  if (faces_without_uv_ > 0)
    out.push_back(obj_path_ + ": " + std::to_string(faces_without_uv_) +
                  (faces_without_uv_ == 1 ? " textured face has" : " textured faces have") +
                  " no texture coordinates (vt); they use the texture's mean colour");
  return out;
}

}  // namespace prt
