#pragma once
/// \file
/// The triangle mesh every stage works on: welded vertices with one normal and one albedo each,
/// and, when textured, texture coordinates per triangle corner and a texture per triangle.
///
/// Vertex order and triangle order are those of the source (OBJ face order for loaded files), so
/// the course's transport format (three rows per triangle, in face order) can be written back.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace prt {

/// A mesh names its textures; texture/texture.h defines them (its users include it).
class Texture;

struct Mesh {
  std::vector<glm::vec3> positions;  ///< world units, Y up
  std::vector<glm::vec3> normals;    ///< unit length, one per vertex
  std::vector<glm::vec3> albedo;     ///< linear RGB in [0,1], one per vertex
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise seen from outside
  /// Every face of the source file in file order, zero-area and collapsed ones included (their
  /// corners' vertices), for formats with one row per file face such as the course's
  /// transport.txt. Empty when the mesh was not read from a file: then `triangles` is it.
  std::vector<std::array<std::uint32_t, 3>> file_triangles;

  /// Texture coordinates, three per triangle: corner c of triangle t at 3 t + c (OBJ's vt, v up).
  /// Per corner, not per vertex: a vertex welded across a UV seam keeps one transport while the
  /// triangles on either side keep their own coordinates. Empty for an untextured mesh.
  std::vector<glm::vec2> corner_uv;
  /// Per triangle, an index into `textures`; empty for an untextured mesh.
  std::vector<std::uint32_t> triangle_texture;
  /// The albedo textures, shared (copying a mesh copies no texels). In a textured mesh every
  /// triangle has one: a material without map_Kd gets a 1 x 1 texture of its Kd. `albedo` then
  /// holds each vertex's mean texture albedo over its corners (geometry/mesh_texture.h).
  std::vector<std::shared_ptr<const Texture>> textures;

  bool textured() const { return !triangle_texture.empty(); }

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
};

/// What loading or building a mesh had to repair, for the run summary.
struct MeshReport {
  std::size_t dropped_degenerate = 0;   ///< zero-area triangles removed
  std::size_t recomputed_normals = 0;   ///< vertices whose normal was missing or zero-length
  std::size_t welded_away = 0;          ///< corners merged into an existing vertex
  /// Lines of the source file that were not understood: not a statement of the format, or (OBJ)
  /// a `v`/`vn` line whose numbers do not all parse. 0 for meshes not read from a file.
  std::size_t skipped_lines = 0;
  std::size_t first_skipped_line = 0;   ///< 1-based line number of the first of them; 0 if none
  std::string first_skipped_text;       ///< its text, cut to about 40 characters, printable
  std::vector<std::string> warnings;    ///< e.g. a material the .mtl does not define
};

}  // namespace prt
