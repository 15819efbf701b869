// The threads tier of src/raster (tests/README.md, "Tiers"): the rasterizer's stages (vertices,
// triangle set-up, bins, bands) and the tone map, each split in chunks, give the same image on
// one thread and on more threads than cores; ThreadSanitizer watches the many-thread runs.
#include <doctest/doctest.h>

#include <tuple>

#include "geometry/procedural.h"
#include "raster/camera.h"
#include "raster/rasterizer.h"
#include "raster/tonemap.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("raster") {
  TEST_CASE("threads: a drawn frame, supersampled and tone mapped in its bands, and the tone map alone, are the same bits on 1 and many threads") {
    const Mesh knot = MakeTorusKnot(2, 3, 0.2f, 128, 16);
    std::vector<glm::vec3> colors;
    for (const auto& n : knot.normals) colors.push_back(0.5f * n + 0.5f);
    const Camera camera = FrameBounds(glm::vec3(-1.f), glm::vec3(1.f), 1.5f);
    ToneMapOptions tone;
    tone.curve = ToneCurve::kReinhard;
    const auto [one, many] = test::OneAndMany([&] {
      Rasterizer rasterizer;
      Image8 toned;
      RasterOptions options;
      options.ssaa = 2;
      options.tone_map = &tone;
      options.tone_mapped = &toned;
      const RasterImage& frame = rasterizer.Draw(camera, 150, 100, knot.positions, knot.triangles, colors, options);
      return std::make_tuple(frame.image.pixels, frame.coverage, toned.rgb);
    });
    CHECK(std::get<0>(one) == std::get<0>(many));
    CHECK(std::get<1>(one) == std::get<1>(many));  // the mesh's share of each pixel
    CHECK(std::get<2>(one) == std::get<2>(many));
    const RasterImage plain = Rasterize(camera, 150, 100, knot.positions, knot.triangles, colors);
    const auto [toned_one, toned_many] = test::OneAndMany([&] { return ToneMap(plain.image, tone).image.rgb; });
    CHECK(toned_one == toned_many);
  }
}

}  // namespace prt
