// The wavelet basis's frame light (wavelet/frame_light.h): the turned sky resampled onto the cube,
// cut to K terms, shaded as its own pieces shade it.
#include <doctest/doctest.h>

#include <cmath>

#include "env/procedural.h"
#include "geometry/procedural.h"
#include "sh/rotation.h"
#include "wavelet/cube_grid.h"
#include "wavelet/frame_light.h"
#include "wavelet/light_cube.h"
#include "wavelet/texel_sh.h"
#include "wavelet/shade.h"

namespace prt {

TEST_SUITE("wavelet") {
  TEST_CASE("frame light: wavelets resample the turned sky, keep K light terms and show what they keep") {
    const Mesh mesh = MakeSphere(12);
    TransportOptions o;
    o.mode = TransportMode::kUnshadowed;
    WaveletOptions w;
    w.face_size = 8;
    const WaveletTransport t = ComputeWaveletTransport(mesh, o, w, nullptr);
    const auto sky = MakeSky(SkyParams{});
    const glm::dvec3 axis(0, 1, 0);
    constexpr int kTerms = 20;
    const auto frame = MakeWaveletFrameLight(t, *sky, {}, axis, kTerms, Selection::kArea);
    frame->Turn(1.3);
    // The same steps by hand.
    const CubeGrid grid(8);
    CubeRgb rgb;
    LightCube(*sky, grid).Resample(AxisAngle(axis, 1.3), rgb);
    CubeToHaar(8, rgb);
    KeepLightTerms(SelectionWeights(8, Selection::kArea), kTerms, rgb);
    CubeRgb kept_texels = rgb;  // the base's light is that of the kept terms
    CubeFromHaar(8, kept_texels);
    const auto expected =
        ShadeWavelet(mesh, t, PackWaveletLight(rgb, BaseLight(TexelSh(grid, t.base_lmax), kept_texels)), {}, false);
    const auto got = frame->Shade(mesh, false, nullptr);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) CHECK(got[v][c] == expected[v][c]);
    // The light view: the kept terms back on the texels.
    CubeFromHaar(8, rgb);
    for (std::size_t texel = 0; texel < grid.texels(); texel += 5)
      CHECK(frame->Kept(grid.Direction(texel)).y == doctest::Approx(rgb.c[1][texel]).epsilon(1e-6));
    // Fewer terms than the light has: the kept light is not the whole light.
    const auto all = MakeWaveletFrameLight(t, *sky, {}, axis, 0, Selection::kArea);
    all->Turn(1.3);
    double differ = 0.0;
    for (std::size_t texel = 0; texel < grid.texels(); ++texel)
      differ += std::abs(all->Kept(grid.Direction(texel)).y - frame->Kept(grid.Direction(texel)).y);
    CHECK(differ > 0.01);
    // No SH coefficients for the transport view, and no lobe.
    CHECK(frame->ViewCoefficients() == 0);
    CHECK_FALSE(frame->HasGlossy());
  }
}

}  // namespace prt
