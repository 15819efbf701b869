// The 8-wide tree that traversal runs on: its structure (full blocks, filled nodes, boxes
// padded for the fused slab test), and agreement with brute force on every instruction set for
// binary leaves of 1, 20 and 64 triangles, a pile of coincident triangles, which SAH cannot
// split (the median fallback below depth 96 must keep the leaves small), a small mesh far from
// the origin, where the fused test's padding matters most, and rays that take the exact test;
// and closest-hit fans (packets, bvh_packet_traverse.h) against single rays bit for bit where
// the order of leaves could decide: tied hits at vertices and in the pile.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "core/rng.h"
#include "geometry/brute_force.h"
#include "geometry/bvh.h"
#include "geometry/mesh_ops.h"
#include "geometry/procedural.h"
#include "geometry/ray_fan.h"
#include "tests/geometry/ray_sets.h"

namespace prt {

// Hit distances of two triangles tied at a shared edge or vertex: a few ulps apart.
constexpr double kTieTolerance = 1e-6;
// The optimal collapse averages about 6 children per node on a torus knot; the greedy one about
// 4. Between them, so the test catches a collapse that stops filling nodes.
constexpr double kMinMeanChildren = 5.0;

TEST_SUITE("geometry") {
  TEST_CASE("wide bvh: every triangle in one leaf, full blocks, boxes padded around their contents") {
    const Mesh m = MakeTorusKnot(2, 3, 0.16f, 128, 16);
    for (const int leaf : {1, 8, 20, 64}) {
      CAPTURE(leaf);
      BvhOptions opt;
      opt.max_leaf_size = leaf;
      const Bvh bvh = Bvh::Build(m, opt);
      const WideBvh& w = bvh.wide();
      // The padding the fused slab test needs (bvh_wide.h): 2^-23 of the origin bound.
      const double pad = 0x1.0p-23 * w.fused_origin_bound;
      CHECK(w.fused_origin_bound >= 2.0f * std::max({std::abs(bvh.nodes()[0].lo.x), std::abs(bvh.nodes()[0].hi.x),
                                                     std::abs(bvh.nodes()[0].lo.y), std::abs(bvh.nodes()[0].hi.y),
                                                     std::abs(bvh.nodes()[0].lo.z), std::abs(bvh.nodes()[0].hi.z)}));
      std::vector<int> seen(m.triangle_count(), 0);
      int unpadded = 0, short_blocks = 0;
      // The corners' box of every child, bottom up; each stored box must hold it grown by pad.
      std::function<Bounds3(WideRef)> contents = [&](WideRef ref) {
        Bounds3 b;
        if (IsLeaf(ref)) {
          std::vector<std::uint32_t> ids;
          for (std::uint32_t k = 0; k < LeafBlockCount(ref); ++k) {
            const TriangleBlock& block = w.blocks[LeafFirstBlock(ref) + k];
            for (int l = 0; l < kBlockWidth; ++l) {
              ids.push_back(block.id[l]);
              for (int c = 0; c < 3; ++c) b.Extend(glm::vec3(block.p[c][0][l], block.p[c][1][l], block.p[c][2][l]));
            }
          }
          std::sort(ids.begin(), ids.end());
          ids.erase(std::unique(ids.begin(), ids.end()), ids.end());  // a short block repeats
          for (std::uint32_t id : ids) ++seen[id];
          // Blocks are full but for the last: as few blocks as the triangles need.
          short_blocks += LeafBlockCount(ref) == (ids.size() + kBlockWidth - 1) / kBlockWidth ? 0 : 1;
          return b;
        }
        const WideNode& n = w.nodes[ref];
        for (int c = 0; c < kBvhWidth; ++c) {
          if (n.child[c] == kWideEmpty) continue;
          const Bounds3 inner = contents(n.child[c]);
          for (int a = 0; a < 3; ++a) {
            unpadded += n.planes[a][c] > inner.lo[a] - pad ? 1 : 0;
            unpadded += n.planes[3 + a][c] < inner.hi[a] + pad ? 1 : 0;
          }
          b.Extend(inner.lo), b.Extend(inner.hi);
        }
        return b;
      };
      contents(0);
      CHECK(unpadded == 0);
      CHECK(short_blocks == 0);
      CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(m.triangle_count()));
    }
  }

  TEST_CASE("wide bvh: the collapse fills nodes (more than 5 children on average on the knot)") {
    const Bvh bvh = Bvh::Build(MakeTorusKnot(2, 3, 0.16f, 256, 24));
    int children = 0;
    for (const WideNode& n : bvh.wide().nodes)
      for (const WideRef c : n.child) children += c == kWideEmpty ? 0 : 1;
    const double mean = static_cast<double>(children) / static_cast<double>(bvh.wide().nodes.size());
    MESSAGE("children per wide node: " << mean << " over " << bvh.wide().nodes.size() << " nodes");
    // The greedy collapse (open the largest child until eight) gives about 4 here.
    CHECK(mean > kMinMeanChildren);
  }

  TEST_CASE("wide bvh: leaf sizes 1, 20, 64, a pile of coincident triangles and a small mesh far from the origin agree with brute force on every instruction set") {
    Mesh pile = MakeSphere(6, 1.0f);
    const Mesh one = pile;
    for (int k = 0; k < 60; ++k) AppendMesh(pile, one);  // 61 copies of every triangle
    // 1e-2 across and 1e3 away: the rounding of origin * inverse that the fused slab test
    // pads for is a few ulps of 1e3, about 1e-4, a hundredth of the mesh (bvh_wide.h).
    Mesh far = MakeTorusKnot(2, 3, 0.16f, 96, 12);
    for (glm::vec3& p : far.positions) p = 1e-2f * p + glm::vec3(1000.0f, -1000.0f, 500.0f);
    std::vector<std::pair<Mesh, int>> cases = {{MakeTorusKnot(2, 3, 0.16f, 96, 12), 1},
                                               {MakeTorusKnot(2, 3, 0.16f, 96, 12), 20},
                                               {MakeTorusKnot(2, 3, 0.16f, 96, 12), 64},
                                               {pile, 4},
                                               {far, 8}};
    test::ForEachIsa([&](const std::string& isa) {
      CAPTURE(isa);
      for (std::size_t k = 0; k < cases.size(); ++k) {
        CAPTURE(k);
        const Mesh& mesh = cases[k].first;
        BvhOptions opt;
        opt.max_leaf_size = cases[k].second;
        const Bvh bvh = Bvh::Build(mesh, opt);
        const BruteForceCaster reference(mesh);
        int disagreements = 0;
        for (const Ray& ray : test::DifferentialRays(mesh, 4000, 77)) {
          const auto want = reference.Intersect(ray);
          const auto got = bvh.Intersect(ray);
          disagreements += bvh.Occluded(ray) != want.has_value() ? 1 : 0;
          disagreements += got.has_value() != want.has_value() ? 1 : 0;
          if (!got || !want) continue;
          // The same triangle gives the same t (same float code); two triangles tied at a
          // shared edge agree to a few ulps (kTieTolerance).
          const double tol = got->triangle == want->triangle ? 0.0 : kTieTolerance * want->t;
          disagreements += std::abs(static_cast<double>(got->t) - want->t) > tol ? 1 : 0;
        }
        CHECK(disagreements == 0);
      }
    });
  }

  TEST_CASE("wide bvh: rays and fans the fused slab test does not cover (far origins, almost axis-parallel directions) agree with brute force") {
    const Mesh mesh = MakeTorusKnot(2, 3, 0.16f, 96, 12);
    const Bvh bvh = Bvh::Build(mesh);
    const BruteForceCaster reference(mesh);
    const float bound = bvh.wide().fused_origin_bound;
    Pcg32 rng(31, 7);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < mesh.vertex_count(); i += 7) {
      const glm::vec3 target = mesh.positions[i];
      // From beyond the bound, aimed exactly at a vertex.
      const glm::vec3 from = target + 3.0f * bound * test::UniformSphere(rng);
      rays.push_back(Ray{from, target - from});
      // Along an axis but for a component of 1e-31, whose inverse times the origin overflows.
      glm::vec3 d(0.0f);
      d[static_cast<int>(i % 3)] = i % 2 == 0 ? 1.0f : -1.0f;
      d[static_cast<int>((i + 1) % 3)] = 1e-31f;
      rays.push_back(Ray{target - 2.0f * d, d});
    }
    test::ForEachIsa([&](const std::string& isa) {
      CAPTURE(isa);
      int disagreements = 0, hits = 0;
      for (const Ray& ray : rays) {
        const auto want = reference.Intersect(ray);
        hits += want ? 1 : 0;
        disagreements += bvh.Occluded(ray) != want.has_value() ? 1 : 0;
        const auto got = bvh.Intersect(ray);
        disagreements += got.has_value() != want.has_value() ? 1 : 0;
        if (got && want) disagreements += std::abs(static_cast<double>(got->t) - want->t) > kTieTolerance * want->t ? 1 : 0;
      }
      CHECK(hits > static_cast<int>(rays.size()) / 2);
      CHECK(disagreements == 0);
      // A fan from beyond the bound: its packets take the exact test too.
      const RayFan fan = MakeRayFan(test::FibonacciDirections(4096));
      const glm::vec3 origin(3.0f * bound, 0.5f, 0.25f), towards(-1.0f, 0.0f, 0.0f);
      std::vector<std::uint8_t> occluded;
      bvh.OccludedFan(fan, origin, towards, std::numeric_limits<float>::infinity(), occluded);
      int fan_disagreements = 0, fan_hits = 0;
      for (std::size_t i = 0; i < fan.directions.size(); ++i) {
        const bool above = glm::dot(towards, fan.directions[i]) > 0.0f;
        const bool want = above && reference.Occluded(Ray{origin, fan.directions[i]});
        fan_hits += want ? 1 : 0;
        fan_disagreements += (occluded[i] != 0) != want ? 1 : 0;
      }
      CHECK(fan_hits > 0);
      CHECK(fan_disagreements == 0);
    });
  }

  TEST_CASE("closest-hit fans give each ray's single-ray answer bit for bit, tied hits included, on every instruction set") {
    // Tied hits are where the order of leaves could decide: 61 copies of every triangle, and
    // rays aimed exactly at vertices, where several triangles meet at one distance.
    Mesh pile = MakeSphere(6, 1.0f);
    const Mesh one = pile;
    for (int k = 0; k < 60; ++k) AppendMesh(pile, one);
    std::vector<test::NamedMesh> meshes = test::TestMeshes();
    meshes.push_back({"pile", pile});
    const RayFan fibonacci = MakeRayFan(test::FibonacciDirections(512));
    test::ForEachIsa([&](const std::string& isa) {
      CAPTURE(isa);
      for (const test::NamedMesh& named : meshes) {
        CAPTURE(named.name);
        const Mesh& mesh = named.mesh;
        const Bvh bvh = Bvh::Build(mesh);
        Pcg32 rng(5, 9);
        int rays = 0, hits = 0, disagreements = 0;
        std::vector<std::optional<Hit>> got;
        for (int k = 0; k < 24; ++k) {
          const std::size_t vi = rng.NextU32() % mesh.vertex_count();
          const glm::vec3 normal = k % 2 == 0 ? mesh.normals[vi] : test::UniformSphere(rng);
          const glm::vec3 origin = k % 2 == 0 ? OffsetRayOrigin(mesh.positions[vi], normal, bvh.SceneScale())
                                              : mesh.positions[vi] + 0.5f * test::UniformSphere(rng);
          const float tmax = k % 3 == 0 ? 0.7f : std::numeric_limits<float>::infinity();
          // Every third fan: from the origin exactly to 256 vertices.
          RayFan at_vertices;
          if (k % 3 == 1) {
            std::vector<glm::vec3> dirs;
            for (int i = 0; i < 256; ++i) {
              const glm::vec3 d = mesh.positions[rng.NextU32() % mesh.vertex_count()] - origin;
              if (glm::dot(d, d) > 0.0f) dirs.push_back(d);
            }
            at_vertices = MakeRayFan(dirs);
          }
          const RayFan& fan = k % 3 == 1 ? at_vertices : fibonacci;
          bvh.IntersectFan(fan, origin, normal, tmax, got);
          for (std::size_t i = 0; i < fan.directions.size(); ++i) {
            const glm::vec3 d = fan.directions[i];
            const auto want = glm::dot(normal, d) > 0.0f ? bvh.Intersect(Ray{origin, d, 0.0f, tmax}) : std::nullopt;
            ++rays;
            hits += want ? 1 : 0;
            if (got[i].has_value() != want.has_value()) {
              ++disagreements;
            } else if (want) {
              const bool same = got[i]->triangle == want->triangle && got[i]->t == want->t &&
                                got[i]->u == want->u && got[i]->v == want->v;
              disagreements += same ? 0 : 1;
            }
          }
        }
        CAPTURE(rays);
        CHECK(hits > rays / 16);
        CHECK(disagreements == 0);
      }
    });
  }
}

}  // namespace prt
