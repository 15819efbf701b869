#pragma once
/// \file
/// Wavefront OBJ text for meshes prt makes (`prt sample-files`): one object per part, each with
/// its material, positions and normals per vertex and faces `f a//a b//b c//c` (1-based), so
/// LoadObj reads the same vertices back (one per (position, normal) pair). The .mtl text gives
/// each material its diffuse colour Kd.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"

namespace prt {

/// A named part of an OBJ file with one material.
struct ObjPart {
  std::string name;   ///< object and material name (no spaces)
  Mesh mesh;          ///< its albedo is ignored: `kd` is the material's colour
  glm::vec3 kd{0.8f};
};

/// The OBJ text of `parts`, referring to the material file `mtl_name`.
std::string FormatObj(const std::vector<ObjPart>& parts, const std::string& mtl_name);

/// The .mtl text of the parts' materials.
std::string FormatMtl(const std::vector<ObjPart>& parts);

}  // namespace prt
