// `prt render --look course` through the binary: the picture is what the GAMES202 homework-2
// WebGL viewer draws from the light.txt and transport.txt that `prt precompute` writes (per vertex
// light . transport, no albedo, then the sRGB curve, no exposure), from the viewer's camera unless
// one is given, and a bad --look value is a one-line usage error.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/atomic_file.h"
#include "io/png_io.h"
#include "tests/app/viewer_files.h"
#include "tests/env/env_test_util.h"
#include "tests/test_process.h"

namespace prt {
namespace {

using test::Q;

// Levels of 255 that the look's pixels may differ from the viewer's formula evaluated here:
// prt shades in float, this test in double (a difference far below a level), so what remains is
// the 8-bit rounding of a value that lies near a level's boundary: one level.
constexpr int kViewerLevels = 1;

/// The viewer's fragment shader's toSRGB, then 8 bits.
int ViewerLevel(double x) {
  x = std::clamp(x, 0.0, 1.0);
  const double s = x < 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255.0 * s));
}

/// dir/quad.obj: a 2 x 2 square in the plane z = 0 facing +z (two triangles, so every vertex has
/// the normal +z and the same transport), with a coloured albedo from dir/quad.mtl that the
/// viewer must not show. Returns the OBJ's path.
std::string WriteColouredQuad(const std::string& dir) {
  std::ofstream(dir + "/quad.mtl") << "newmtl paint\nKd 0.2 0.5 0.9\n";
  std::ofstream(dir + "/quad.obj") << "mtllib quad.mtl\nusemtl paint\n"
                                      "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";
  return dir + "/quad.obj";
}

/// A cube map whose faces each light one channel at their own level (posx red 1, negx red 1/4,
/// posy green 1, ...): the +z quad sees every channel differently.
std::string WriteColouredSky(const std::string& dir) {
  return test::WriteHdrCube(dir, 8, [](int k, int, int) {
    glm::vec3 value(0.0f);
    value[k / 2] = k % 2 == 0 ? 1.0f : 0.25f;
    return value;
  });
}

/// The line of `text` that starts with `prefix`, or "".
std::string LineStarting(const std::string& text, const std::string& prefix) {
  std::size_t at = text.find(prefix);
  while (at != std::string::npos && at != 0 && text[at - 1] != '\n' && text[at - 1] != ' ') at = text.find(prefix, at + 1);
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("render --look course: the pixels are the viewer's sRGB(light.txt . transport.txt), without albedo") {
    const std::string dir = test::ScratchDir("course_look_pixels");
    const std::string scene = "--mesh " + Q(WriteColouredQuad(dir)) + " --env " + Q(WriteColouredSky(dir + "/sky")) +
                              " --transport unshadowed";
    const auto pre = test::RunPrt("precompute " + scene + " --out " + Q(dir + "/files") + " --quiet");
    REQUIRE_MESSAGE(pre.exit_code == 0, pre.err);

    // The viewer's colour of each corner: per channel, the 9 light coefficients times the row's 9.
    const auto light = test::ReadLikeTheViewer(dir + "/files/light.txt", 3, test::ViewerHeader::kNone);
    const auto transport = test::ReadLikeTheViewer(dir + "/files/transport.txt", 9);
    REQUIRE(light.size() == 9);
    REQUIRE(transport.size() == 6);  // three rows per face
    std::vector<glm::ivec3> corners;
    for (const auto& row : transport) {
      glm::ivec3 level;
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int k = 0; k < 9; ++k) sum += light[k][c] * row[k];
        level[c] = ViewerLevel(sum);
      }
      corners.push_back(level);
    }
    // Every corner faces +z: one colour, so interpolation over the triangles keeps it exactly.
    for (const glm::ivec3& level : corners) CHECK(level == corners.front());
    const glm::ivec3 expected = corners.front();
    // Each channel in the curve's range and apart from the others: a swapped channel, a clipped
    // one or the albedo (0.2, 0.5, 0.9) multiplied in would show.
    CAPTURE(expected);
    REQUIRE(std::min({expected.x, expected.y, expected.z}) > 20);
    REQUIRE(std::max({expected.x, expected.y, expected.z}) < 235);

    // A camera that sees only the quad: every pixel is its inside.
    const auto run = test::RunPrt("render " + scene + " --look course --eye 0,0,3 --target 0,0,0 --fov 30 --frames 1 "
                                  "--size 16x16 --out " + Q(dir + "/look"));
    REQUIRE_MESSAGE(run.exit_code == 0, run.err);
    const Image8 frame = ReadPng(test::FramePath(dir + "/look", 0, 1));
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < frame.width; ++x) {
        const glm::ivec3 got = test::PixelAt(frame, x, y);
        CAPTURE(x);
        CAPTURE(y);
        CAPTURE(got);
        REQUIRE(std::abs(got.x - expected.x) <= kViewerLevels);
        REQUIRE(std::abs(got.y - expected.y) <= kViewerLevels);
        REQUIRE(std::abs(got.z - expected.z) <= kViewerLevels);
      }
    // The summary says what the look set, the camera given on the command line named as kept.
    const std::string look = LineStarting(run.err, "look course");
    CHECK(look.find("--view irradiance --tonemap srgb --exposure 0 --window none") != std::string::npos);
    CHECK(look.find("kept: --eye --target --fov") != std::string::npos);
  }

  TEST_CASE("render --look course: the viewer's camera unless one is given; explicit options win") {
    const std::string dir = test::ScratchDir("course_look_camera");
    const std::string scene = "render --mesh " + Q(WriteColouredQuad(dir)) + " --env furnace --transport unshadowed "
                              "--frames 1 --size 16x16 --look course";
    // three.js's eye (0, 0, 100), target 0, fov 75, with the mesh at translate (0, -35, 0) scale 20.
    const auto viewer = test::RunPrt(scene + " --out " + Q(dir + "/viewer"));
    REQUIRE_MESSAGE(viewer.exit_code == 0, viewer.err);
    CHECK(LineStarting(viewer.err, "camera:").find("--eye 0,1.75,5 --target 0,1.75,0 --up 0,1,0 --fov 75") !=
          std::string::npos);
    CHECK(LineStarting(viewer.err, "look course").find("--eye 0,1.75,5 --target 0,1.75,0 --fov 75") !=
          std::string::npos);

    // An explicit --eye wins; the target and fov not given stay the viewer's.
    const auto eye = test::RunPrt(scene + " --eye 1,2,6 --out " + Q(dir + "/eye"));
    REQUIRE_MESSAGE(eye.exit_code == 0, eye.err);
    CHECK(LineStarting(eye.err, "camera:").find("--eye 1,2,6 --target 0,1.75,0 --up 0,1,0 --fov 75") !=
          std::string::npos);
    CHECK(LineStarting(eye.err, "look course").find("kept: --eye") != std::string::npos);

    // Any other option given wins too: --tonemap aces changes the picture and the summary line.
    const auto aces = test::RunPrt(scene + " --tonemap aces --out " + Q(dir + "/aces"));
    REQUIRE_MESSAGE(aces.exit_code == 0, aces.err);
    CHECK(LineStarting(aces.err, "look course").find("--tonemap srgb") == std::string::npos);
    const Image8 a = ReadPng(test::FramePath(dir + "/viewer", 0, 1)), b = ReadPng(test::FramePath(dir + "/aces", 0, 1));
    CHECK(a.rgb != b.rgb);
  }

  TEST_CASE("render --look course is byte for byte the options its summary line says it sets, each of which counts") {
    // Under a bright small sun at lmax 6 on a coloured knot, each option the look sets changes the
    // picture (albedo, exposure, curve, the auto window against none, the camera): the look's frame must be
    // the frame of the options its line names, given explicitly, and not the frame of those
    // options less any one of them.
    const std::string dir = test::ScratchDir("course_look_bytes");
    const std::string base = "render --mesh " + Q(test::WriteSmallScene(dir)) + " --env sky:sun=1000,radius=1 --lmax 6 --frames 1 "
                             "--size 48x36 --ssaa 1 --cache " + Q(dir + "/transport.cache") + " --out ";
    const auto look = test::RunPrt(base + Q(dir + "/look") + " --look course");
    REQUIRE_MESSAGE(look.exit_code == 0, look.err);
    std::string line = LineStarting(look.err, "look course");
    REQUIRE(line.find("):") != std::string::npos);
    line = line.substr(line.find("):") + 2);
    CHECK(line.find("kept") == std::string::npos);  // nothing given on the command line
    // The options, as --name value pairs.
    std::vector<std::string> options;
    std::istringstream words(line);
    for (std::string name, value; words >> name >> value;) options.push_back(name + " " + value);
    REQUIRE(options.size() == 7);  // view, tonemap, exposure, window, eye, target, fov
    const auto frame = [&](const std::string& out) { return ReadFile(test::FramePath(dir + "/" + out, 0, 1)); };
    const std::string expected = frame("look");
    std::string all;
    for (const std::string& o : options) all += " " + o;
    const auto same = test::RunPrt(base + Q(dir + "/explicit") + all);
    REQUIRE_MESSAGE(same.exit_code == 0, same.err);
    CHECK(frame("explicit") == expected);
    for (std::size_t left = 0; left < options.size(); ++left) {
      CAPTURE(options[left]);
      std::string rest;
      for (std::size_t i = 0; i < options.size(); ++i)
        if (i != left) rest += " " + options[i];
      const std::string out = "without_" + std::to_string(left);
      const auto r = test::RunPrt(base + Q(dir + "/" + out) + rest);
      REQUIRE_MESSAGE(r.exit_code == 0, r.err);
      CHECK(frame(out) != expected);
    }
  }

  TEST_CASE("render --look: a bad value or --basis wavelet is a one-line usage error; another lmax is warned") {
    const std::string dir = test::ScratchDir("course_look_errors");
    const auto foo = test::RunPrt(test::QuickRender(dir + "/foo", 1) + " --look foo");
    CHECK(foo.exit_code == 2);  // docs/CLI.md: 2 for a usage error
    CHECK(foo.err.rfind("prt: error: --look: unknown value 'foo'", 0) == 0);
    CHECK(foo.err.find("default, course") != std::string::npos);
    CHECK(std::count(foo.err.begin(), foo.err.end(), '\n') == 1);

    const auto wavelet = test::RunPrt(test::QuickRender(dir + "/wavelet", 1) + " --look course --basis wavelet");
    CHECK(wavelet.exit_code == 2);
    CHECK(wavelet.err.rfind("prt: error: --look course:", 0) == 0);

    const auto lmax = test::RunPrt(test::QuickRender(dir + "/lmax", 1) + " --look course --lmax 3 --eye 0,1,5");
    CHECK(lmax.exit_code == 0);
    CHECK(lmax.err.find("reads exactly 9 numbers a row") != std::string::npos);
  }
}

}  // namespace prt
