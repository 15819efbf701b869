// The course workflow through the binary: the files `prt precompute` writes are read the way the
// course's WebGL viewer reads them (header line ignored, rows split on single spaces, exactly 9
// numbers a row), coloured interreflection still gives a transport.txt the viewer loads beside
// the exact per-channel files, an lmax the viewer cannot read is said, and a material the .mtl
// does not define is one warning in prt's words.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/atomic_file.h"
#include "geometry/procedural.h"
#include "io/obj_writer.h"
#include "tests/test_support.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

using test::Q;

// The files hold 7 significant digits (transport_txt.h): a value and a mix of three of them
// agree to a few units of the 7th digit.
constexpr double kPrintedRelative = 2e-6;
constexpr double kPrintedAbsolute = 1e-7;

enum class Header { kSkip, kNone };

/// A file read as the course's viewer reads it: transport.txt's header line skipped (light.txt
/// has none), each further non-empty line split on single spaces into numbers. A row that would
/// not give exactly `per_row` numbers (an empty field from a double or trailing space, a token
/// that is not a number) fails.
std::vector<std::vector<double>> ReadLikeTheViewer(const std::string& path, std::size_t per_row,
                                                   Header header = Header::kSkip) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::string line;
  if (header == Header::kSkip) std::getline(in, line);  // the vertex count: the viewer ignores it
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::size_t start = 0;
    for (;;) {
      const std::size_t space = line.find(' ', start);
      const std::string token = line.substr(start, space == std::string::npos ? std::string::npos : space - start);
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      CAPTURE(line);
      REQUIRE_FALSE(token.empty());
      REQUIRE(*end == '\0');
      row.push_back(v);
      if (space == std::string::npos) break;
      start = space + 1;
    }
    CAPTURE(line);
    REQUIRE(row.size() == per_row);
    rows.push_back(row);
  }
  return rows;
}

/// A white floor (side 2, 8 x 8 quads, first in the file) beside a red wall at x = -1: the
/// floor receives red light from the wall after one bounce, nothing else.
std::string WriteRedWallScene(const std::string& dir) {
  ObjPart floor{"floor", MakePlane(2.0f, 8), glm::vec3(0.9f)};
  ObjPart wall{"wall", MakeBox(glm::vec3(-1.2f, 0.0f, -1.0f), glm::vec3(-1.0f, 1.5f, 1.0f), BoxFacing::kOutward, 4),  // WallFaces()
               glm::vec3(0.9f, 0.1f, 0.1f)};
  WriteFileAtomic(dir + "/scene.obj", FormatObj({floor, wall}, "scene.mtl"));
  WriteFileAtomic(dir + "/scene.mtl", FormatMtl({floor, wall}));
  return dir + "/scene.obj";
}

std::size_t FloorFaces() { return MakePlane(2.0f, 8).triangle_count(); }
std::size_t WallFaces() { return MakeBox(glm::vec3(0.0f), glm::vec3(1.0f), BoxFacing::kOutward, 4).triangle_count(); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("course files: coloured interreflection writes a transport.txt the viewer loads, and the exact channels") {
    const std::string dir = test::ScratchDir("course_colour");
    const std::string mesh = WriteRedWallScene(dir);
    const std::string out = dir + "/out";
    const auto r = test::RunPrt("precompute --mesh " + Q(mesh) +
                                " --env furnace --transport interreflection --samples 256 --out " + Q(out));
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("luminance-weighted mix 0.2126 R + 0.7152 G + 0.0722 B") != std::string::npos);

    const auto light = ReadLikeTheViewer(out + "/light.txt", 3, Header::kNone);
    CHECK(light.size() == 9);
    const auto mix = ReadLikeTheViewer(out + "/transport.txt", 9);
    const auto red = ReadLikeTheViewer(out + "/transport_r.txt", 9);
    const auto green = ReadLikeTheViewer(out + "/transport_g.txt", 9);
    const auto blue = ReadLikeTheViewer(out + "/transport_b.txt", 9);
    REQUIRE(mix.size() == 3 * (FloorFaces() + WallFaces()));
    REQUIRE(red.size() == mix.size());
    REQUIRE(green.size() == mix.size());
    REQUIRE(blue.size() == mix.size());
    for (std::size_t i = 0; i < mix.size(); ++i)
      for (std::size_t k = 0; k < 9; ++k) {
        const double expected = 0.2126 * red[i][k] + 0.7152 * green[i][k] + 0.0722 * blue[i][k];
        CAPTURE(i);
        CAPTURE(k);
        REQUIRE(std::abs(mix[i][k] - expected) <= kPrintedAbsolute + kPrintedRelative * std::abs(expected));
      }

    // Colour bleeding: the floor (its rows come first) receives more red than green or blue,
    // and green and blue alike (the wall reflects both at 0.1). The floor's own albedo is not in
    // the transport; the red it receives is 0.9 wall albedo times what it sees of the wall.
    double floor_r = 0.0, floor_g = 0.0, floor_b = 0.0;
    for (std::size_t i = 0; i < 3 * FloorFaces(); ++i) floor_r += red[i][0], floor_g += green[i][0], floor_b += blue[i][0];
    CHECK(floor_r > 1.05 * floor_b);
    CHECK(std::abs(floor_g - floor_b) <= 1e-6 * std::abs(floor_b));
  }

  TEST_CASE("course files: grey albedo writes one transport.txt and no channel files") {
    const std::string dir = test::ScratchDir("course_grey");
    const std::string mesh = WriteRedWallScene(dir);
    const auto r = test::RunPrt("precompute --mesh " + Q(mesh) + " --albedo 0.5,0.5,0.5 --env furnace " +
                                "--transport interreflection --samples 64 --out " + Q(dir + "/out"));
    REQUIRE(r.exit_code == 0);
    CHECK(ReadLikeTheViewer(dir + "/out/transport.txt", 9).size() == 3 * (FloorFaces() + WallFaces()));
    CHECK_FALSE(fs::exists(dir + "/out/transport_r.txt"));
  }

  TEST_CASE("course files: an lmax the viewer cannot read is said, lmax 2 is not") {
    const std::string dir = test::ScratchDir("course_lmax");
    const std::string base = "precompute --mesh " + Q(test::Fixture("obj/tetra_no_normals.obj")) +
                             " --env furnace --transport unshadowed --out " + Q(dir);
    const auto three = test::RunPrt(base + " --lmax 3");
    CAPTURE(three.err);
    CHECK(three.exit_code == 0);
    const std::size_t warning = three.err.find("prt: warning: lmax 3: these files will have 16 numbers per row, but "
                                                "the course's WebGL viewer reads exactly 9");
    CHECK(warning != std::string::npos);
    CHECK(warning < three.err.find("mesh: "));  // said before any work
    CHECK(ReadLikeTheViewer(dir + "/transport.txt", 16).size() == 12);
    const auto two = test::RunPrt(base + " --lmax 2");
    CHECK(two.exit_code == 0);
    CHECK(two.err.find("viewer") == std::string::npos);
    CHECK(ReadLikeTheViewer(dir + "/transport.txt", 9).size() == 12);
  }

  TEST_CASE("course files: a material the .mtl does not define is one warning in prt's words") {
    const auto r = test::RunPrt("precompute --mesh " + Q(test::Fixture("obj/missing_material.obj")) +
                                " --env furnace --transport unshadowed --out " + Q(test::ScratchDir("course_mtl")));
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("not found in .mtl") == std::string::npos);  // tinyobjloader's own words
    const std::size_t first = r.err.find("is not defined in missing_material.mtl");
    CHECK(first != std::string::npos);
    CHECK(r.err.find("is not defined in", first + 1) == std::string::npos);
  }

  TEST_CASE("course files: mary's undefined material is said once, and her files load in the viewer" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    const std::string out = test::ScratchDir("course_mary");
    const auto r = test::RunPrt("precompute --mesh " + Q(data + "/games202/mary/mary.obj") + " --env " +
                                Q(data + "/games202/cubemap/GraceCathedral") + " --samples 64 --out " + Q(out));
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("not found in .mtl") == std::string::npos);
    const std::string said = "material 'MC003_Kozakura_Mari' is not defined in mary.mtl";
    const std::size_t first = r.err.find(said);
    CHECK(first != std::string::npos);
    CHECK(r.err.find("MC003_Kozakura_Mari", first + said.size()) == std::string::npos);
    CHECK(ReadLikeTheViewer(out + "/transport.txt", 9).size() == 30522);  // three rows per face of the file
    CHECK(ReadLikeTheViewer(out + "/light.txt", 3, Header::kNone).size() == 9);
  }
}

}  // namespace prt
