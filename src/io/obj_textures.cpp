#include "io/obj_textures.h"

#include <filesystem>

#include "geometry/mesh_ops.h"
#include "texture/load_texture.h"

namespace prt {

ObjTextures::ObjTextures(const std::vector<tinyobj::material_t>& materials, const std::vector<std::string>& folders,
                         const std::vector<glm::vec3>& albedos, const std::string& override_path,
                         const std::string& obj_path)
    : materials_(materials), folders_(folders), albedos_(albedos), override_(override_path), obj_path_(obj_path) {
  std::map<std::string, int> last;
  for (std::size_t m = 0; m < materials.size(); ++m) last[materials[m].name] = static_cast<int>(m);
  for (const auto& m : materials) last_definition_.push_back(last[m.name]);
  active_ = !override_.empty();
  for (int m : last_definition_) active_ = active_ || !materials[static_cast<std::size_t>(m)].diffuse_texname.empty();
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
    namespace fs = std::filesystem;
    const std::string& name = materials_[static_cast<std::size_t>(m)].diffuse_texname;
    path = (fs::path(folders_[static_cast<std::size_t>(m)]) / name).string();
    std::error_code ec;
    if (!fs::exists(path, ec)) {
      ++missing_[path + "' of material '" + material];
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
    out.push_back(obj_path_ + ": texture '" + what + "' was not found; its " + std::to_string(faces) +
                  (faces == 1 ? " face uses" : " faces use") + " the material's Kd");
  if (faces_without_uv_ > 0)
    out.push_back(obj_path_ + ": " + std::to_string(faces_without_uv_) +
                  (faces_without_uv_ == 1 ? " textured face has" : " textured faces have") +
                  " no texture coordinates (vt); they use the texture's mean colour");
  return out;
}

}  // namespace prt
