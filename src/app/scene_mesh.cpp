// LoadSceneMesh (pipeline.h): the mesh of --mesh or the embedded scene, repaired and reported.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include <glm/geometric.hpp>

#include "options/option_table.h"
#include "app/pipeline.h"
#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "geometry/mesh_ops.h"
#include "geometry/mesh_texture.h"
#include "geometry/orientation.h"
#include "geometry/procedural.h"
#include "geometry/subdivide.h"
#include "io/obj_loader.h"
#include "texture/albedo_limit.h"

namespace prt {
namespace {

/// --max-edge may not make more triangles than this: beyond it the precompute would take hours
/// and the mesh would not fit comfortably in memory (about 100 bytes a triangle with its BVH).
constexpr std::size_t kMaxSplitTriangles = 20'000'000;

/// What loading repaired or skipped, for the mesh's summary line.
std::string LoadNotes(const MeshReport& report) {
  std::string notes;
  if (report.dropped_degenerate)
    notes += ", " + std::to_string(report.dropped_degenerate) + " zero-area triangles dropped";
  if (report.recomputed_normals) notes += ", " + std::to_string(report.recomputed_normals) + " normals computed";
  if (report.skipped_lines) notes += ", " + DescribeSkippedLines(report);
  return notes;
}

void SplitLongTriangles(Mesh& mesh, const SceneOptions& options) {
  const Bounds3 box = MeshBounds(mesh);
  const double diagonal = glm::length(box.hi - box.lo);
  const float max_edge = static_cast<float>(MaxEdgeLength(options, diagonal));
  const double finest = MinimumMaxEdge(mesh);
  if (!(max_edge > finest))
    throw Error("--max-edge: " + ShortestFloat(max_edge) + " is finer than float coordinates resolve on this mesh " +
                "(expected more than " + ShortestFloat(static_cast<float>(finest)) + ")");
  const std::size_t estimate = EstimateSplitTriangles(mesh, max_edge);
  if (estimate > kMaxSplitTriangles) {
    char count[64];
    if (estimate == std::numeric_limits<std::size_t>::max()) std::snprintf(count, sizeof count, "more than 1e19");
    else std::snprintf(count, sizeof count, "about %.2g", double(estimate));
    throw Error("--max-edge: " + ShortestFloat(max_edge) + " would split the mesh into " + count +
                " triangles (expected at most " + std::to_string(kMaxSplitTriangles) + ": choose a longer edge)");
  }
  const auto t0 = std::chrono::steady_clock::now();
  // The faces as read, kept for the files with a row per face of the file (--vertex-radiance's):
  // the split appends the vertices it adds, so each face's corners are still vertices of the
  // split mesh, with their own indices (geometry/subdivide.h clears file_triangles).
  std::vector<std::array<std::uint32_t, 3>> faces_as_read =
      mesh.file_triangles.empty() ? mesh.triangles : mesh.file_triangles;
  const SplitReport r = SplitLongEdges(mesh, max_edge);
  if (r.passes > 0) mesh.file_triangles = std::move(faces_as_read);
  char line[200];
  std::snprintf(line, sizeof line, "split: no edge longer than %.4g: %zu triangles -> %zu, %zu vertices added", max_edge,
                r.triangles_before, r.triangles_after, r.vertices_added);
  Summary(line + Formatted(" [%.3f s]", SecondsSince(t0)));
}

// The textures of a textured mesh for its summary line: each file with its size and mip levels,
// and how many materials use a plain Kd.
std::string DescribeTextures(const Mesh& mesh) {
  std::string files;
  std::size_t solid = 0;
  for (const auto& t : mesh.textures) {
    if (t->width() == 1 && t->height() == 1) {
      ++solid;
      continue;
    }
    files += (files.empty() ? "" : ", ") + t->name() + " (" + std::to_string(t->width()) + "x" +
             std::to_string(t->height()) + ", " + std::to_string(t->level_count()) + " mip levels)";
  }
  if (solid > 0) files += (files.empty() ? "" : "; ") + std::to_string(solid) + " plain colours (Kd)";
  return files;
}

// The materials' summary line: the libraries read, the fields used and ignored, the gloss offered.
std::string DescribeMaterials(const LoadedMesh& loaded, const SceneOptions& options) {
  std::string libraries;
  for (std::size_t i = 1; i < loaded.files_read.size(); ++i)
    libraries += (libraries.empty() ? "" : ", ") + std::filesystem::path(loaded.files_read[i]).filename().string();
  MaterialUse use;
  use.colour_replaced = options.albedo.has_value();
  use.texture_replaced = !options.texture.empty();
  use.glossy = options.material.glossy;
  use.textured = loaded.mesh.textured() && !options.albedo;
  if (options.albedo) use.brightest_kd = static_cast<float>(std::max({options.albedo->x, options.albedo->y, options.albedo->z}));
  else
    for (const glm::vec3& a : loaded.mesh.albedo) use.brightest_kd = std::max({use.brightest_kd, a.x, a.y, a.z});
  const std::string fields = DescribeMaterialFields(loaded.material_fields, use);
  return libraries.empty() || fields.empty() ? "" : libraries + ": " + fields;
}

// The per-texel energy rule (texture/albedo_limit.h) on every texture of a glossy mesh, with one
// warning naming each texture that had texels above 1 - KS.
void FitTexturesBesideCoat(Mesh& mesh, const Material& material, const std::string& mesh_name) {
  const float limit = static_cast<float>(1.0 - material.ks);
  std::string changed;
  for (auto& texture : mesh.textures) {
    std::size_t scaled = 0;
    std::optional<Texture> fitted = LimitAlbedo(*texture, limit, scaled);
    if (!fitted) continue;
    const std::size_t texels = static_cast<std::size_t>(texture->width()) * static_cast<std::size_t>(texture->height());
    changed += (changed.empty() ? "" : ", ") + std::to_string(scaled) + " of " + std::to_string(texels) +
               (texels == 1 ? " texel of '" : " texels of '") + texture->name() + "'";
    texture = std::make_shared<const Texture>(std::move(*fitted));
  }
  if (changed.empty()) return;
  SetVertexAlbedoFromTextures(mesh);
  Warn(mesh_name + ": " + material.Name() + " keeps albedo + KS <= 1 per texel: texels brighter than 1 - KS = " +
       ShortestFloat(limit) + " were scaled down to it, hue kept (" + changed + ")");
}

}  // namespace

Mesh LoadSceneMesh(const SceneOptions& options, OutputFolder* folder) {
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh;
  std::string what, materials;
  OrientationReport orientation;
  if (options.mesh.empty()) {
    mesh = MakeDemoScene();
    what = "embedded demo scene (torus knot on a ground plane)";
  } else {
    LoadedMesh loaded = LoadObj(options.mesh, options.texture);
    if (folder) {
      for (const std::string& file : loaded.files_read) folder->KeepInput(file);
      for (const std::string& file : loaded.texture_files) folder->KeepInput(file);
    }
    for (const auto& w : loaded.report.warnings) Warn(w);
    what = options.mesh + LoadNotes(loaded.report);
    materials = DescribeMaterials(loaded, options);
    orientation = OrientMesh(loaded.mesh, loaded.normal_from_file);
    mesh = std::move(loaded.mesh);
  }
  Summary("mesh: " + what + ": " + std::to_string(mesh.vertex_count()) + " vertices, " +
          std::to_string(mesh.triangle_count()) + " triangles" + Formatted(" [%.3f s]", SecondsSince(t0)));
  if (!materials.empty()) Summary("materials: " + materials);
  if (mesh.textured() && options.albedo)
    Summary("texture: not used: --albedo " + VecText(*options.albedo) + " replaces the textures of " + options.mesh +
            " (" + DescribeTextures(mesh) + ")");
  else if (mesh.textured())
    Summary("texture: " + DescribeTextures(mesh) +
            "; frames shade each pixel as the texture's albedo times the interpolated irradiance");
  if (!orientation.fixed.empty()) Summary("orientation: " + orientation.fixed);
  if (!orientation.warning.empty()) Warn(options.mesh + ": " + orientation.warning);
  ApplySceneEdits(mesh, options);
  return mesh;
}

void ApplySceneEdits(Mesh& mesh, const SceneOptions& options) {
  if (options.albedo) SetUniformAlbedo(mesh, glm::vec3(*options.albedo));
  if (options.material.glossy && mesh.textured()) {
    FitTexturesBesideCoat(mesh, options.material, options.mesh);
  } else if (options.material.glossy) {  // before any long work: the mesh's own albedo with KS
    float brightest = 0.0f;
    for (const glm::vec3& a : mesh.albedo) brightest = std::max({brightest, a.x, a.y, a.z});
    CheckMaterialEnergy(options.material, brightest,
                        options.albedo ? "--albedo" : options.mesh.empty() ? "the demo scene" : "the brightest Kd of " + options.mesh);
  }
  if (options.max_edge > 0.0) SplitLongTriangles(mesh, options);
}

}  // namespace prt
