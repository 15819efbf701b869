// A block of vertices (TransportOptions::block, farm/vertex_blocks.h) computes those vertices'
// transport to the bit as the whole run does, and nothing else: what makes a farm job's merged
// shards the same bytes as one run. Checked for every mode a shard takes and every glossy part.
#include <doctest/doctest.h>

#include <cstring>
#include <string>
#include <vector>

#include "farm/vertex_blocks.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "precompute/transport.h"
#include "material/material.h"
#include "sh/coeffs.h"

namespace prt {
namespace {

/// A knot above a ground: vertices in shadow and in the open, a count 3 does not divide.
Mesh KnotOnGround() {
  Mesh mesh = MakeTorusKnot(2, 3, 0.3f, 24, 5);
  for (auto& p : mesh.positions) p.y += 1.2f;
  AppendMesh(mesh, MakePlane(6.0f, 9));
  return mesh;
}

/// True when rows [begin, end) of `part` (per_vertex floats each) equal `whole`'s bit for bit
/// and every other row of `part` is 0.
bool RowsAreTheWholeRuns(const std::vector<float>& part, const std::vector<float>& whole, std::size_t per_vertex,
                         const VertexBlock& block) {
  if (part.size() != whole.size()) return false;
  for (std::size_t v = 0; v < whole.size() / per_vertex; ++v) {
    const float* p = part.data() + v * per_vertex;
    const float* w = whole.data() + v * per_vertex;
    for (std::size_t k = 0; k < per_vertex; ++k)
      if (block.Has(v) ? std::memcmp(p + k, w + k, sizeof(float)) != 0 : p[k] != 0.0f) return false;
  }
  return true;
}

}  // namespace

TEST_SUITE("precompute") {
TEST_CASE("transport of a vertex block: the whole run's rows to the bit, every mode and glossy part, 0 elsewhere") {
  const Mesh mesh = KnotOnGround();
  REQUIRE_MESSAGE(mesh.vertex_count() % 3 != 0, mesh.vertex_count());
  struct Case {
    const char* name;
    TransportMode mode;
    bool glossy, matrices;
  };
  const Case cases[] = {{"unshadowed", TransportMode::kUnshadowed, false, false},
                        {"shadowed", TransportMode::kShadowed, false, false},
                        {"shadowed, glossy toward a fixed eye", TransportMode::kShadowed, true, false},
                        {"shadowed, glossy transfer matrices", TransportMode::kShadowed, true, true},
                        {"unshadowed, glossy transfer matrices", TransportMode::kUnshadowed, true, true}};
  for (const Case& c : cases) {
    CAPTURE(c.name);
    TransportOptions o;
    o.mode = c.mode;
    o.lmax = 3;
    o.samples = 64;
    o.direction_sets = 8;
    if (c.glossy) {
      o.material = ParseMaterial("phong:8,0.2");
      o.matrices = c.matrices;
      if (!c.matrices) o.eye = glm::dvec3(3.0, 2.5, 4.0);
    }
    const Transport whole = ComputeTransport(mesh, o, nullptr);
    const std::size_t n = CoeffCount(o.lmax);
    const std::vector<std::uint64_t> work(mesh.vertex_count(), 1);
    for (int i = 0; i < 3; ++i) {
      CAPTURE(i);
      TransportOptions b = o;
      b.block = BlockOf(work, i, 3);
      const Transport part = ComputeTransport(mesh, b, nullptr);
      CHECK(part.channels == whole.channels);
      CHECK(RowsAreTheWholeRuns(part.coeffs, whole.coeffs, n * whole.channels, b.block));
      CHECK(RowsAreTheWholeRuns(part.glossy, whole.glossy, n * whole.channels, b.block));
      CHECK(RowsAreTheWholeRuns(part.matrices, whole.matrices, n * n * whole.channels, b.block));
      CHECK(part.glossy.size() == (c.glossy && !c.matrices ? whole.coeffs.size() : 0));
      CHECK(part.matrices.size() == (c.matrices ? whole.coeffs.size() * n : 0));
    }
  }
}

}  // TEST_SUITE

}  // namespace prt
