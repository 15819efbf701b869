// The turning light and the background drawn behind the mesh turn together (render/render_frames.h),
// above all about axes that point down (-Z: the polar shortcut, which carries the axis's sign;
// -Y, -X; an axis with every component negative): an environment that is band-limited has an
// exact SH light, so the "light" view's background (the turned coefficients reconstructed) must
// equal, pixel by pixel, the environment render draws behind the mesh at the same angle (its own
// background direction, turned by its own matrix).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "env/environment.h"
#include "geometry/procedural.h"
#include "precompute/transport.h"
#include "render/render_frames.h"
#include "sh/axis_rotation.h"
#include "sh_basis/frame_light.h"
#include "tests/sh/sh_test_util.h"

namespace prt {
namespace {

constexpr int kLmax = 4;  // band matrices of every size up to 9 x 9 take part
// A frame's pixels are floats, and render turns the background direction by a float matrix:
// measured 5e-7 at worst on radiances of 0.5 to 3.2; a light turned the wrong way (or about the
// wrong axis) is off by more than 1.
constexpr double kFrameTolerance = 1e-4;

/// The environment whose radiance is the band-limited f(d) = sum_k c_k Y_k(d): its SH light is c
/// exactly. Only Radiance is used (render's background); it has no quadrature rows.
class BandLimitedEnvironment : public Environment {
 public:
  explicit BandLimitedEnvironment(ShRgb c) : c_(std::move(c)) {}
  glm::dvec3 Radiance(const glm::dvec3& dir) const override { return test::EvaluateSh(c_, dir); }
  std::size_t RowCount() const override { return 0; }
  void Row(std::size_t, std::vector<Texel>& out) const override { out.clear(); }
  std::string Describe() const override { return "band-limited test light"; }

 private:
  ShRgb c_;
};

}  // namespace

TEST_SUITE("render") {
  TEST_CASE("light turn: about negative axes the drawn background turns with the SH light") {
    // The environment is band-limited, so its SH light is exact and the "light" view's background
    // (the turned coefficients reconstructed) must equal the environment render draws behind the
    // mesh at the same angle. A small sphere behind the camera keeps every pixel background.
    const ShRgb light = test::RandomLight(kLmax, 2);
    const BandLimitedEnvironment env(light);
    for (const glm::dvec3& forward : {glm::dvec3(1, 0.3, 0.2), glm::dvec3(-0.4, -0.8, 0.5)}) {
      const Mesh mesh = MakeSphere(6, 0.05f, glm::vec3(-3.0 * glm::normalize(forward)));
      TransportOptions t;
      t.mode = TransportMode::kUnshadowed;
      t.lmax = kLmax;
      const Transport transport = ComputeTransport(mesh, t, nullptr);
      RenderOptions o;
      o.width = o.height = 24;
      o.ssaa = 1;
      o.fov = 100.0;
      o.eye = glm::dvec3(0.0);
      o.target = forward;
      for (const glm::dvec3& axis : {glm::dvec3(0, 0, -1), glm::dvec3(0, -1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(-1, -2, -2)}) {
        o.axis = axis;
        const Camera camera = ChooseCamera(mesh, o);
        for (double angle : {1.1, -2.0}) {
          Rasterizer rasterizer;
          o.view = View::kLight;
          const RasterImage sh = RasterizeFrame(rasterizer, mesh, *MakeShFrameLight(transport, light, o.axis), env, camera, o, angle, 0.0);
          Rasterizer rasterizer2;
          o.view = View::kRadiance;
          o.env_background = true;
          const RasterImage drawn = RasterizeFrame(rasterizer2, mesh, *MakeShFrameLight(transport, light, o.axis), env, camera, o, angle, 0.0);
          double worst = 0.0;
          std::size_t background = 0;
          for (std::size_t i = 0; i < sh.image.pixels.size(); ++i) {
            if (sh.coverage[i] > 0.f || drawn.coverage[i] > 0.f) continue;
            ++background;
            for (int ch = 0; ch < 3; ++ch)
              worst = std::max(worst, double(std::abs(sh.image.pixels[i][ch] - drawn.image.pixels[i][ch])));
          }
          INFO("axis (" << axis.x << ", " << axis.y << ", " << axis.z << "), angle " << angle << ": worst " << worst);
          CHECK(background == sh.image.pixels.size());
          CHECK(worst < kFrameTolerance);
        }
      }
    }
  }
}

}  // namespace prt
