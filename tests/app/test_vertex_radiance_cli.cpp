// render --vertex-radiance writes what frame 0 shades, a row per corner of each face of the mesh
// as read: its light turned by --start-angle (checked against the light turned by other means:
// the scene turned the other way, a closed form of diffuse unshadowed shading), and its rows
// those of the file's faces when --max-edge splits them (checked against the run without the
// split, where the corners' transport is the same). Both bases.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/atomic_file.h"
#include "geometry/procedural.h"
#include "io/obj_writer.h"
#include "tests/test_process.h"

namespace prt {
namespace {

/// A --vertex-radiance file: its count line and its rows.
struct RadianceFile {
  long count = 0;
  std::vector<glm::dvec3> rows;
};

RadianceFile ReadRadiance(const std::string& path) {
  RadianceFile f;
  std::ifstream in(path);
  std::string line;
  REQUIRE_MESSAGE(std::getline(in, line), path);
  f.count = std::stol(line);
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    glm::dvec3 c;
    REQUIRE_MESSAGE(bool(fields >> c.x >> c.y >> c.z), line);
    f.rows.push_back(c);
  }
  return f;
}

/// The largest difference of any channel of any row, and the largest value (same row counts).
struct Difference {
  double worst = 0.0, peak = 0.0;
};

Difference Compare(const RadianceFile& a, const RadianceFile& b) {
  Difference d;
  REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    for (int c = 0; c < 3; ++c)
      d.worst = std::max(d.worst, std::abs(a.rows[i][c] - b.rows[i][c])), d.peak = std::max(d.peak, a.rows[i][c]);
  return d;
}

/// The small scene's parts (test::WriteSmallScene's: a knot on a 6 x 6 ground), turned a quarter
/// turn about +Y by R(-90 degrees): (x, y, z) -> (-z, y, x), exact in float and in the OBJ's text.
/// Written as dir/NAME.obj; returns its path.
std::string WriteSmallScene(const std::string& dir, const std::string& name, bool turned) {
  Mesh knot = MakeTorusKnot(2, 3, 0.16f, 32, 6);
  StandUpright(knot, 3.4f);
  std::vector<ObjPart> parts = {{"ground", MakePlane(12.0f, 6), glm::vec3(0.7f)},
                                {"knot", knot, glm::vec3(0.80f, 0.38f, 0.20f)}};
  if (turned)
    for (ObjPart& part : parts) {
      for (glm::vec3& p : part.mesh.positions) p = glm::vec3(-p.z, p.y, p.x);
      for (glm::vec3& n : part.mesh.normals) n = glm::vec3(-n.z, n.y, n.x);
    }
  WriteFileAtomic(dir + "/" + name + ".obj", FormatObj(parts, name + ".mtl"));
  WriteFileAtomic(dir + "/" + name + ".mtl", FormatMtl(parts));
  return dir + "/" + name + ".obj";
}

/// The OBJ's face count (its `f` lines: FormatObj writes triangles).
/// The lines of `obj` that start with `prefix`.
std::size_t LinesStarting(const std::string& obj, const std::string& prefix) {
  std::ifstream in(obj);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

std::size_t FaceLines(const std::string& obj) { return LinesStarting(obj, "f "); }

/// Runs `render` and returns its run summary; the run must succeed.
std::string Render(const std::string& args) {
  const test::RunResult r = test::RunPrt("render " + args);
  const std::string what = args + "\n" + r.err;
  REQUIRE_MESSAGE(r.exit_code == 0, what);
  return r.err;
}

// Diffuse unshadowed shading under a light turned by R, L'(d) = L(R^T d), is at a normal n what
// the unturned light gives at R^T n: the same integral of L times the clamped cosine. The
// scene turned by R^T under the unturned light must therefore write the same file, corner for
// corner (the turned OBJ keeps the face order). Measured 1.0e-7 of the peak (SH: the band
// rotation in float) and 5.3e-7 (wavelets: a quarter turn about +Y takes the cube's texels onto
// texels, so only the sums' rounding differs); the light left unturned is off by 0.56 (SH) and
// 0.62 (wavelets) of the peak, a turn the wrong way by 0.72 and 0.71.
constexpr double kTurnedSceneTolerance = 1e-5;

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("--vertex-radiance: frame 0's light, turned by --start-angle, in both bases") {
    const std::string dir = test::ScratchDir("vertex_radiance_start_angle");
    const std::string scene = WriteSmallScene(dir, "scene", false), turned = WriteSmallScene(dir, "turned", true);
    for (const std::string basis : {"sh", "wavelet"}) {
      CAPTURE(basis);
      const std::string run = " --basis " + basis + " --transport unshadowed --env sky --frames 1 --size 24x16 --quiet";
      const std::string a = dir + "/" + basis + "_start90.txt", b = dir + "/" + basis + "_turned.txt",
                        c = dir + "/" + basis + "_unturned.txt";
      Render("--mesh " + test::Q(scene) + run + " --start-angle 90 --out " + test::Q(dir + "/" + basis + "_a") +
             " --vertex-radiance " + test::Q(a));
      Render("--mesh " + test::Q(turned) + run + " --out " + test::Q(dir + "/" + basis + "_b") +
             " --vertex-radiance " + test::Q(b));
      Render("--mesh " + test::Q(scene) + run + " --out " + test::Q(dir + "/" + basis + "_c") + " --vertex-radiance " +
             test::Q(c));
      const RadianceFile start = ReadRadiance(a), by_scene = ReadRadiance(b), unturned = ReadRadiance(c);
      CHECK(start.count == by_scene.count);
      const Difference same = Compare(start, by_scene), moved = Compare(start, unturned);
      INFO(basis << ": --start-angle 90 against the scene turned back: " << same.worst / same.peak
                 << " of the peak; against the light unturned: " << moved.worst / moved.peak);
      CHECK(same.peak > 0.1);
      CHECK(same.worst <= kTurnedSceneTolerance * same.peak);
      CHECK(moved.worst > 0.1 * moved.peak);  // the sky's sun moved a quarter turn
    }
  }

  TEST_CASE("--vertex-radiance with --max-edge: a row per corner of the faces as read, the corners' own radiance") {
    // Unshadowed, each vertex's transport is its normal's alone (closed form for SH, the exact
    // clamped cosine per texel for wavelets), and the split adds vertices without touching the
    // others: the file must be the unsplit run's, byte for byte, whatever the split added.
    const std::string dir = test::ScratchDir("vertex_radiance_max_edge");
    const std::string scene = WriteSmallScene(dir, "scene", false);
    const std::size_t faces = FaceLines(scene);
    REQUIRE(faces > 100);
    for (const std::string basis : {"sh", "wavelet"}) {
      CAPTURE(basis);
      const std::string run = "--mesh " + test::Q(scene) + " --basis " + basis +
                              " --transport unshadowed --env sky --frames 1 --size 24x16 --start-angle 30";
      const std::string whole = dir + "/" + basis + "_whole.txt", split = dir + "/" + basis + "_split.txt";
      Render(run + " --quiet --out " + test::Q(dir + "/" + basis + "_w") + " --vertex-radiance " + test::Q(whole));
      const std::string summary = Render(run + " --max-edge 0.5 --out " + test::Q(dir + "/" + basis + "_s") +
                                         " --vertex-radiance " + test::Q(split));
      CAPTURE(summary);
      CHECK(summary.find("split: no edge longer than 0.5") != std::string::npos);
      CHECK(summary.find("vertices --max-edge added are not in it") != std::string::npos);
      const RadianceFile a = ReadRadiance(whole), b = ReadRadiance(split);
      CHECK(a.count == static_cast<long>(LinesStarting(scene, "v ")));  // every vertex of the file is a face's corner
      CHECK(a.rows.size() == 3 * faces);
      CHECK(b.rows.size() == 3 * faces);
      CHECK(b.count == a.count);
      CHECK(ReadFile(split) == ReadFile(whole));
      // The summary counts what the file holds: the vertices as read, not the split mesh's.
      CHECK(summary.find("radiance of " + std::to_string(b.count) + " vertices toward the camera") != std::string::npos);
    }
  }
}

}  // namespace prt
