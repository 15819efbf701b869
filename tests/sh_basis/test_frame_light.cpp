// The SH basis's frame light (sh_basis/frame_light.h): what its own pieces give, turned by the
// band rotations, and the coefficients the transport view shows.
#include <doctest/doctest.h>

#include <cmath>

#include "env/procedural.h"
#include "geometry/procedural.h"
#include "precompute/light.h"
#include "precompute/shade.h"
#include "sh/axis_rotation.h"
#include "sh/rotation.h"
#include "sh_basis/frame_light.h"

namespace prt {

TEST_SUITE("sh_basis") {
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
    // What the views read: the lobe flag and the transfer coefficients of the first channel.
    CHECK_FALSE(frame->HasGlossy());
    REQUIRE(frame->ViewCoefficients() == CoeffCount(3));
    for (std::size_t v = 0; v < mesh.vertex_count(); v += 7)
      for (int k = 0; k < CoeffCount(3); ++k) CHECK(frame->Coefficient(v, k) == t.at(v, 0)[k]);
  }

  TEST_CASE("frame light: SH SetAxis gives the bytes of a light made with that axis") {
    const Mesh mesh = MakeSphere(12);
    TransportOptions o;
    o.mode = TransportMode::kUnshadowed;
    o.lmax = 4;
    const Transport t = ComputeTransport(mesh, o, nullptr);
    const ShRgb light = ProjectLight(*MakeSky(SkyParams{}), 4);
    const glm::dvec3 first(0, 1, 0), second = glm::normalize(glm::dvec3(0.6, 0.7, -0.3));
    const auto moved = MakeShFrameLight(t, light, first), made = MakeShFrameLight(t, light, second);
    moved->Turn(1.1);
    const auto before = moved->Shade(mesh, true, nullptr);
    moved->SetAxis(second);
    moved->Turn(1.1);
    made->Turn(1.1);
    const auto got = moved->Shade(mesh, true, nullptr), expected = made->Shade(mesh, true, nullptr);
    bool differs = false;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) {
        CHECK(got[v][c] == expected[v][c]);
        differs = differs || got[v][c] != before[v][c];
      }
    CHECK(differs);
  }
}

}  // namespace prt
