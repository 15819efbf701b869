// The frame's light per basis (render/frame_light.h): each is what its own pieces give, turned
// by the same rotation.
#include <doctest/doctest.h>

#include <cmath>

#include "env/procedural.h"
#include "geometry/procedural.h"
#include "precompute/light.h"
#include "precompute/shade.h"
#include "precompute/shade_wavelet.h"
#include "render/frame_light.h"
#include "sh/axis_rotation.h"
#include "sh/rotation.h"

namespace prt {

TEST_SUITE("render") {
  TEST_CASE("frame light: SH is the band-rotated light dotted with each transfer vector") {
    const Mesh mesh = MakeSphere(16);
    TransportOptions o;
    o.mode = TransportMode::kUnshadowed;
    o.lmax = 3;
    const Transport t = ComputeTransport(mesh, o, nullptr);
    const auto sky = MakeSky(SkyParams{});
    const ShRgb light = ProjectLight(*sky, 6);  // more bands than the transport: the first are used
    const glm::dvec3 axis(0.3, 1.0, 0.2);
    const auto frame = MakeShFrameLight(t, light, axis);
    frame->Turn(0.8);
    const ShRgb turned = AxisRotation(axis, 3).Rotate(FirstBands(light, 3), 0.8);
    const auto got = frame->Shade(mesh, true, nullptr), expected = ShadeVertices(mesh, t, turned, true);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) CHECK(got[v][c] == expected[v][c]);
    CHECK(frame->ShTransport() == &t);
  }

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
    const auto expected = ShadeWavelet(mesh, t, PackWaveletLight(rgb), {}, false);
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
    CHECK(frame->ShTransport() == nullptr);
  }
}

}  // namespace prt
