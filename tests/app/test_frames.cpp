// What `prt render` writes, frame by frame, checked through the binary against closed forms and
// symmetries rather than golden images: exposure scales radiance by 2^EV, frame k of N shows the
// light turned by 2 pi k / N (so the sequence loops without a repeated frame), and the colour
// channels never mix: permuting R, G, B in every input permutes them in every pixel.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include <glm/vec3.hpp>

#include "core/image.h"
#include "io/png_io.h"
#include "raster/image_diff.h"
#include "raster/tonemap.h"
#include "tests/env/env_test_util.h"
#include "tests/test_process.h"

namespace prt {
namespace {

using test::Q;

/// How many pixels of `image` hold exactly `value` in all three channels.
std::size_t CountGrey(const Image8& image, std::uint8_t value) {
  std::size_t n = 0;
  for (std::size_t p = 0; p < image.rgb.size(); p += 3)
    n += image.rgb[p] == value && image.rgb[p + 1] == value && image.rgb[p + 2] == value;
  return n;
}


/// Renders with `options` into a fresh folder named `name` and returns the folder.
std::string Render(const std::string& name, const std::string& options) {
  const std::string out = test::ScratchDir(name);
  const auto r = test::RunPrt("render --quiet --cache none --out " + Q(out) + " " + options);
  CAPTURE(options);
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
  return out;
}

/// (r, g, b) -> (g, b, r).
glm::vec3 Permute(const glm::vec3& v) { return {v.y, v.z, v.x}; }

/// A white floor beside a wall of three colours (WriteFloorAndWall), under a cube map whose
/// faces differ in colour and level; every input colour passes through `colour`.
std::string WriteColourScene(const std::string& dir, glm::vec3 (*colour)(const glm::vec3&)) {
  test::WriteFloorAndWall(dir, colour(glm::vec3(0.9f)), colour(glm::vec3(0.9f, 0.5f, 0.1f)));
  const std::array<glm::vec3, 6> faces = {glm::vec3(1.0f, 0.5f, 0.25f), glm::vec3(0.25f, 0.5f, 1.0f),
                                          glm::vec3(2.0f, 1.0f, 0.5f),  glm::vec3(0.125f, 0.25f, 0.0625f),
                                          glm::vec3(0.5f, 1.0f, 0.5f),  glm::vec3(1.0f, 0.25f, 0.5f)};
  test::WriteHdrCube(dir + "/cube", 8, [&](int k, int row, int) { return colour(faces[k] * (1.0f + 0.125f * float(row))); });
  return dir;
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("frames: --exposure EV multiplies the radiance by 2^EV before the tone curve") {
    // Furnace, unshadowed, albedo 0.25: every mesh pixel is 0.25 exactly before exposure.
    const std::string scene = test::QuickScene() +
                              " --albedo 0.25,0.25,0.25 --tonemap srgb --ssaa 1 --background black --frames 1 --size 48x48";
    for (int ev : {-1, 0, 1}) {
      const Image8 image = ReadPng(test::FramePath(Render("exposure", scene + " --exposure " + std::to_string(ev)), 0, 1));
      const std::uint8_t expected = EncodeSrgb8(0.25f * std::exp2(float(ev)));
      const std::uint8_t opposite = EncodeSrgb8(0.25f * std::exp2(float(-ev)));
      CAPTURE(ev);
      CHECK(CountGrey(image, expected) > 200);
      if (ev != 0) CHECK(CountGrey(image, opposite) == 0);
    }
  }

  TEST_CASE("frames: frame k of N shows the light turned by 2 pi k/N, so the loop never repeats a frame") {
    // The sky's sun turns about +Y with the light; the background turns with it.
    const std::string scene = "--mesh " + Q(test::Fixture("obj/tetra_no_normals.obj")) +
                              " --env sky --transport unshadowed --exposure 0 --ssaa 1 --size 48x36";
    const std::string four = Render("frames4", scene + " --frames 4");
    const std::string eight = Render("frames8", scene + " --frames 8");
    for (int k = 0; k < 4; ++k) {
      CAPTURE(k);
      const DiffMetrics same = CompareImages(ReadPng(test::FramePath(four, k, 4)), ReadPng(test::FramePath(eight, 2 * k, 8)));
      CHECK(same.differing_pixels == 0);
    }
    // Frame N-1 is a quarter turn short of the full turn (frame N would be frame 0 again).
    CHECK(CompareImages(ReadPng(test::FramePath(four, 3, 4)), ReadPng(test::FramePath(four, 0, 4))).differing_pixels > 100);
    const std::string turned = Render("frames_quarter", scene + " --frames 4 --turns -1");
    // -pi/2 and 3 pi/2 differ in the last bits of their sines: a pixel may round the other way.
    const DiffMetrics back = CompareImages(ReadPng(test::FramePath(four, 3, 4)), ReadPng(test::FramePath(turned, 1, 4)));
    CHECK(back.max_abs <= 1);
    CHECK(back.differing_pixels <= 4);
    // About -Y a quarter turn is +Y's three quarters: the mesh's light and the background both
    // follow --axis (a light that turned about +Y whatever the axis would shade the mesh as
    // frame 1 of the +Y turn).
    const std::string down = Render("frames_down", scene + " --frames 4 --axis 0,-1,0");
    const DiffMetrics axis = CompareImages(ReadPng(test::FramePath(four, 3, 4)), ReadPng(test::FramePath(down, 1, 4)));
    CHECK(axis.max_abs <= 1);
    CHECK(axis.differing_pixels <= 4);
  }

  TEST_CASE("frames: the run summary's bounce line says coloured albedo only when it is coloured") {
    const std::string scene = "render --mesh " + Q(test::Fixture("obj/tetra_no_normals.obj")) +
                              " --env sky --transport interreflection --samples 64 --size 16x12 --frames 1";
    const std::string clause = "; coloured albedo: one transport vector per colour channel";
    const std::pair<std::string, bool> cases[] = {{"0.5,0.5,0.5", false}, {"0.5,0.4,0.3", true}};  // albedo, coloured
    for (const auto& [albedo, coloured] : cases) {
      CAPTURE(albedo);
      const auto r = test::RunPrt(scene + " --albedo " + albedo + " --out " + Q(test::ScratchDir("albedo_clause")));
      REQUIRE(r.exit_code == 0);
      const std::size_t line = r.err.find("\nbounces: ");
      REQUIRE(line != std::string::npos);
      const std::string bounces = r.err.substr(line, r.err.find('\n', line + 1) - line);
      CHECK((bounces.find(clause) != std::string::npos) == coloured);
    }
  }

  TEST_CASE("frames: a white floor beside a red wall is tinted red by the bounce, and grey without it") {
    // Seen from above, the wall out of view: only floor pixels. The floor's direct light is the
    // same in every channel, its bounce light is the wall's albedo (0.9, 0.1, 0.1).
    const std::string dir = test::ScratchDir("bleeding");
    test::WriteFloorAndWall(dir, glm::vec3(0.9f), glm::vec3(0.9f, 0.1f, 0.1f));
    const std::string scene = "--mesh " + Q(dir + "/scene.obj") + " --env furnace --samples 256 --tonemap srgb " +
                              "--exposure 0 --ssaa 1 --background black --size 48x48 --frames 1 " +
                              "--eye -0.5,3,0.01 --target -0.5,0,0 --fov 20";
    for (const std::string mode : {"interreflection", "shadowed"}) {
      const Image8 image = ReadPng(test::FramePath(Render("bleeding_out", scene + " --transport " + mode), 0, 1));
      std::size_t covered = 0, green_is_blue = 0;
      double red_excess = 0.0;
      for (std::size_t p = 0; p < image.rgb.size(); p += 3) {
        if (image.rgb[p] == 0 && image.rgb[p + 1] == 0 && image.rgb[p + 2] == 0) continue;
        ++covered;
        green_is_blue += image.rgb[p + 1] == image.rgb[p + 2];
        red_excess += double(image.rgb[p]) - double(image.rgb[p + 1]);
      }
      CAPTURE(mode);
      REQUIRE(covered > 1000);
      CHECK(green_is_blue == covered);
      if (mode == "interreflection") {
        CHECK(red_excess / double(covered) > 5.0);  // measured: 22 levels on average
      } else {
        CHECK(red_excess == 0.0);
      }
    }
  }

  TEST_CASE("frames: colour channels never mix: permuting R, G, B in every input permutes every pixel") {
    // A coloured cube map, a coloured wall bouncing light onto a white floor, exposure fixed
    // (automatic exposure weighs channels by luminance, which no permutation keeps): each
    // channel goes through the same arithmetic alone, so the images agree exactly up to the
    // permutation. A channel dropped, duplicated or swapped anywhere (light projection,
    // bounces, shading, tone mapping, PNG) breaks it.
    const std::string options = " --transport interreflection --bounces 1 --samples 256 --tonemap srgb --exposure -1 "
                                "--ssaa 1 --size 64x48 --frames 2 --eye 1.5,2.5,2.5 --target -0.4,0.3,0";
    const std::string a = WriteColourScene(test::ScratchDir("channels_a"), [](const glm::vec3& v) { return v; });
    const std::string b = WriteColourScene(test::ScratchDir("channels_b"), Permute);
    const std::string out_a = Render("channels_out_a", "--mesh " + Q(a + "/scene.obj") + " --env " + Q(a + "/cube") + options);
    const std::string out_b = Render("channels_out_b", "--mesh " + Q(b + "/scene.obj") + " --env " + Q(b + "/cube") + options);
    for (int i = 0; i < 2; ++i) {
      const Image8 image_a = ReadPng(test::FramePath(out_a, i, 2)), image_b = ReadPng(test::FramePath(out_b, i, 2));
      REQUIRE(image_a.rgb.size() == image_b.rgb.size());
      std::size_t differing = 0, coloured = 0;
      for (std::size_t p = 0; p < image_a.rgb.size(); p += 3) {
        differing += image_b.rgb[p] != image_a.rgb[p + 1] || image_b.rgb[p + 1] != image_a.rgb[p + 2] ||
                     image_b.rgb[p + 2] != image_a.rgb[p];
        coloured += image_a.rgb[p] != image_a.rgb[p + 1] && image_a.rgb[p + 1] != image_a.rgb[p + 2];
      }
      CAPTURE(i);
      CHECK(differing == 0);
      CHECK(coloured > image_a.rgb.size() / 3 / 2);  // the test means something: most pixels have three distinct channels
    }
  }
}

}  // namespace prt
