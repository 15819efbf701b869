// Defaults that look right, through the binary: without flags a render is tone mapped by ACES
// with 2 x 2 supersampling at an automatic exposure that the summary prints exactly enough to
// repeat the run byte for byte, and neither the embedded scene nor a bright HDR sun clips; the
// automatic camera fits what it sees for any frame shape; `render` and `reference` without
// --mesh use the demo's camera; the transport view is drawn on neutral grey with a legend that
// grows with the image; the SH pole's direction is said where students look.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/atomic_file.h"
#include "core/image.h"
#include "geometry/procedural.h"
#include "io/obj_writer.h"
#include "io/png_io.h"
#include "tests/test_process.h"

namespace prt {
namespace {

using test::Q;

/// The value printed after `--exposure ` in "(--exposure X repeats it)" on the summary.
std::string PrintedExposure(const std::string& err) {
  const std::string key = "(--exposure ";
  const auto at = err.find(key);
  if (at == std::string::npos) return "";
  const auto end = err.find(' ', at + key.size());
  return err.substr(at + key.size(), end - at - key.size());
}

/// Share of pixels with a channel at 255.
double ClippedShare(const Image8& image) {
  std::size_t clipped = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    clipped += image.rgb[i] == 255 || image.rgb[i + 1] == 255 || image.rgb[i + 2] == 255;
  return double(clipped) / double(image.width * image.height);
}

/// The smallest box of pixel rows and columns holding every pixel that is not black.
struct Covered {
  int top, bottom, left, right;  // inclusive
};
Covered CoveredBox(const Image8& image) {
  Covered c{image.height, -1, image.width, -1};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = &image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x)];
      if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;
      c.top = std::min(c.top, y), c.bottom = std::max(c.bottom, y);
      c.left = std::min(c.left, x), c.right = std::max(c.right, x);
    }
  return c;
}

// Measured with a post 3 units tall and 0.5 wide: rows 7..292 of 300 in a 90x300 frame, 95 %.
// The fit keeps a margin of a few percent, and a bounding-sphere fit fills about 27 %.
constexpr double kFilledShare = 0.9;
// Centred: the two margins differ by the pixel rounding of the projected box.
constexpr int kCentringPixels = 2;

/// An upright box, half-width x and half-depth z, `height` tall on y = 0, as OBJ text.
std::string BoxObj(float x, float height, float z) {
  return FormatObj({{"box", MakeBox(glm::vec3(-x, 0.0f, -z), glm::vec3(x, height, z))}}, "box.mtl");
}

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("defaults: ACES, 2x2 supersampling and an automatic exposure printed exactly enough to repeat the run") {
    const std::string dir = test::ScratchDir("defaults");
    const std::string scene = "render --samples 64 --frames 1 --size 160x120";
    const auto plain = test::RunPrt(scene + " --out " + Q(dir + "/plain"));
    CAPTURE(plain.err);
    REQUIRE(plain.exit_code == 0);
    const std::string ev = PrintedExposure(plain.err);
    REQUIRE_FALSE(ev.empty());
    CHECK(plain.err.find("exposure: auto -> " + ev + " EV") != std::string::npos);
    const auto spelled = test::RunPrt(scene + " --tonemap aces --ssaa 2 --exposure " + ev + " --out " + Q(dir + "/spelled"));
    REQUIRE(spelled.exit_code == 0);
    CHECK(ReadFile(dir + "/plain/frame_0000.png") == ReadFile(dir + "/spelled/frame_0000.png"));

    // The old defaults (srgb, exposure 0, no supersampling) clip 14 % of this frame; these none.
    CHECK(ClippedShare(ReadPng(dir + "/plain/frame_0000.png")) == 0.0);
    const auto old = test::RunPrt(scene + " --tonemap srgb --exposure 0 --ssaa 1 --out " + Q(dir + "/old"));
    REQUIRE(old.exit_code == 0);
    CHECK(ClippedShare(ReadPng(dir + "/old/frame_0000.png")) > 0.05);
  }

  TEST_CASE("defaults: a bright HDR sun does not blow the mesh to white") {
    const std::string dir = test::ScratchDir("defaults_sun");
    const auto samples = test::RunPrt("sample-files --quiet --out " + Q(dir + "/samples"));
    REQUIRE(samples.exit_code == 0);
    const std::string scene = "render --mesh " + Q(dir + "/samples/scene.obj") + " --env " +
                              Q(dir + "/samples/sky.hdr") + " --samples 64 --frames 1 --size 160x120 --background black";
    const auto plain = test::RunPrt(scene + " --out " + Q(dir + "/plain"));
    REQUIRE(plain.exit_code == 0);
    CHECK(ClippedShare(ReadPng(dir + "/plain/frame_0000.png")) == 0.0);
    // A light far beyond what the automatic exposure's range covers: said, not silently white.
    const auto blinding = test::RunPrt("render --env furnace:1e12 --transport unshadowed --frames 1 --size 32x24 --out " +
                                       Q(dir + "/blinding"));
    CHECK(blinding.err.find("auto -> -20.0 EV") != std::string::npos);
    CHECK(blinding.err.find("the limit: the scene is brighter than -20 EV can show") != std::string::npos);
    CHECK(plain.err.find("the limit") == std::string::npos);
    // Measured: srgb at exposure 0 clips 23 % of this frame (nearly all of the mesh).
    const auto old = test::RunPrt(scene + " --tonemap srgb --exposure 0 --ssaa 1 --out " + Q(dir + "/old"));
    REQUIRE(old.exit_code == 0);
    CHECK(ClippedShare(ReadPng(dir + "/old/frame_0000.png")) > 0.1);
  }

  TEST_CASE("defaults: the automatic camera fills tall and wide frames with what it sees, centred") {
    const std::string dir = test::ScratchDir("framing");
    WriteFileAtomic(dir + "/post.obj", BoxObj(0.25f, 3.0f, 0.25f));
    WriteFileAtomic(dir + "/beam.obj", BoxObj(2.0f, 0.4f, 0.25f));
    // Which direction limits the fit: the post's height in a tall or square frame; the beam's
    // height (with its depth, seen from above) in a 400x90 strip; its length in a square.
    enum class Fills { kRows, kColumns };
    const struct {
      const char* mesh;
      const char* size;
      Fills fills;
    } cases[] = {{"post", "90x300", Fills::kRows},
                 {"post", "300x300", Fills::kRows},
                 {"beam", "400x90", Fills::kRows},
                 {"beam", "300x300", Fills::kColumns}};
    for (const auto& c : cases) {
      CAPTURE(c.mesh);
      CAPTURE(c.size);
      const std::string out = dir + "/" + c.mesh + "_" + c.size;
      const auto r = test::RunPrt(std::string("render --mesh ") + Q(dir + "/" + c.mesh + ".obj") +
                                  " --env furnace --transport unshadowed --background black --frames 1 --size " + c.size +
                                  " --out " + Q(out));
      REQUIRE(r.exit_code == 0);
      const Image8 image = ReadPng(out + "/frame_0000.png");
      const Covered box = CoveredBox(image);
      CAPTURE(box.top);
      CAPTURE(box.bottom);
      CAPTURE(box.left);
      CAPTURE(box.right);
      // Filled in the limiting direction, centred in both.
      if (c.fills == Fills::kRows) CHECK(box.bottom - box.top + 1 >= kFilledShare * image.height);
      else CHECK(box.right - box.left + 1 >= kFilledShare * image.width);
      CHECK(std::abs(box.top - (image.height - 1 - box.bottom)) <= kCentringPixels);
      CHECK(std::abs(box.left - (image.width - 1 - box.right)) <= kCentringPixels);
    }
  }

  TEST_CASE("defaults: render and reference without --mesh see the embedded scene with the demo's camera") {
    const std::string dir = test::ScratchDir("demo_camera");
    const std::string demo_camera = "camera: --eye 6,3.2,9 --target 0,1.5,0 --up 0,1,0 --fov 36";
    const auto render = test::RunPrt("render --transport unshadowed --frames 1 --size 32x24 --out " + Q(dir + "/r"));
    CAPTURE(render.err);
    CHECK(render.exit_code == 0);
    CHECK(render.err.find(demo_camera) != std::string::npos);
    const auto reference = test::RunPrt("reference --transport unshadowed --reference-samples 2 --size 32x24 --out " +
                                        Q(dir + "/ref"));
    CAPTURE(reference.err);
    CHECK(reference.exit_code == 0);
    CHECK(reference.err.find(demo_camera) != std::string::npos);
    // Each value not given stays the demo's: one option changes one thing.
    const auto fov = test::RunPrt("render --fov 50 --transport unshadowed --frames 1 --size 32x24 --out " + Q(dir + "/f"));
    CHECK(fov.err.find("camera: --eye 6,3.2,9 --target 0,1.5,0 --up 0,1,0 --fov 50") != std::string::npos);
    const auto eye = test::RunPrt("render --eye 0,3,9 --transport unshadowed --frames 1 --size 32x24 --out " + Q(dir + "/e"));
    CHECK(eye.err.find("camera: --eye 0,3,9 --target 0,1.5,0 --up 0,1,0 --fov 36") != std::string::npos);
    const auto same = test::RunPrt("render --eye 0,1.5,0 --out " + Q(dir + "/s"));
    CHECK(same.exit_code == 2);
    CHECK(same.err.find("--eye: equals the embedded scene's camera target 0,1.5,0") != std::string::npos);
  }

  TEST_CASE("defaults: the transport view is drawn on neutral grey, with a legend that grows with the image") {
    const std::string dir = test::ScratchDir("transport_view");
    int legend_width[2] = {0, 0};
    const char* sizes[2] = {"400x300", "1600x1200"};
    for (int i = 0; i < 2; ++i) {
      const std::string out = dir + "/" + sizes[i];
      // On the small scene.
      const auto r = test::RunPrt(std::string("render --view transport:0 --samples 16 --frames 1 --size ") + sizes[i] +
                                  test::SmallSceneOption("transport_view_small_scene") + " --out " + Q(out));
      REQUIRE(r.exit_code == 0);
      const Image8 image = ReadPng(out + "/frame_0000.png");
      // The top-left corner shows background: the default --background env would be sky blue.
      CHECK(image.rgb[0] == image.rgb[1]);
      CHECK(image.rgb[1] == image.rgb[2]);
      CHECK(image.rgb[0] > 64);
      // The legend is a dark panel (26, 26, 26) at the right edge; its left edge is the first
      // dark pixel in the right half of the row a quarter down (nothing else there is dark:
      // the background is 128 grey, the false colours run from red through white to blue).
      const std::size_t row = 3 * static_cast<std::size_t>(image.height / 4) * image.width;
      int left = image.width / 2;
      while (left < image.width && std::max({image.rgb[row + 3 * left], image.rgb[row + 3 * left + 1],
                                             image.rgb[row + 3 * left + 2]}) >= 40)
        ++left;
      legend_width[i] = image.width - left;
      CHECK(image.rgb[3 * (image.width - 1)] == image.rgb[0]);  // the panel keeps off the top edge
    }
    CAPTURE(legend_width[0]);
    CAPTURE(legend_width[1]);
    CHECK(legend_width[0] >= 30);  // measured 53 and 126
    CHECK(legend_width[1] >= 2 * legend_width[0]);
    // Too small to hold a readable legend: left out, and said.
    const auto tiny = test::RunPrt("render --view transport:0 --samples 16 --frames 1 --size 48x32 --out " + Q(dir + "/tiny"));
    CHECK(tiny.err.find("legend: left out, a 48x32 frame is too small") != std::string::npos);
  }

  TEST_CASE("defaults: the SH pole is said to be world +Z where students read the basis") {
    const auto help = test::RunPrt("help basis");
    CHECK(help.exit_code == 0);
    CHECK(help.out.find("world +Z, while scenes are Y-up") != std::string::npos);
    CHECK(ReadFile(test::SourceDir() + "/README.md").find("The SH pole is world +Z") != std::string::npos);
  }
}

}  // namespace prt
