#include <doctest/doctest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.h"
#include "env/load_environment.h"
#include "env/procedural.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "io/obj_loader.h"
#include "precompute/light.h"
#include "precompute/transport.h"
#include "raster/image_diff.h"
#include "raster/tonemap.h"
#include "render/render_frames.h"
#include "sh/rotation.h"
#include "sh_basis/frame_light.h"
#include "tests/golden.h"
#include "tests/test_support.h"

using namespace prt;

namespace {

/// A small scene with self-shadowing: a sphere resting on a plane, albedo 0.7.
Mesh SphereOnPlane() {
  Mesh m = MakeSphere(40, 1.0f, glm::vec3(0.0f, 1.0f, 0.0f));
  AppendMesh(m, MakePlane(5.0f, 24));
  SetUniformAlbedo(m, glm::vec3(0.7f));
  return m;
}

struct Scene {
  Mesh mesh;
  Transport transport;
  ShRgb light;
  std::unique_ptr<Environment> env;
};

Scene MakeScene(TransportMode mode, int lmax, const std::string& material = "diffuse") {
  Scene s;
  s.mesh = SphereOnPlane();
  SkyParams sky;
  sky.sun = 6.0;
  s.env = MakeSky(sky);
  s.light = ProjectLight(*s.env, lmax);
  TransportOptions t;
  t.mode = mode;
  t.lmax = lmax;
  t.samples = 128;
  t.material = ParseMaterial(material);
  if (t.material.glossy) {
    for (auto& albedo : s.mesh.albedo) albedo *= 0.5f;  // room for KS
    t.eye = glm::dvec3(ChooseCamera(s.mesh, test::GoldenFrame()).eye);
  }
  s.transport = ComputeTransport(s.mesh, t, nullptr);
  return s;
}

Image8 Draw(const Scene& s, const RenderOptions& o, double angle) {
  Rasterizer r;
  const auto light = MakeShFrameLight(s.transport, s.light, o.axis);
  return DrawFrame(r, s.mesh, *light, *s.env, ChooseCamera(s.mesh, o), o, angle, *o.exposure)
      .image;
}

}  // namespace

TEST_SUITE("render") {
  TEST_CASE("golden frames: unshadowed, shadowed, interreflection, light turned 90 degrees") {
    const RenderOptions o = test::GoldenFrame();
    const Scene unshadowed = MakeScene(TransportMode::kUnshadowed, 2);
    test::CheckGolden("unshadowed", Draw(unshadowed, o, 0.0));
    const Scene shadowed = MakeScene(TransportMode::kShadowed, 4);
    test::CheckGolden("shadowed", Draw(shadowed, o, 0.0));
    test::CheckGolden("shadowed_turned_90", Draw(shadowed, o, kPi / 2));
    const Scene inter = MakeScene(TransportMode::kInterreflection, 4);
    test::CheckGolden("interreflection", Draw(inter, o, 0.0));
  }

  TEST_CASE("golden frame: a glossy sphere (phong:40,0.5) toward the fixed camera") {
    const Scene glossy = MakeScene(TransportMode::kShadowed, 6, "phong:40,0.5");
    test::CheckGolden("glossy_phong40", Draw(glossy, test::GoldenFrame(), 0.0));
  }

  TEST_CASE("furnace: every covered pixel is exactly the albedo") {
    // Constant radiance 1 and unshadowed transport: outgoing radiance = albedo exactly, so
    // every drawn pixel is the sRGB encoding of the albedo (0.6 -> 203) and no other value.
    Scene s;
    s.mesh = MakeSphere(32);
    SetUniformAlbedo(s.mesh, glm::vec3(0.6f));
    s.env = MakeFurnace(1.0);
    s.light = ProjectLight(*s.env, 2);
    TransportOptions t;
    t.mode = TransportMode::kUnshadowed;
    s.transport = ComputeTransport(s.mesh, t, nullptr);
    RenderOptions o = test::GoldenFrame();
    o.env_background = false;
    o.eye = glm::dvec3(0, 0, 5), o.target = glm::dvec3(0.0);
    const Image8 img = Draw(s, o, 0.3);
    const auto expected = EncodeSrgb8(0.6f);
    CHECK(expected == 203);
    std::size_t covered = 0, wrong = 0;
    for (std::size_t i = 0; i < img.rgb.size(); ++i) {
      if (img.rgb[i] == 0) continue;
      ++covered;
      wrong += img.rgb[i] != expected;
    }
    CHECK(covered > 1000);
    CHECK(wrong == 0);
  }

  TEST_CASE("a full turn of the light reproduces frame 0 exactly") {
    const Scene s = MakeScene(TransportMode::kShadowed, 4);
    const RenderOptions o = test::GoldenFrame();
    const DiffMetrics m = CompareImages(Draw(s, o, 0.0), Draw(s, o, 2 * kPi));
    // The rotation of 2 pi is the identity up to rounding (1e-16 of the coefficients); an 8-bit
    // pixel can only flip where its value sits on a rounding boundary.
    CHECK(m.max_abs <= 1);
    CHECK(m.differing_pixels <= 2);
  }

  TEST_CASE("turning camera and light together about a symmetry axis of the scene changes nothing") {
    // A sphere of 48 segments about Y is mapped onto itself by turns of 2 pi k / 48 about Y.
    // Turning the light and the camera by such a turn R shows the same scene in the same light
    // from the same relative viewpoint: the image must not change.
    Scene s;
    s.mesh = MakeSphere(48);
    s.env = MakeSky(SkyParams{});
    s.light = ProjectLight(*s.env, 4);
    TransportOptions t;
    t.mode = TransportMode::kUnshadowed;
    t.lmax = 4;
    s.transport = ComputeTransport(s.mesh, t, nullptr);
    RenderOptions o = test::GoldenFrame();
    o.env_background = false;
    o.eye = glm::dvec3(0, 1, 5), o.target = glm::dvec3(0.0);
    const Image8 before = Draw(s, o, 0.0);
    const double a = 2 * kPi * 7 / 48;
    o.eye = AxisAngle({0, 1, 0}, a) * *o.eye;
    const Image8 after = Draw(s, o, a);
    const DiffMetrics m = CompareImages(before, after);
    // Vertex positions agree with their turned images to float rounding (1e-7), so a pixel
    // centre lying on an edge may fall on the other side: allow a handful of silhouette pixels;
    // shading agrees to 8-bit rounding.
    MESSAGE("symmetry: " << FormatDiffMetrics(m));
    CHECK(m.differing_pixels <= 8);
    CHECK(m.mean_abs < 0.2);
  }

  TEST_CASE("a non-square frame shows a sphere round, of the size the pinhole camera gives") {
    // Sphere of radius 1 at distance 8 on the optical axis: its outline is a circle of angular
    // radius asin(1/8), tan(asin(1/8)) / tan(fov/2) half-heights wide, in both directions:
    // pixels are square whatever the frame's shape. Wide and tall frames alike.
    Scene s;
    s.mesh = MakeSphere(64);
    s.env = MakeFurnace(1.0);
    s.light = ProjectLight(*s.env, 2);
    TransportOptions t;
    t.mode = TransportMode::kUnshadowed;
    s.transport = ComputeTransport(s.mesh, t, nullptr);
    for (const auto& [width, height] : {std::pair{160, 80}, std::pair{60, 120}}) {
      RenderOptions o = test::GoldenFrame();
      o.env_background = false;
      o.width = width, o.height = height;
      o.eye = glm::dvec3(0, 0, 8), o.target = glm::dvec3(0.0);
      const Image8 img = Draw(s, o, 0.0);
      int x0 = width, x1 = -1, y0 = height, y1 = -1;
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
          if (img.rgb[3 * (std::size_t(y) * width + x)] != 0) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      const double radius = std::tan(std::asin(0.125)) / std::tan(0.5 * *o.fov * kPi / 180.0) * 0.5 * height;
      CAPTURE(width);
      CAPTURE(height);
      // A pixel is covered when its centre is inside: the extent is the diameter to within a
      // pixel at each end (the 64-segment outline is 0.1 % smaller than the sphere's).
      CHECK(std::abs((x1 - x0 + 1) - 2.0 * radius) <= 2.0);
      CHECK(std::abs((y1 - y0 + 1) - 2.0 * radius) <= 2.0);
      CHECK(std::abs(0.5 * (x0 + x1 + 1) - 0.5 * width) <= 1.0);
      CHECK(std::abs(0.5 * (y0 + y1 + 1) - 0.5 * height) <= 1.0);
    }
  }

  TEST_CASE("the environment behind the mesh turns with the light: the sun is drawn where the light comes from") {
    // Light turned by a about +Y comes from R(a) d where it came from d (CONVENTIONS.md). A
    // camera looking along R(a) sun must see the sun's disk (radiance in the hundreds, white
    // after the clamp even at exposure -6, which leaves the sky around it grey) at the image
    // centre; one looking along R(-a) sun must not.
    Scene s;
    SkyParams sky;
    s.env = MakeSky(sky);
    s.light = ProjectLight(*s.env, 2);
    const double a = kPi / 2;
    const glm::dvec3 sun = SunDirection(sky);
    const glm::dvec3 turned = AxisAngle({0, 1, 0}, a) * sun, against = AxisAngle({0, 1, 0}, -a) * sun;
    s.mesh = MakeSphere(8, 0.1f, glm::vec3(-3.0 * (turned + against)));  // behind both cameras
    TransportOptions t;
    t.mode = TransportMode::kUnshadowed;
    s.transport = ComputeTransport(s.mesh, t, nullptr);
    RenderOptions o = test::GoldenFrame();
    o.width = o.height = 33;
    o.fov = 10.0;
    o.exposure = -6.0;
    o.eye = glm::dvec3(0.0);
    const auto centre = [](const Image8& img) { return test::PixelAt(img, 16, 16); };
    o.target = turned;
    CHECK(centre(Draw(s, o, a)) == glm::ivec3(255));
    o.target = against;
    CHECK(centre(Draw(s, o, a)) != glm::ivec3(255));
    CHECK(centre(Draw(s, o, -a)) == glm::ivec3(255));
    // In a frame twice as wide as high, a sun 10 degrees right of the view axis is half way
    // from the centre to the right edge: tan 10 / (2 tan(fov/2)) = 0.5 for fov 20 (square pixels).
    o.width = 66, o.height = 33, o.fov = 20.0;
    const glm::dvec3 right = glm::normalize(glm::cross(turned, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, turned);
    o.target = glm::dvec3(AxisAngle(up, 10.0 * kPi / 180.0) * turned);  // the camera turned 10 degrees left
    o.up = up;
    const Image8 wide = Draw(s, o, a);
    CHECK(test::PixelAt(wide, 49, 16) == glm::ivec3(255));
    CHECK(test::PixelAt(wide, 16, 16) != glm::ivec3(255));
  }

  TEST_CASE("golden frame of the course scene: mary under Grace Cathedral" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    Scene s;
    s.mesh = LoadObj(data + "/games202/mary/mary.obj").mesh;
    s.env = LoadEnvironment(data + "/games202/cubemap/GraceCathedral", CubeLayout::kStandard);
    s.light = ProjectLight(*s.env, 2);
    TransportOptions t;
    t.mode = TransportMode::kShadowed;
    t.samples = 64;
    s.transport = ComputeTransport(s.mesh, t, nullptr);
    RenderOptions o = test::GoldenFrame();
    o.width = 72, o.height = 96;
    o.env_background = false;
    o.eye = glm::dvec3(0, 8, 22) * 0.45, o.target = glm::dvec3(0, 1.7, 0), o.fov = 30.0;
    const Image8 img = Draw(s, o, 0.0);
    test::CheckGolden("mary_gracecathedral", img);
  }
}
