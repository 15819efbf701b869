#include "io/obj_loader.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <istream>
#include <set>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "core/error.h"
#include "core/progress.h"
#include "geometry/mesh_ops.h"
#include "geometry/mesh_texture.h"
#include "geometry/weld.h"
#include "io/material_names.h"
#include "io/obj_materials.h"
#include "io/obj_scan.h"
#include "io/obj_textures.h"

namespace prt {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& problem, const std::string& expected) {
  throw Error(path + ": " + problem + " (expected " + expected + ")");
}

// The progress bar's share of each stage, per byte of the file, from a 100 MB, 1M-triangle OBJ
// (read 0.37 s, mostly page faults of a fresh buffer; scan 0.12 s; tinyobjloader's parse
// 1.2 s; gathering corners 0.3 s and welding 0.3 s), so that the time left it shows is right.
constexpr std::size_t kReadWeight = 3, kScanWeight = 1, kParseWeight = 10, kBuildWeight = 5;
constexpr std::size_t kSlice = std::size_t(1) << 20;  // bytes read or parsed between reports

// The whole file (`size` bytes), read in slices so that a slow disk shows progress.
std::string ReadText(const std::string& path, std::size_t size, const std::function<void(std::size_t)>& advance) {
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, std::string("cannot be opened: ") + std::strerror(errno), "a readable OBJ file");
  std::string text(size, '\0');
  for (std::size_t done = 0; done < size;) {
    const std::size_t n = std::min(kSlice, size - done);
    if (!in.read(text.data() + done, static_cast<std::streamsize>(n)))
      Fail(path, "cannot be read to the end", "a readable OBJ file");
    done += n;
    advance(n);
  }
  return text;
}

// A stream buffer over text in memory that hands it out a slice at a time, reporting each:
// tinyobjloader's parser reads a std::istream and has no progress callback.
class SlicedText : public std::streambuf {
 public:
  SlicedText(std::string& text, std::function<void(std::size_t)> advance)
      : next_(text.data()), end_(text.data() + text.size()), advance_(std::move(advance)) {}

 protected:
  int_type underflow() override {
    if (next_ == end_) return traits_type::eof();
    char* begin = next_;
    next_ += std::min(kSlice, static_cast<std::size_t>(end_ - next_));
    setg(begin, begin, next_);
    advance_(static_cast<std::size_t>(next_ - begin));
    return traits_type::to_int_type(*begin);
  }

 private:
  char* next_;
  char* end_;
  std::function<void(std::size_t)> advance_;
};

// tinyobjloader's warnings in prt's words. The scan has already refused what it reports about
// indices and short faces; a missing library or material is said by WarnMissingMaterials; names
// it could not find at their `usemtl` go to `not_found`; the rest passes on with the path.
void TranslateWarnings(const std::string& path, const std::string& raw, std::set<std::string>& not_found,
                       std::vector<std::string>& warnings) {
  for (const std::string& w : TinyObjLines(raw)) {
    const std::string material = "material [ '";
    if (w.rfind(material, 0) == 0) {
      const std::size_t end = w.rfind("' ]");
      if (end != std::string::npos && end >= material.size())
        not_found.insert(w.substr(material.size(), end - material.size()));
      continue;
    }
    if (w.find("Failed to load material file") != std::string::npos) continue;  // library unread
    if (w.find("empty filename for mtllib") != std::string::npos) continue;     // a skipped line
    if (w.find("Empty group name") != std::string::npos) continue;              // `g` alone: legal
    if (w.find("out of bounds") != std::string::npos || w.find("Degenerated face") != std::string::npos ||
        w.find("invalid vertex index") != std::string::npos)
      Fail(path, "tinyobjloader: " + w, "the indices the scan accepted; please report this file");
    if (w == ".") continue;  // the tail of tinyobjloader's "Degenerated face found\n."
    warnings.push_back(path + ": " + w);
  }
}

}  // namespace

LoadedMesh LoadObj(const std::string& path, const std::string& texture) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) Fail(path, "no such file", "an OBJ mesh");
  if (fs::is_directory(path, ec)) Fail(path, "is a directory", "an OBJ file");
  const std::size_t bytes = static_cast<std::size_t>(fs::file_size(path, ec));
  if (ec) Fail(path, "cannot be read: " + ec.message(), "a readable OBJ file");
  Progress progress("loading " + fs::path(path).filename().string(),
                    bytes * (kReadWeight + kScanWeight + kParseWeight + kBuildWeight));

  // Read once; check the text (finite coordinates, indices as written, lines not understood).
  std::string text = ReadText(path, bytes, [&](std::size_t n) { progress.Advance(n * kReadWeight); });
  const ObjScan scan = ScanObj(text, path, [&](std::size_t n) { progress.Advance(n * kScanWeight); });
  LoadedMesh out;
  out.report.skipped_lines = scan.skipped_lines;
  out.report.first_skipped_line = scan.first_skipped_line;
  out.report.first_skipped_text = scan.first_skipped_text;

  // Parse and triangulate from memory; libraries are read by MaterialLibraries. Names with
  // blanks are handed over with their blanks hidden, and shown again after (material_names.h).
  HideNameBlanks(text, "usemtl");
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  MaterialLibraries libraries(path, scan.mtllib_lines);
  std::string raw_warnings, raw_errors;
  {
    SlicedText buffer(text, [&](std::size_t n) { progress.Advance(n * kParseWeight); });
    std::istream stream(&buffer);
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &raw_warnings, &raw_errors, &stream, &libraries,
                          /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
      const auto lines = TinyObjLines(raw_errors);
      Fail(path, lines.empty() ? "cannot be parsed" : "tinyobjloader: " + lines.front(), "a Wavefront OBJ file");
    }
  }
  text = std::string();  // the text is no longer needed: free it before building the mesh
  for (tinyobj::material_t& m : materials) m.name = ShowNameBlanks(std::move(m.name));
  std::set<std::string> not_found;
  TranslateWarnings(path, ShowNameBlanks(raw_warnings), not_found, out.report.warnings);
  for (const std::string& r : libraries.remarks()) out.report.warnings.push_back(r);
  out.files_read.push_back(path);
  for (const std::string& library : libraries.read_paths()) out.files_read.push_back(library);
  if (texture.empty())  // --texture replaces every material's colour: none is missing then
    WarnMissingMaterials(path, scan.faces_by_material, materials, libraries, not_found, out.report.warnings);
  const std::vector<glm::vec3> albedos = MaterialAlbedos(materials, path, out.report.warnings);
  out.material_fields = FindMaterialFields(libraries, materials, scan.faces_by_material);
  auto albedo_of = [&](int id) {
    return id < 0 || static_cast<std::size_t>(id) >= albedos.size() ? glm::vec3(kDefaultAlbedo)
                                                                     : albedos[static_cast<std::size_t>(id)];
  };
  if (!texture.empty() && attrib.texcoords.empty())
    Fail(path, "has no texture coordinates (vt lines) for --texture " + texture, "an OBJ with vt coordinates on its faces");
  ObjTextures textures(materials, libraries.material_folders(), albedos, libraries.map_kd_options(), texture, path);
  const auto texcoord_count = static_cast<int>(attrib.texcoords.size() / 2);

  // Gather the triangles' corners. The scan checked the indices on the text; the two checks
  // below only confirm that tinyobjloader resolved them alike (they guard memory, not input).
  const auto vertex_count = static_cast<int>(attrib.vertices.size() / 3);
  const auto normal_count = static_cast<int>(attrib.normals.size() / 3);
  std::size_t corners = 0;
  for (const auto& shape : shapes) corners += shape.mesh.indices.size() / 3 * 3;
  CornerSoup soup;
  soup.positions.reserve(corners), soup.normals.reserve(corners), soup.ids.reserve(corners), soup.albedo.reserve(corners);
  if (textures.active()) soup.uv.reserve(corners), soup.texture.reserve(corners / 3);
  // Progress: half of the build stage for gathering, half for welding.
  const std::size_t build_units = bytes * kBuildWeight;
  std::size_t build_reported = 0;
  std::size_t faces = 0, zero_normals = 0;
  for (const auto& shape : shapes) {
    const auto& idx = shape.mesh.indices;
    for (std::size_t f = 0; f * 3 + 2 < idx.size(); ++f) {
      if (++faces % 65536 == 0) {
        const std::size_t units = build_units / 2 * (3 * faces) / corners;
        progress.Advance(units - build_reported);
        build_reported = units;
      }
      glm::dvec3 p[3];
      for (int c = 0; c < 3; ++c) {
        const tinyobj::index_t& i = idx[f * 3 + c];
        if (i.vertex_index < 0 || i.vertex_index >= vertex_count)
          Fail(path, "triangle " + std::to_string(faces) + " uses vertex " + std::to_string(i.vertex_index + 1) +
                         " of " + std::to_string(vertex_count), "tinyobjloader to resolve indices as the scan does");
        if (i.normal_index < -1 || i.normal_index >= normal_count)
          Fail(path, "triangle " + std::to_string(faces) + " uses normal " + std::to_string(i.normal_index + 1) +
                         " of " + std::to_string(normal_count), "tinyobjloader to resolve indices as the scan does");
        p[c] = glm::dvec3(attrib.vertices[3 * i.vertex_index], attrib.vertices[3 * i.vertex_index + 1],
                          attrib.vertices[3 * i.vertex_index + 2]);
      }
      // Zero-area faces go on into the soup: the welder drops them from the triangles but
      // keeps them in file_triangles, so per-face outputs still have a row for every face.
      const int material = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[f];
      const glm::vec3 albedo = albedo_of(material);
      if (textures.active()) {
        // Corners without a vt (or with an index tinyobjloader did not resolve) have none.
        bool has_uv = true;
        for (int c = 0; c < 3; ++c) {
          const int t = idx[f * 3 + c].texcoord_index;
          has_uv = has_uv && t >= 0 && t < texcoord_count;
          soup.uv.push_back(has_uv ? textures.MapUv(material, glm::vec2(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]))
                                   : glm::vec2(0.f));
        }
        soup.texture.push_back(textures.ForFace(material, has_uv));
      }
      for (int c = 0; c < 3; ++c) {
        const tinyobj::index_t& i = idx[f * 3 + c];
        soup.positions.emplace_back(p[c]);
        glm::vec3 n(0.0f);
        if (i.normal_index >= 0) {
          n = glm::vec3(attrib.normals[3 * i.normal_index], attrib.normals[3 * i.normal_index + 1],
                        attrib.normals[3 * i.normal_index + 2]);
          const float len = glm::length(n);
          if (len > 0.0f) n /= len;
          else zero_normals += 1;  // recomputed by the welder as a corner without a normal
        }
        soup.normals.push_back(n);
        soup.ids.push_back(static_cast<std::uint64_t>(i.vertex_index) << 32 | static_cast<std::uint32_t>(i.normal_index));
        soup.albedo.push_back(albedo);
      }
    }
  }
  if (faces == 0) {
    const std::string skipped = out.report.skipped_lines ? "; " + DescribeSkippedLines(out.report) : "";
    Fail(path, "no faces" + skipped, "at least one triangle");
  }
  if (zero_normals > 0)
    out.report.warnings.push_back(path + ": " + std::to_string(zero_normals) +
                                  (zero_normals == 1 ? " corner has a zero-length normal" : " corners have zero-length normals") +
                                  " (recomputed)");

  // Weld (normal-less corners within a tolerance relative to the mesh size).
  Bounds3 box;
  for (const glm::vec3& q : soup.positions) box.Extend(q);
  const float tolerance = kWeldRelativeTolerance * glm::length(box.hi - box.lo);
  WeldedMesh welded = WeldCorners(soup, tolerance, out.report);
  progress.Advance(build_units - build_reported);
  out.mesh = std::move(welded.mesh);
  if (textures.active()) {
    out.mesh.textures = textures.TakeTextures();
    SetVertexAlbedoFromTextures(out.mesh);
    for (std::string& w : textures.Warnings()) out.report.warnings.push_back(std::move(w));
    out.texture_files = textures.Files();
  }
  out.normal_from_file = std::move(welded.normal_from_file);
  if (out.mesh.triangles.empty())
    Fail(path, "all " + std::to_string(faces) + " faces have zero area or collapse when welding",
         "at least one non-degenerate triangle");
  return out;
}

std::string DescribeSkippedLines(const MeshReport& report) {
  if (report.skipped_lines == 0) return {};
  return std::to_string(report.skipped_lines) + (report.skipped_lines == 1 ? " line" : " lines") +
         " not understood, skipped (first: line " + std::to_string(report.first_skipped_line) + ": '" +
         report.first_skipped_text + "')";
}

}  // namespace prt
