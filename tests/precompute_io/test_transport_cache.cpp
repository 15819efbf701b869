// The transport cache must never be reused for other inputs: a stale cache is a silently wrong
// picture. Its key covers every input of the transport, checked one input at a time in the
// library. (Through the binary: test_transport_cache_cli.cpp.)
#include <doctest/doctest.h>

#include <map>
#include <set>
#include <string>

#include "geometry/procedural.h"
#include "precompute_io/transport_cache.h"
#include "tests/precompute_io/sphere_on_floor.h"
#include "tests/test_support.h"

namespace prt {

TEST_SUITE("precompute_io") {
  TEST_CASE("cache key: every input of the transport changes it") {
    const Mesh mesh = test::SphereOnFloor(1.0f);
    const TransportOptions base;
    std::map<std::string, std::uint64_t> keys;
    keys["base"] = TransportKey(mesh, base);
    CHECK(TransportKey(mesh, base) == keys["base"]);  // a function of its inputs only
    const auto with = [&](const std::string& name, auto change) {
      TransportOptions o = base;
      Mesh m = mesh;
      change(m, o);
      keys[name] = TransportKey(m, o);
    };
    with("position", [](Mesh& m, TransportOptions&) { m.positions[5].y += 1e-6f; });
    with("normal", [](Mesh& m, TransportOptions&) { m.normals[5].x += 1e-6f; });
    with("albedo", [](Mesh& m, TransportOptions&) { m.albedo[5].z = 0.5f; });
    with("triangle", [](Mesh& m, TransportOptions&) { std::swap(m.triangles[3][0], m.triangles[3][1]); });
    with("mode", [](Mesh&, TransportOptions& o) { o.mode = TransportMode::kInterreflection; });
    with("lmax", [](Mesh&, TransportOptions& o) { o.lmax = 3; });
    with("samples", [](Mesh&, TransportOptions& o) { o.samples = 1025; });
    with("sampler", [](Mesh&, TransportOptions& o) { o.sampler = Sampler::kStratified; });
    with("bounces", [](Mesh&, TransportOptions& o) { o.bounces = 2; });
    with("seed", [](Mesh&, TransportOptions& o) { o.seed = 2; });
    with("tolerance", [](Mesh&, TransportOptions& o) { o.bounce_tolerance = 2e-4; });
    with("direction sets", [](Mesh&, TransportOptions& o) { o.direction_sets = 63; });
    // Which vertices the camera sees decides which take the fewer directions.
    const auto seen = [](const Mesh& m, std::size_t hidden) {
      std::vector<std::uint8_t> s(m.vertex_count(), 1);
      s[hidden] = 0;
      return s;
    };
    with("hidden samples", [&](Mesh& m, TransportOptions& o) { o.hidden_samples = 64, o.seen = seen(m, 5); });
    with("seen vertices", [&](Mesh& m, TransportOptions& o) { o.hidden_samples = 64, o.seen = seen(m, 6); });
    std::set<std::uint64_t> distinct;
    for (const auto& [name, key] : keys) {
      CAPTURE(name);
      CHECK(distinct.insert(key).second);
    }
  }

}

}  // namespace prt
