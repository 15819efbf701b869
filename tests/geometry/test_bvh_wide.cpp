// The 8-wide tree that traversal runs on: its structure, and agreement with brute force for
// leaves of one block (1 and 8 triangles), three blocks (20) and the most blocks (64), and for
// a pile of coincident triangles, which SAH cannot split (the median fallback below depth 96
// must keep the leaves small).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "geometry/brute_force.h"
#include "geometry/bvh.h"
#include "geometry/procedural.h"
#include "tests/geometry/ray_sets.h"

namespace prt {

// Hit distances of two triangles tied at a shared edge or vertex: a few ulps apart.
constexpr double kTieTolerance = 1e-6;

TEST_SUITE("geometry") {
  TEST_CASE("wide bvh: every triangle in a leaf block, child boxes inside their binary parents' root") {
    const Mesh m = MakeTorusKnot(2, 3, 0.16f, 128, 16);
    for (const int leaf : {1, 8, 20, 64}) {
      CAPTURE(leaf);
      BvhOptions opt;
      opt.max_leaf_size = leaf;
      const Bvh bvh = Bvh::Build(m, opt);
      const WideBvh& w = bvh.wide();
      std::vector<int> seen(m.triangle_count(), 0);
      int outside_root = 0;
      const BvhNode& root = bvh.nodes()[0];
      for (const WideNode& n : w.nodes) {
        for (int c = 0; c < kBvhWidth; ++c) {
          if (n.child[c] == kWideEmpty) continue;
          for (int a = 0; a < 3; ++a)
            outside_root += (n.planes[a][c] < root.lo[a] || n.planes[3 + a][c] > root.hi[a]) ? 1 : 0;
          if (!IsLeaf(n.child[c])) continue;
          // Distinct ids of the leaf's blocks (a short block repeats its last triangle).
          std::vector<std::uint32_t> ids;
          for (std::uint32_t b = 0; b < LeafBlockCount(n.child[c]); ++b)
            for (std::uint32_t id : w.blocks[LeafFirstBlock(n.child[c]) + b].id) ids.push_back(id);
          std::sort(ids.begin(), ids.end());
          ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
          CHECK(ids.size() <= static_cast<std::size_t>(leaf));
          for (std::uint32_t id : ids) ++seen[id];
        }
      }
      CHECK(outside_root == 0);
      CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(m.triangle_count()));
    }
  }

  TEST_CASE("wide bvh: leaf sizes 1, 20, 64 and a pile of coincident triangles agree with brute force") {
    Mesh pile = MakeSphere(6, 1.0f);
    const Mesh one = pile;
    for (int k = 0; k < 60; ++k) AppendMesh(pile, one);  // 61 copies of every triangle
    std::vector<std::pair<Mesh, int>> cases = {{MakeTorusKnot(2, 3, 0.16f, 96, 12), 1},
                                               {MakeTorusKnot(2, 3, 0.16f, 96, 12), 20},
                                               {MakeTorusKnot(2, 3, 0.16f, 96, 12), 64},
                                               {pile, 4}};
    for (const auto& [mesh, leaf] : cases) {
      CAPTURE(leaf);
      BvhOptions opt;
      opt.max_leaf_size = leaf;
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
  }
}

}  // namespace prt
