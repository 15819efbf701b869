#pragma once
/// \file
/// The OBJ loader's textures: which texture each face takes, read once per file.
///
/// Sources. A material's `map_Kd FILE` is its diffuse texture, FILE relative to the folder of the
/// .mtl that defines it (as OBJ tools resolve it); `--texture FILE` applies one texture to every
/// face instead. The texture replaces the material's Kd rather than multiplying it (Blender's
/// importer reads it so; exporters write Kd 0.8 or 1 beside a map_Kd, and a painted albedo
/// darkened by 0.8 is not what the artist painted).
///
/// A textured mesh has a texture on every face: a material without map_Kd gets a 1 x 1 texture
/// of its Kd, and a face of a textured material without texture coordinates (no `vt` on a
/// corner) a 1 x 1 texture of the texture's mean, counted in one warning. A map_Kd file that does
/// not exist is a warning (its faces keep Kd, as a missing material keeps the default); one that
/// exists but cannot be decoded is an error. Each file is read once however many materials name it.
///
/// Where a map_Kd file is found. Exporters write the path the artist's machine had: an absolute
/// `C:\Users\art\tex\checker.png` or `/home/x/tex/checker.png`, or a relative path with `\`
/// separators. As most viewers do, the name is tried as written (relative to the .mtl's folder),
/// then with `\` read as a separator, then its file name beside the .mtl, then in a `textures/`
/// folder beside the .mtl; a file found by a fallback is named in one warning per map.
///
/// Options. `map_Kd -s u v w -o u v w FILE` scales and offsets the texture coordinates,
/// (u, v) -> (s_u u + o_u, s_v v + o_v), as three.js's MTLLoader (repeat and offset) and
/// Blender's importer (mapping scale and location) read them; w has no meaning on a surface.
/// tinyobjloader parses the options apart from the file name. The other options (-clamp, -mm,
/// -boost, -t, -texres, -imfchan, -blendu, -blendv, -type, -colorspace, -bm) are ignored, said
/// in one warning naming them and their materials: each one the line writes, even with its
/// default value (`-clamp off`, `-bm 1`), since the user wrote it to be read. An option tinyobjloader does not know stays
/// in the name it hands over (`-foo 1 tex.png`); the longest tail of it after a blank that names
/// a file is taken, the words before it named as ignored.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <tiny_obj_loader.h>

#include "texture/texture.h"

namespace prt {

class ObjTextures {
 public:
  /// `folders[m]`: the folder of the .mtl that defined material m; `albedos[m]`: its Kd;
  /// `map_kd_options[m]`: the options its map_Kd line writes (obj_materials.h). `override_path`
  /// non-empty: --texture, for every face.
  ObjTextures(const std::vector<tinyobj::material_t>& materials, const std::vector<std::string>& folders,
              const std::vector<glm::vec3>& albedos, const std::vector<std::vector<std::string>>& map_kd_options,
              const std::string& override_path, const std::string& obj_path);

  /// True when some material names a map_Kd or --texture is given: the mesh is textured.
  bool active() const { return active_; }
  /// The texture index of a face of material `id` (-1: none), whose corners all have texture
  /// coordinates when `has_uv`. Reads the texture on first use.
  std::uint32_t ForFace(int id, bool has_uv);
  /// The texture coordinates of a face of material `id` as its map_Kd options place them.
  glm::vec2 MapUv(int id, glm::vec2 uv) const;
  /// The textures ForFace numbered, and the warnings (missing files, faces without coordinates).
  std::vector<std::shared_ptr<const Texture>> TakeTextures() { return std::move(textures_); }
  std::vector<std::string> Warnings() const;
  /// The texture files read, for the run's record of inputs.
  std::vector<std::string> Files() const {
    std::vector<std::string> out;
    for (const auto& [path, texture] : files_) out.push_back(path);
    return out;
  }

 private:
  std::uint32_t Add(std::shared_ptr<const Texture> texture);
  std::uint32_t Solid(const glm::vec3& albedo, const std::string& name);
  /// The file material m's map_Kd names, found as the file comment says; empty if nowhere.
  const std::string& FileOf(int m);
  void WarnIgnoredOptions(const std::vector<std::vector<std::string>>& map_kd_options);

  const std::vector<tinyobj::material_t>& materials_;
  std::vector<std::string> folders_;
  std::vector<glm::vec3> albedos_;
  std::string override_, obj_path_;
  bool active_ = false;
  std::vector<int> last_definition_;                 ///< per material id: the id of its name's last definition
  std::map<std::string, std::shared_ptr<const Texture>> files_;  ///< by resolved path
  std::map<std::string, std::uint32_t> index_of_;   ///< by key (see ForFace)
  std::vector<std::shared_ptr<const Texture>> textures_;
  std::vector<std::string> warnings_;
  std::map<std::string, std::size_t> missing_;       ///< map_Kd path -> faces
  std::map<int, std::string> file_of_;               ///< per material id (last definition): FileOf
  std::size_t faces_without_uv_ = 0;
};

}  // namespace prt
