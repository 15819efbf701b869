// Glossy materials from the command line: --material values, the energy refusal, the
// --vertex-radiance file, --orbit's transfer matrices and their memory refusal, and
// precompute's transfer_matrices.bin.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <glm/vec3.hpp>

#include "precompute_io/transfer_matrix_file.h"
#include "tests/test_process.h"

using namespace prt;
using namespace prt::test;

namespace {

/// The rows of a --vertex-radiance file after its count line (which goes to `count`).
std::vector<glm::dvec3> ReadVertexRadiance(const std::string& path, long& count) {
  std::ifstream in(path);
  std::string line;
  REQUIRE(std::getline(in, line));
  count = std::stol(line);
  std::vector<glm::dvec3> rows;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    glm::dvec3 c;
    std::string extra;
    REQUIRE_MESSAGE(bool(fields >> c.x >> c.y >> c.z), line);
    REQUIRE_MESSAGE(!(fields >> extra), line);  // exactly three numbers a row
    rows.push_back(c);
  }
  return rows;
}

/// A small tetrahedron (no normals in the file): every run on it takes a fraction of a second.
std::string Tetrahedron() { return "--mesh " + Q(Fixture("obj/tetra_no_normals.obj")); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("--material: a malformed value is a usage error, albedo + KS > 1 is refused before any work") {
    RunResult r = RunPrt("render --material phong:0 --out " + Q(ScratchDir("glossy_bad")));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--material: 'phong:0'") != std::string::npos);
    r = RunPrt("render --material shiny --out " + Q(ScratchDir("glossy_bad")));
    CHECK(r.exit_code == 2);
    r = RunPrt("render --material phong:10,0.5 --albedo 0.6,0.2,0.2 --out " + Q(ScratchDir("glossy_bad")));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("exceeds 1") != std::string::npos);
    // The demo scene's own albedo (0.8) with KS 0.5: a failure naming it, before the light.
    r = RunPrt("render --material phong:10,0.5 --frames 1 --out " + Q(ScratchDir("glossy_bad")));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("the demo scene") != std::string::npos);
    CHECK(r.err.find("light:") == std::string::npos);
  }

  TEST_CASE("--vertex-radiance: the count line, three R G B rows per face, the furnace's closed forms") {
    const std::string dir = ScratchDir("vertex_radiance");
    // Diffuse, unshadowed, furnace light 1: every corner's radiance is its albedo exactly.
    RunResult r = RunPrt("render --quiet " + Tetrahedron() + " --env furnace --transport unshadowed --albedo 0.25,0.5,0.75 "
                         "--frames 1 --size 16x16 --out " + Q(dir + "/d") + " --vertex-radiance " + Q(dir + "/d.txt"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    long count = 0;
    const std::vector<glm::dvec3> diffuse = ReadVertexRadiance(dir + "/d.txt", count);
    CHECK(count > 0);
    CHECK(diffuse.size() % 3 == 0);
    CHECK(diffuse.size() >= 3 * 4);  // a tetrahedron: four faces or more
    for (const auto& c : diffuse) {
      CHECK(c.x == doctest::Approx(0.25).epsilon(1e-6));
      CHECK(c.y == doctest::Approx(0.5).epsilon(1e-6));
      CHECK(c.z == doctest::Approx(0.75).epsilon(1e-6));
    }
    // phong:1,0.2: albedo + 0.2 (sin g + (pi - g) cos g)/pi, between albedo and albedo + 0.2,
    // the same for each channel.
    r = RunPrt("render --quiet " + Tetrahedron() + " --env furnace --transport unshadowed --albedo 0.25,0.5,0.75 "
               "--material phong:1,0.2 --frames 1 --size 16x16 --out " + Q(dir + "/g") + " --vertex-radiance " +
               Q(dir + "/g.txt"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const std::vector<glm::dvec3> glossy = ReadVertexRadiance(dir + "/g.txt", count);
    REQUIRE(glossy.size() == diffuse.size());
    double most = 0.0;
    for (std::size_t i = 0; i < glossy.size(); ++i) {
      const glm::dvec3 added = glossy[i] - diffuse[i];
      CHECK(added.x >= -1e-6);
      CHECK(added.x <= 0.2 + 1e-6);
      CHECK(added.y == doctest::Approx(added.x).epsilon(1e-5));
      CHECK(added.z == doctest::Approx(added.x).epsilon(1e-5));
      most = std::max(most, added.x);
    }
    CHECK(most > 0.05);  // the faces that face the camera get a good part of KS
  }

  TEST_CASE("--vertex-radiance: row i belongs to corner i of the file's faces") {
    // A floor and a wall of different colours under furnace light, unshadowed: every corner's
    // radiance is its own albedo, so the floor's faces (first in the file) give the floor's
    // colour and the wall's the wall's. Rows in any other order would mix them.
    const std::string dir = ScratchDir("vertex_radiance_order");
    const glm::vec3 floor_kd(0.2f, 0.4f, 0.6f), wall_kd(0.7f, 0.5f, 0.1f);
    const std::string obj = WriteFloorAndWall(dir, floor_kd, wall_kd);
    const RunResult r = RunPrt("render --quiet --mesh " + Q(obj) + " --env furnace --transport unshadowed --frames 1 "
                               "--size 16x16 --out " + Q(dir + "/out") + " --vertex-radiance " + Q(dir + "/v.txt"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    long count = 0;
    const std::vector<glm::dvec3> rows = ReadVertexRadiance(dir + "/v.txt", count);
    REQUIRE(rows.size() == 3 * (FloorTriangles() + WallTriangles()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const glm::vec3 kd = i < 3 * FloorTriangles() ? floor_kd : wall_kd;
      CAPTURE(i);
      CHECK(glm::length(rows[i] - glm::dvec3(kd)) < 1e-6);
    }
  }

  TEST_CASE("--orbit: glossy frames come from transfer matrices, frame 0 close to the fixed camera's") {
    const std::string dir = ScratchDir("orbit");
    const std::string scene = Tetrahedron() + " --env sky --albedo 0.5,0.5,0.5 --material phong:2,0.4 --transport unshadowed";
    RunResult fixed = RunPrt("render " + scene + " --frames 2 --size 32x32 --exposure 0 --out " + Q(dir + "/f") +
                             " --vertex-radiance " + Q(dir + "/f.txt"));
    REQUIRE_MESSAGE(fixed.exit_code == 0, fixed.err);
    CHECK(fixed.err.find("fixed camera: one view-dependent transfer vector per vertex") != std::string::npos);
    RunResult orbit = RunPrt("render " + scene + " --frames 2 --size 32x32 --exposure 0 --orbit 90 --out " + Q(dir + "/o") +
                             " --vertex-radiance " + Q(dir + "/o.txt"));
    REQUIRE_MESSAGE(orbit.exit_code == 0, orbit.err);
    CHECK(orbit.err.find("transfer matrices for a view that moves") != std::string::npos);
    long count = 0;
    const auto a = ReadVertexRadiance(dir + "/f.txt", count), b = ReadVertexRadiance(dir + "/o.txt", count);
    REQUIRE(a.size() == b.size());
    // Tolerance: the matrices truncate V L cos to lmax 2 before a lobe whose bands go on (phong:2
    // keeps 3.1% of its energy above band 2, LobeBandShare); unshadowed here, so only that truncation differs.
    double worst = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[i][c] - b[i][c])), peak = std::max(peak, a[i][c]);
    CHECK(worst < 0.05 * peak);
    // The second frame is seen from elsewhere: it differs from the fixed camera's second frame.
    const RunResult diff = RunPrt("diff " + Q(dir + "/f/frame_0001.png") + " " + Q(dir + "/o/frame_0001.png"));
    CHECK(diff.exit_code == 1);
  }

  TEST_CASE("--orbit: matrices that would not fit in memory are refused at once, naming an lmax that fits") {
    const RunResult r = RunPrt("render --material phong:10,0.2 --albedo 0.5,0.5,0.5 --orbit 30 --lmax 64 --out " +
                               Q(ScratchDir("orbit_memory")));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("transfer matrices would take") != std::string::npos);
    CHECK(r.err.find("or lower") != std::string::npos);
    CHECK(r.err.find("light:") == std::string::npos);  // refused before the light was loaded
  }

  TEST_CASE("precompute --material phong writes transfer_matrices.bin that reads back") {
    const std::string dir = ScratchDir("precompute_glossy");
    const RunResult r = RunPrt("precompute --quiet " + Tetrahedron() + " --env furnace --albedo 0.5,0.5,0.5 --material phong:7,0.25 "
                               "--out " + Q(dir));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const TransferMatrixFile f = ReadTransferMatrixFile(dir + "/transfer_matrices.bin");
    CHECK(f.exponent == 7);
    CHECK(f.ks == 0.25);
    CHECK(f.lmax == 2);
    CHECK(f.positions.size() > 0);
    CHECK(std::filesystem::exists(dir + "/transport.txt"));
  }
}
