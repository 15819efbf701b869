// The threads tier of src/precompute (tests/README.md, "Tiers"): every stage that runs on several
// threads, run on one and on more threads than the machine has cores, must give the same bits
// (the project's promise: identical output for any --threads), and ThreadSanitizer watches the
// many-thread runs. The stages: the light's projection, the direct transport (shadowed), the
// bounces, the glossy vectors and transfer matrices, the per-vertex shading, and the reference
// (its environment sampler and its per-vertex loop), diffuse and glossy.
#include <doctest/doctest.h>

#include "env/procedural.h"
#include "material/material.h"
#include "precompute/light.h"
#include "precompute/reference.h"
#include "precompute/shade.h"
#include "precompute/transport.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/threads_util.h"

namespace prt {
namespace {

/// Large enough for several chunks of every stage's loop (64 and 256 vertices a chunk).
test::SphereOverPlaneShape Shape() {
  test::SphereOverPlaneShape s;
  s.plane_divisions = 16;
  s.sphere_segments = 20;
  return s;
}

}  // namespace

TEST_SUITE("precompute") {
  TEST_CASE("threads: the light's projection is the same bits on 1 and many threads") {
    const auto sky = MakeSky(SkyParams{});
    const auto [one, many] = test::OneAndMany([&] { return ProjectLight(*sky, 6); });
    CHECK(one == many);
  }

  TEST_CASE("threads: shadowed, interreflected and glossy transport, vectors and matrices, the same bits on 1 and many threads") {
    const Mesh mesh = test::SphereOverPlane(Shape());
    for (const char* mode : {"shadowed", "interreflection", "glossy vectors", "glossy matrices"}) {
      CAPTURE(mode);
      TransportOptions o;
      o.mode = std::string(mode) == "shadowed" ? TransportMode::kShadowed : TransportMode::kInterreflection;
      o.samples = 64;
      o.bounces = 2;
      o.lmax = 2;
      if (std::string(mode).rfind("glossy", 0) == 0) {
        o.material = ParseMaterial("phong:20,0.4");
        o.eye = glm::dvec3(3, 2, 4);
        o.matrices = std::string(mode) == "glossy matrices";
      }
      const auto [one, many] = test::OneAndMany([&] { return ComputeTransport(mesh, o, nullptr); });
      CHECK(one.coeffs == many.coeffs);
      CHECK(one.glossy == many.glossy);
      CHECK(one.matrices == many.matrices);
      // Shading a frame: the per-vertex loop, and the lobe through the matrices toward an eye.
      const ShRgb light = test::BandLimitedLight(2);
      const glm::dvec3 eye(1, 3, 5);
      const auto [shaded_one, shaded_many] =
          test::OneAndMany([&] { return ShadeVertices(mesh, one, light, true, o.matrices ? &eye : nullptr); });
      CHECK(shaded_one == shaded_many);
    }
  }

  TEST_CASE("threads: the reference, diffuse with bounces and glossy, the same bits on 1 and many threads") {
    const auto sky = MakeSky(SkyParams{});
    const Mesh mesh = test::SphereOverPlane();
    ReferenceOptions o;
    o.mode = TransportMode::kInterreflection;
    o.bounces = 2;
    o.samples = 16;
    o.table_rows = 32, o.table_cols = 64;
    for (const char* material : {"diffuse", "phong:20,0.4"}) {
      CAPTURE(material);
      o.material = ParseMaterial(material);
      if (o.material.glossy) o.eye = glm::dvec3(3, 2, 4);
      const auto [one, many] = test::OneAndMany([&] { return ComputeReference(mesh, *sky, o); });
      CHECK(one.radiance == many.radiance);
      CHECK(one.error == many.error);
      CHECK(one.rays == many.rays);
    }
  }
}

}  // namespace prt
