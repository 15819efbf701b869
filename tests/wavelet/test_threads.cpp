// The threads tier of src/wavelet (tests/README.md, "Tiers"): the wavelet transport, the light
// cube's gathering and turning, and the shading, on one thread and on more threads than cores,
// give the same bits; ThreadSanitizer watches the many-thread runs.
#include <doctest/doctest.h>

#include "env/procedural.h"
#include "precompute/light.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/threads_util.h"
#include "wavelet/cube_grid.h"
#include "wavelet/light_cube.h"
#include "wavelet/shade.h"
#include "wavelet/texel_sh.h"
#include "wavelet/transport.h"

namespace prt {

TEST_SUITE("wavelet") {
  TEST_CASE("threads: the wavelet transport, the turned light and the shading, the same bits on 1 and many threads") {
    const Mesh mesh = test::SphereOverPlane();
    TransportOptions sh;
    sh.mode = TransportMode::kInterreflection;
    sh.samples = 64;
    WaveletOptions w;
    w.face_size = 8;
    w.budget = 48;
    const auto [one, many] = test::OneAndMany([&] { return ComputeWaveletTransport(mesh, sh, w, nullptr); });
    CHECK(one.index == many.index);
    CHECK(one.value == many.value);
    CHECK(one.offsets == many.offsets);
    CHECK(one.means == many.means);
    CHECK(one.scale == many.scale);
    CHECK(one.base == many.base);
    CHECK(one.bounce.coeffs == many.bounce.coeffs);
    // The budget, kept at every vertex; per vertex 25 base floats (lmax 4), the 6 faces' means,
    // the other 42 terms of 4 bytes, a step; and an offset.
    const std::size_t nv = mesh.vertex_count();
    CHECK(one.Kept() == 48 * nv);
    CHECK(one.Bytes() == nv * (25 * 4 + 6 * 4 + 42 * 4 + 4) + (nv + 1) * 8);

    // A frame: the sky gathered onto the cube, turned and shaded.
    const auto sky = MakeSky(SkyParams{});
    const CubeGrid grid(w.face_size);
    const TexelSh base(grid, one.base_lmax);
    const ShRgb sh_light = ProjectLight(*sky, 2);
    const glm::dmat3 turn(glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0));
    const auto [frame_one, frame_many] = test::OneAndMany([&] {
      const LightCube cube(*sky, grid);
      CubeRgb coeffs;
      const WaveletLight light = TurnedWaveletLight(cube, turn, 0, {}, &base, coeffs);
      return ShadeWavelet(mesh, one, light, sh_light);
    });
    CHECK(frame_one == frame_many);
  }
}

}  // namespace prt
