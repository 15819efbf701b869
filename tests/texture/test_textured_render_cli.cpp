// A textured square under the furnace through the command line: each quadrant of its texture
// comes out as its own texels (albedo x 1), in SH and in wavelets. (The textured rasterizer and
// transport in-process: test_textured_raster.cpp.)
#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "core/atomic_file.h"
#include "io/png_io.h"
#include "tests/test_process.h"

using namespace prt;

TEST_SUITE_BEGIN("texture");

TEST_CASE("textured render: a checker under the furnace comes out as its own texels (albedo x 1), in SH and in wavelets") {
  const std::string dir = test::ScratchDir("textured_furnace");
  // Four quadrants of distinct colours (a flipped v, swapped channels or a lost texture show).
  const std::uint8_t colours[4][3] = {{200, 30, 30}, {30, 200, 30}, {30, 30, 200}, {240, 240, 240}};
  Image8 texture(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) texture.rgb[3 * (y * 16 + x) + c] = colours[(y / 8) * 2 + x / 8][c];
  WritePng(dir + "/quadrants.png", texture);
  WriteFileAtomic(dir + "/square.obj",
                  "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                  "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
  // In either basis: the wavelets' white furnace is exact too.
  for (const std::string basis : {"sh", "wavelet --cube-size 8"}) {
    CAPTURE(basis);
    const test::RunResult r = test::RunPrt(
        "render --mesh " + test::Q(dir + "/square.obj") + " --texture " + test::Q(dir + "/quadrants.png") +
        " --env furnace --transport unshadowed --exposure 0 --tonemap srgb --ssaa 1 --frames 1 --size 64x64"
        " --eye 0,0,3 --target 0,0,0 --fov 30 --basis " + basis + " --out " + test::Q(dir + "/out"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const Image8 frame = ReadPng(dir + "/out/frame_0000.png");
    // Quadrant centres (x, y = +-0.5) are 20 pixels from the image centre; a 5 x 5 block around
    // each lies well inside its quadrant, where the texture is one colour.
    const int centres[4][2] = {{12, 12}, {52, 12}, {12, 52}, {52, 52}};
    for (int q = 0; q < 4; ++q)
      for (int y = centres[q][1] - 2; y <= centres[q][1] + 2; ++y)
        for (int x = centres[q][0] - 2; x <= centres[q][0] + 2; ++x)
          CHECK(test::PixelAt(frame, x, y) == glm::ivec3(colours[q][0], colours[q][1], colours[q][2]));
  }
}

