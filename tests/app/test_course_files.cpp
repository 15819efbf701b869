// The course workflow through the binary: the files `prt precompute` writes are read the way the
// course's WebGL viewer reads them (header line ignored, rows split on single spaces, exactly 9
// numbers a row), coloured interreflection still gives a transport.txt the viewer loads beside
// the exact per-channel files, an lmax the viewer cannot read is said, and a material the .mtl
// does not define is one warning in prt's words.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/atomic_file.h"
#include "tests/app/viewer_files.h"
#include "tests/env/env_test_util.h"
#include "tests/test_process.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

using test::Q;

// The files hold 7 significant digits (transport_txt.h): a value and a mix of three of them
// agree to a few units of the 7th digit.
constexpr double kPrintedRelative = 2e-6;
constexpr double kPrintedAbsolute = 1e-7;

/// WriteFloorAndWall with a white floor and an orange wall (0.9, 0.5, 0.1: every channel its own).
std::string WriteWallScene(const std::string& dir) {
  return test::WriteFloorAndWall(dir, glm::vec3(0.9f), glm::vec3(0.9f, 0.5f, 0.1f));
}

/// A cube map folder of .hdr faces (size^2 texels, one value per face): red lights posx (1)
/// and negx (1/4), green posy and negy, blue posz and negz. Every face has its own channel and
/// level, so a face put in another's place, or a channel in another's, changes the light.
std::string WriteAxisCube(const std::string& dir, int size) {
  return test::WriteHdrCube(dir, size, [](int k, int, int) {
    glm::vec3 value(0.0f);
    value[k / 2] = k % 2 == 0 ? 1.0f : 0.25f;
    return value;
  });
}

/// The 9 coefficients (bands 0..2) of the WriteAxisCube light, per channel, by a quadrature of
/// our own: each face is the plane at distance 1, where dw = ds dt / r^3 (r^2 = 1 + s^2 + t^2),
/// integrated by the midpoint rule on a 400^2 grid (error below 1e-5), against the closed forms
/// of CONVENTIONS.md.
std::vector<glm::dvec3> AxisCubeCoefficients() {
  std::vector<glm::dvec3> L(9, glm::dvec3(0.0));
  const int n = 400;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1}) {
      const double level = sign > 0 ? 1.0 : 0.25;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const double s = -1.0 + (i + 0.5) * 2.0 / n, t = -1.0 + (j + 0.5) * 2.0 / n;
          const double r = std::sqrt(1.0 + s * s + t * t);
          glm::dvec3 d(0.0);
          d[axis] = sign / r;
          d[(axis + 1) % 3] = s / r;
          d[(axis + 2) % 3] = t / r;
          const double dw = (2.0 / n) * (2.0 / n) / (r * r * r);
          const double x = d.x, y = d.y, z = d.z;
          const double Y[9] = {0.282095, -0.488603 * y, 0.488603 * z, -0.488603 * x, 1.092548 * x * y,
                               -1.092548 * y * z, 0.315392 * (3 * z * z - 1), -1.092548 * x * z,
                               0.546274 * (x * x - y * y)};
          for (int k = 0; k < 9; ++k) L[k][axis] += level * Y[k] * dw;
        }
    }
  return L;
}


}  // namespace

TEST_SUITE("app") {
  TEST_CASE("course files: coloured interreflection writes a transport.txt the viewer loads, and the exact channels") {
    const std::string dir = test::ScratchDir("course_colour");
    const std::string mesh = WriteWallScene(dir);
    const std::string out = dir + "/out";
    const auto r = test::RunPrt("precompute --mesh " + Q(mesh) +
                                " --env furnace --transport interreflection --samples 256 --out " + Q(out));
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("luminance-weighted mix 0.2126 R + 0.7152 G + 0.0722 B") != std::string::npos);

    const auto light = test::ReadLikeTheViewer(out + "/light.txt", 3, test::ViewerHeader::kNone);
    CHECK(light.size() == 9);
    const auto mix = test::ReadLikeTheViewer(out + "/transport.txt", 9);
    const auto red = test::ReadLikeTheViewer(out + "/transport_r.txt", 9);
    const auto green = test::ReadLikeTheViewer(out + "/transport_g.txt", 9);
    const auto blue = test::ReadLikeTheViewer(out + "/transport_b.txt", 9);
    REQUIRE(mix.size() == 3 * (test::FloorTriangles() + test::WallTriangles()));
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

    // Colour bleeding, channel by channel: the floor (its rows come first) sees only the wall, so
    // what one bounce adds to its transport is the wall's albedo times the same geometry in each
    // channel. The bounce is the interreflected transport minus the shadowed one (same seed, so
    // the same rays): summed over the floor's rows, red : green : blue = 0.9 : 0.5 : 0.1.
    const auto direct_run = test::RunPrt("precompute --mesh " + Q(mesh) +
                                         " --env furnace --transport shadowed --samples 256 --out " + Q(out + "_direct"));
    REQUIRE(direct_run.exit_code == 0);
    const auto direct = test::ReadLikeTheViewer(out + "_direct/transport.txt", 9);
    REQUIRE(direct.size() == mix.size());
    double bounce_r = 0.0, bounce_g = 0.0, bounce_b = 0.0;
    for (std::size_t i = 0; i < 3 * test::FloorTriangles(); ++i) {
      bounce_r += red[i][0] - direct[i][0];
      bounce_g += green[i][0] - direct[i][0];
      bounce_b += blue[i][0] - direct[i][0];
    }
    CAPTURE(bounce_r);
    CAPTURE(bounce_g);
    CAPTURE(bounce_b);
    REQUIRE(bounce_b > 0.0);
    // Only the printed digits (7 of values ~0.23 whose bounce part is ~0.003) separate them:
    // measured 8.99998 and 4.99999.
    CHECK(bounce_r / bounce_b == doctest::Approx(9.0).epsilon(1e-4));
    CHECK(bounce_g / bounce_b == doctest::Approx(5.0).epsilon(1e-4));
  }

  TEST_CASE("course files: light.txt of prt light and prt precompute holds each face's light in its own channel") {
    // Read back as the viewer reads it, against an independent quadrature of the same cube.
    const std::string dir = test::ScratchDir("course_light");
    const std::string cube = WriteAxisCube(dir + "/cube", 32);
    const std::vector<glm::dvec3> expected = AxisCubeCoefficients();
    // The red light of +X is -0.4886 * 0.75 * 1.7408 in Y11 (Y11 = -0.4886 x): its sign says
    // which face is which.
    CHECK(expected[3].x == doctest::Approx(-0.488603 * 0.75 * 4.0 * std::atan(1.0 / std::sqrt(2.0)) / std::sqrt(2.0))
                               .epsilon(1e-4));
    // prt samples each 32^2 face at texel centres with exact texel solid angles: its error
    // falls as 1/N^2 and is 1.1e-4 at most here (measured); faces or channels out of place are
    // off by 0.1 or more.
    constexpr double kCubeQuadrature = 2e-3;
    const auto printed = test::RunPrt("light --env " + Q(cube));
    CAPTURE(printed.err);
    REQUIRE(printed.exit_code == 0);
    WriteFileAtomic(dir + "/printed.txt", printed.out);
    const auto precomputed = test::RunPrt("precompute --mesh " + Q(test::Fixture("obj/tetra_no_normals.obj")) +
                                          " --env " + Q(cube) + " --transport unshadowed --out " + Q(dir + "/out"));
    CAPTURE(precomputed.err);
    REQUIRE(precomputed.exit_code == 0);
    for (const std::string& file : {dir + "/printed.txt", dir + "/out/light.txt"}) {
      const auto rows = test::ReadLikeTheViewer(file, 3, test::ViewerHeader::kNone);
      REQUIRE(rows.size() == 9);
      for (int k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) {
          CAPTURE(file);
          CAPTURE(k);
          CAPTURE(c);
          CHECK(std::abs(rows[k][c] - expected[k][c]) < kCubeQuadrature);
        }
    }
  }

  TEST_CASE("course files: grey albedo writes one transport.txt and no channel files") {
    const std::string dir = test::ScratchDir("course_grey");
    const std::string mesh = WriteWallScene(dir);
    const auto r = test::RunPrt("precompute --mesh " + Q(mesh) + " --albedo 0.5,0.5,0.5 --env furnace " +
                                "--transport interreflection --samples 64 --out " + Q(dir + "/out"));
    REQUIRE(r.exit_code == 0);
    CHECK(test::ReadLikeTheViewer(dir + "/out/transport.txt", 9).size() == 3 * (test::FloorTriangles() + test::WallTriangles()));
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
    CHECK(test::ReadLikeTheViewer(dir + "/transport.txt", 16).size() == 12);
    const auto two = test::RunPrt(base + " --lmax 2");
    CHECK(two.exit_code == 0);
    CHECK(two.err.find("viewer") == std::string::npos);
    CHECK(test::ReadLikeTheViewer(dir + "/transport.txt", 9).size() == 12);
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
    CHECK(test::ReadLikeTheViewer(out + "/transport.txt", 9).size() == 30522);  // three rows per face of the file
    CHECK(test::ReadLikeTheViewer(out + "/light.txt", 3, test::ViewerHeader::kNone).size() == 9);
  }
}

}  // namespace prt
