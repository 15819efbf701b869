#pragma once
// Helpers for the environment tests: environments sampled from a function, in memory.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/atomic_file.h"
#include "env/cubemap.h"
#include "env/equirect.h"
#include "io/hdr_writer.h"
#include "io/png_io.h"

namespace prt::test {

/// Writes `path` (its folder created) as a w x h PNG of one grey level; returns `path`.
inline std::string WriteGreyPng(const std::string& path, int w, int h, std::uint8_t level = 128) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  Image8 image(w, h);
  for (auto& v : image.rgb) v = level;
  WritePng(path, image);
  return path;
}

/// Writes a cube map folder `dir` of six size^2 grey PNG faces (kFaceNames), leaving out the
/// face named `skip`; returns `dir`.
inline std::string WritePngCube(const std::string& dir, int size, const std::string& skip = "") {
  for (const char* face : kFaceNames)
    if (skip != face) WriteGreyPng(dir + "/" + face + ".png", size, size);
  return dir;
}

using RadianceFn = std::function<glm::dvec3(const glm::dvec3&)>;

inline std::unique_ptr<CubemapEnvironment> CubemapFrom(const RadianceFn& f, int size,
                                                       CubeLayout layout = CubeLayout::kStandard) {
  return CubemapFromFunction(f, size, layout);
}

inline std::unique_ptr<EquirectEnvironment> EquirectFrom(const RadianceFn& f, int width, int height) {
  return EquirectFromFunction(f, width, height);
}

/// Writes a cube map folder `dir` of six size^2 .hdr faces (kFaceNames order) whose texel
/// (col, row) of face k holds texel(k, row, col); returns `dir`. RGBE stores small integers and
/// powers of two exactly.
inline std::string WriteHdrCube(const std::string& dir, int size,
                                const std::function<glm::vec3(int face, int row, int col)>& texel) {
  std::filesystem::create_directories(dir);
  for (int k = 0; k < 6; ++k) {
    ImageF face(size, size);
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) face.at(col, row) = texel(k, row, col);
    WriteFileAtomic(dir + "/" + kFaceNames[k] + ".hdr", EncodeHdr(face));
  }
  return dir;
}

/// Where a direction lands on a cube map by the OpenGL specification (4.6 core, table 8.19,
/// "Selection of cube map images"), written out independently of env/cube_faces.cpp: the face
/// (posx negx posy negy posz negz = 0..5) is the major axis, and the texel coordinates are
/// s = (sc / |ma| + 1) / 2 along the image's columns, t = (tc / |ma| + 1) / 2 along its rows
/// (row 0 first in the file).
struct CubeTexel {
  int face = 0;
  double s = 0, t = 0;
};

inline CubeTexel OpenGlCubeTexel(const glm::dvec3& d) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  int face;
  double sc, tc, ma;
  if (ax >= ay && ax >= az) {
    face = d.x > 0 ? 0 : 1, sc = d.x > 0 ? -d.z : d.z, tc = -d.y, ma = ax;
  } else if (ay >= az) {
    face = d.y > 0 ? 2 : 3, sc = d.x, tc = d.y > 0 ? d.z : -d.z, ma = ay;
  } else {
    face = d.z > 0 ? 4 : 5, sc = d.z > 0 ? d.x : -d.x, tc = -d.y, ma = az;
  }
  return {face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0)};
}

/// The direction through (s, t) of `face` by the same table, inverted.
inline glm::dvec3 OpenGlCubeDirection(int face, double s, double t) {
  const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
  switch (face) {
    case 0: return {1.0, -tc, -sc};
    case 1: return {-1.0, -tc, sc};
    case 2: return {sc, 1.0, tc};
    case 3: return {sc, -1.0, -tc};
    case 4: return {sc, -tc, 1.0};
    default: return {-sc, -tc, -1.0};
  }
}

}  // namespace prt::test
