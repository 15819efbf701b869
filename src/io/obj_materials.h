#pragma once
/// \file
/// The OBJ loader's materials: reading the `mtllib` files for tinyobjloader [1], turning Kd into
/// albedo, and saying in prt's words what is missing.
///
/// Lookup. A `mtllib NAME ...` line names one or more libraries; tinyobjloader splits the line at
/// its blanks, asks for the names in turn and keeps the first that can be read. Exporters also
/// write one name with spaces (Blender names the library after the .blend: `mtllib My
/// Scene.mtl`), so when asked for the first word of a line, the whole rest of the line is tried
/// first, as map_Kd reads it. NAME is looked up in the OBJ's folder (an absolute NAME as it is),
/// the way tinyobjloader's own file reader does with the folder as search path; here prt reads the
/// file, so it knows which library was read, which was missing and why.
///
/// Fields. prt reads a material's colour (Kd, or the texture of map_Kd: obj_textures.h); the
/// rest of what an exporter writes (Ka, Ks, Ns, d, illum, Ni, Ke, other maps) describes shading
/// prt takes from --material instead. Each library's statement keywords are recorded so the run
/// summary can say once which fields were used and which were ignored, and the gloss of the
/// material most faces use (Ks and Ns) is offered as the nearest `--material phong:N,KS`.
///
/// Definitions. The last definition of a name wins, over all libraries read (obj_loader.h says
/// why); Kd outside [0, 1] is clamped, a non-finite Kd gives the default albedo.
///
/// Missing materials. A `usemtl NAME` that no library defines leaves its faces at the default
/// albedo; the warning names the material, the libraries (or why none was read) and the number
/// of faces, once per name however often the file uses it.
///
/// References
///  [1] S. Fujita, "tinyobjloader", https://github.com/tinyobjloader/tinyobjloader (2.0.0rc10).

#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <tiny_obj_loader.h>

namespace prt {

/// Reads the material libraries of one OBJ file when tinyobjloader meets its `mtllib` lines.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  /// `obj_path` is the OBJ file; libraries are looked up in its folder. `mtllib_lines`: the whole
  /// rest of each of its `mtllib` lines (ObjScan), tried before their first word.
  MaterialLibraries(const std::string& obj_path, std::vector<std::string> mtllib_lines);

  /// Called by tinyobjloader with one library name: reads it into `materials` and `names`,
  /// returns false when it does not exist or cannot be read.
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warn, std::string* err) override;

  /// Names of the libraries read, as the OBJ wrote them, in order.
  const std::vector<std::string>& read() const { return read_; }
  /// The same libraries' paths as they were opened (the OBJ's folder joined with the name).
  const std::vector<std::string>& read_paths() const { return read_paths_; }
  /// One entry per library that could not be read: "x.mtl was not found", "... could not be read".
  const std::vector<std::string>& unread() const { return unread_; }
  /// Per material read (in tinyobjloader's order), the folder of the library that defined it:
  /// where its map_Kd is looked up.
  const std::vector<std::string>& material_folders() const { return material_folders_; }
  /// Per material read (as material_folders), the options its `map_Kd` line writes before the
  /// file name (`-s`, `-clamp`, ...), whatever their values: the ones prt ignores are named
  /// (obj_textures.h) even where they write their default.
  const std::vector<std::vector<std::string>>& map_kd_options() const { return map_kd_options_; }
  /// tinyobjloader's remarks on the libraries' content, each prefixed with the library's path.
  const std::vector<std::string>& remarks() const { return remarks_; }
  /// Every statement keyword the libraries read contain (`newmtl`, `Kd`, `Ns`, ...).
  const std::set<std::string>& keywords() const { return keywords_; }

 private:
  bool Read(const std::string& name, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* names,
            std::string* err, bool quiet_if_missing);

  std::string folder_;
  std::vector<std::string> mtllib_lines_;
  std::vector<std::string> read_, read_paths_, unread_, remarks_, material_folders_;
  std::vector<std::vector<std::string>> map_kd_options_;
  std::set<std::string> keywords_;
};

/// The material fields of a mesh's libraries, for the run summary (see the file comment).
struct MaterialFields {
  std::set<std::string> keywords;  ///< MaterialLibraries::keywords()
  std::string gloss_material;      ///< the material with Ks > 0 that most faces use; empty if none
  glm::vec3 ks{0.0f};              ///< its Ks
  float ns = 0.0f;                 ///< its Ns (the Phong exponent of the MTL model)
};

/// The gloss of the most used material with a non-zero Ks (ties: the first defined).
MaterialFields FindMaterialFields(const MaterialLibraries& libraries, const std::vector<tinyobj::material_t>& materials,
                                  const std::map<std::string, std::size_t>& faces_by_material);

/// How the run uses a mesh's material colours, for DescribeMaterialFields.
struct MaterialUse {
  bool colour_replaced = false;  ///< --albedo: neither Kd nor map_Kd is used
  bool texture_replaced = false; ///< --texture: map_Kd is not used
  bool glossy = false;           ///< --material already gives a glossy coat: no offer
  float brightest_kd = 0.0f;     ///< untextured: the largest Kd channel, which KS must fit beside
  bool textured = false;         ///< textured: the texels are fitted instead (scene_mesh.cpp)
};

/// One clause for the run summary, e.g. `used Kd, map_Kd; ignored Ka, Ks, Ns, d, illum (shading
/// comes from --material: Ks 0.5 and Ns 200 of material 'coat' read as --material phong:200,0.5)`.
/// Empty when no library was read.
std::string DescribeMaterialFields(const MaterialFields& fields, const MaterialUse& use);

/// Albedo for each tinyobjloader material id: the Kd of the LAST definition of its name,
/// clamped to [0, 1] (with a warning naming the material), the default albedo where Kd is not
/// finite. Warnings are appended to `warnings`, prefixed with `path`.
std::vector<glm::vec3> MaterialAlbedos(const std::vector<tinyobj::material_t>& materials, const std::string& path,
                                       std::vector<std::string>& warnings);

/// One warning per material name used but not defined, e.g. `mary.obj: material 'X' is not
/// defined in mary.mtl; its 9000 faces use the default albedo 0.8`. `faces_by_material` counts
/// the faces of each used name (ObjScan); `used_before_definition` holds the names tinyobjloader
/// could not find when it met their `usemtl` although a later `mtllib` defines them.
void WarnMissingMaterials(const std::string& path, const std::map<std::string, std::size_t>& faces_by_material,
                          const std::vector<tinyobj::material_t>& materials, const MaterialLibraries& libraries,
                          const std::set<std::string>& used_before_definition, std::vector<std::string>& warnings);

/// tinyobjloader's warnings and errors (several lines in one string) as non-empty single lines.
std::vector<std::string> TinyObjLines(const std::string& text);

}  // namespace prt
