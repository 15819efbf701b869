// The BVH against the brute-force reference: single rays and fans, on several meshes, with rays
// aimed exactly at vertices and edges.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/brute_force.h"
#include "geometry/bvh.h"
#include "geometry/ray_fan.h"
#include "tests/geometry/ray_sets.h"
#include "tests/test_support.h"

namespace prt {
namespace {

// Hit distances of the BVH and the reference come from the same float code on the same
// triangle, so they are equal; two different triangles may tie at a shared edge or vertex,
// where their distances agree to rounding of a few ulps, well inside 1e-6 relative.
constexpr double kDistanceTolerance = 1e-6;

bool SameDistance(float a, float b) {
  return std::abs(static_cast<double>(a) - b) <= kDistanceTolerance * std::abs(static_cast<double>(b));
}

struct Tally {
  int rays = 0, hits = 0, hit_miss_disagreements = 0, id_disagreements = 0, distance_disagreements = 0,
      ties = 0;
};

// Compares one closest-hit answer with the reference; ties between different triangles at the
// same distance (a ray through a shared edge) are ambiguous and only their distance is compared.
void Compare(const std::optional<Hit>& got, const std::optional<Hit>& want, Tally& tally) {
  ++tally.rays;
  if (got.has_value() != want.has_value()) {
    ++tally.hit_miss_disagreements;
    return;
  }
  if (!want) return;
  ++tally.hits;
  if (!SameDistance(got->t, want->t)) ++tally.distance_disagreements;
  if (got->triangle != want->triangle) {
    if (SameDistance(got->t, want->t)) ++tally.ties;
    else ++tally.id_disagreements;
  } else if (got->u != want->u || got->v != want->v || got->t != want->t) {
    ++tally.distance_disagreements;  // same triangle must give bit-identical answers
  }
}

}  // namespace

TEST_SUITE("geometry") {
  TEST_CASE("bvh agrees with brute force on 104k seeded rays, edges and vertices included, on every instruction set") {
    // Scaled under a sanitizer (tests/README.md): 8,000 rays a mesh, not 26,000.
    const int rays_per_mesh = test::kSanitized ? 8000 : 26000;
    test::ForEachIsa([&](const std::string& isa) {
      CAPTURE(isa);
      int total = 0;
      for (const auto& [name, mesh] : test::TestMeshes()) {
        CAPTURE(name);
        const Bvh bvh = Bvh::Build(mesh);
        const BruteForceCaster reference(mesh);
        Tally tally;
        int occluded_disagreements = 0;
        for (const Ray& ray : test::DifferentialRays(mesh, rays_per_mesh, 1234)) {
          const auto want = reference.Intersect(ray);
          Compare(bvh.Intersect(ray), want, tally);
          if (bvh.Occluded(ray) != want.has_value()) ++occluded_disagreements;
          if (reference.Occluded(ray) != want.has_value()) ++occluded_disagreements;
        }
        total += tally.rays;
        MESSAGE(isa << ", " << name << ": " << tally.rays << " rays, " << tally.hits << " hits, " << tally.ties << " ties");
        CHECK(tally.hits > tally.rays / 10);  // the rays do exercise the mesh
        CHECK(occluded_disagreements == 0);
        CHECK(tally.hit_miss_disagreements == 0);
        CHECK(tally.id_disagreements == 0);
        CHECK(tally.distance_disagreements == 0);
      }
      CHECK(total >= 4 * rays_per_mesh);
    });
  }

  TEST_CASE("fan traversal agrees with brute force ray by ray, on every instruction set") {
    const RayFan fan = MakeRayFan(test::FibonacciDirections(256));
    test::ForEachIsa([&](const std::string& isa) {
      CAPTURE(isa);
      for (const auto& [name, mesh] : test::TestMeshes()) {
        CAPTURE(name);
        const Bvh bvh = Bvh::Build(mesh);
        const BruteForceCaster reference(mesh);
        Pcg32 rng(99, 1);
        Tally tally;
        int occluded_disagreements = 0;
        std::vector<std::uint8_t> occluded;
        std::vector<std::optional<Hit>> hits;
        for (int k = 0; k < 40; ++k) {
          // Half the origins sit just off a vertex (the PRT case), half anywhere near the mesh.
          const std::size_t vi = rng.NextU32() % mesh.vertex_count();
          const glm::vec3 normal = k % 2 == 0 ? mesh.normals[vi] : test::UniformSphere(rng);
          const glm::vec3 origin = k % 2 == 0 ? OffsetRayOrigin(mesh.positions[vi], normal, bvh.SceneScale())
                                              : mesh.positions[vi] + 0.3f * test::UniformSphere(rng);
          const float tmax = k % 3 == 0 ? 0.7f : std::numeric_limits<float>::infinity();
          bvh.OccludedFan(fan, origin, normal, tmax, occluded);
          bvh.IntersectFan(fan, origin, normal, tmax, hits);
          for (std::size_t i = 0; i < fan.directions.size(); ++i) {
            const glm::vec3 d = fan.directions[i];
            const bool above = normal.x * d.x + normal.y * d.y + normal.z * d.z > 0.0f;
            const Ray ray{origin, d, 0.0f, tmax};
            const auto want = above ? reference.Intersect(ray) : std::nullopt;
            Compare(hits[i], want, tally);
            if ((occluded[i] != 0) != want.has_value()) ++occluded_disagreements;
          }
        }
        CHECK(tally.hits > 0);
        CHECK(occluded_disagreements == 0);
        CHECK(tally.hit_miss_disagreements == 0);
        CHECK(tally.id_disagreements == 0);
        CHECK(tally.distance_disagreements == 0);
      }
    });
  }

  TEST_CASE("watertight: rays from inside closed meshes through vertices and edges never leak, on every instruction set") {
    const RayFan fan = MakeRayFan(test::FibonacciDirections(512));
    test::ForEachIsa([&](const std::string& isa) {
      CAPTURE(isa);
      struct Case {
        Mesh mesh;
        glm::vec3 inside;
      };
      const std::vector<Case> cases = {
          {MakeSphere(40, 1.0f), glm::vec3(0.0f)},
          {MakeSphere(40, 1.0f), glm::vec3(0.3f, 0.2f, -0.1f)},
          {MakeBox(glm::vec3(-1.0f), glm::vec3(1.0f), BoxFacing::kOutward, 4), glm::vec3(0.0f)},
          {MakeTorusKnot(2, 3, 0.16f, 96, 12), glm::vec3(2.0f / 3.0f + 1.0f / 3.0f, 0.0f, 0.0f)}};
      for (std::size_t k = 0; k < cases.size(); ++k) {
        CAPTURE(k);
        const Mesh& m = cases[k].mesh;
        const Bvh bvh = Bvh::Build(m);
        const BruteForceCaster reference(m);
        int leaks = 0, rays = 0;
        // Exactly at every vertex, and at points of every edge (midpoint and a random fraction).
        Pcg32 rng(5, k);
        for (const auto& t : m.triangles) {
          for (int c = 0; c < 3; ++c) {
            const glm::vec3 a = m.positions[t[c]], b = m.positions[t[(c + 1) % 3]];
            for (const glm::vec3 target : {a, 0.5f * (a + b), a + static_cast<float>(rng.NextDouble()) * (b - a)}) {
              const Ray ray{cases[k].inside, target - cases[k].inside};
              leaks += bvh.Occluded(ray) ? 0 : 1;
              leaks += bvh.Intersect(ray) ? 0 : 1;
              leaks += reference.Occluded(ray) ? 0 : 1;
              rays += 3;
            }
          }
        }
        // And a full fan from the inside point.
        std::vector<std::uint8_t> occluded;
        for (const glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
          bvh.OccludedFan(fan, cases[k].inside, n, std::numeric_limits<float>::infinity(), occluded);
          for (std::size_t i = 0; i < occluded.size(); ++i)
            if (glm::dot(n, fan.directions[i]) > 0.0f) leaks += occluded[i] ? 0 : 1, ++rays;
        }
        CHECK(rays > 1000);
        CHECK(leaks == 0);
      }
    });
  }

  TEST_CASE("no self-shadowing on a lone convex mesh at scales 1e-4, 1 and 1e4") {
    const RayFan fan = MakeRayFan(test::FibonacciDirections(256));
    for (const float scale : {1e-4f, 1.0f, 1e4f}) {
      for (int shape = 0; shape < 2; ++shape) {
        CAPTURE(scale);
        CAPTURE(shape);
        // Far from the world origin too, so the coordinates' magnitude exceeds the mesh size.
        const glm::vec3 centre = scale * glm::vec3(3.0f, -2.0f, 1.5f);
        const Mesh m = shape == 0 ? MakeSphere(48, scale, centre)
                                  : MakeBox(centre - scale, centre + glm::vec3(scale, 2 * scale, scale),
                                            BoxFacing::kOutward, 3);
        const Bvh bvh = Bvh::Build(m);
        std::vector<std::uint8_t> occluded;
        int blocked = 0, rays = 0;
        for (std::size_t v = 0; v < m.vertex_count(); ++v) {
          const glm::vec3 n = m.normals[v];
          const glm::vec3 o = OffsetRayOrigin(m.positions[v], n, bvh.SceneScale());
          bvh.OccludedFan(fan, o, n, std::numeric_limits<float>::infinity(), occluded);
          for (std::size_t i = 0; i < occluded.size(); ++i) blocked += occluded[i];
          rays += static_cast<int>(fan.directions.size() / 2);
          // Grazing rays, 1e-4 radians above the tangent plane, single-ray path.
          const glm::vec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
          const glm::vec3 b = glm::cross(n, t);
          for (const glm::vec3 g : {t, -t, b, -b}) blocked += bvh.Occluded(Ray{o, g + 1e-4f * n}) ? 1 : 0;
        }
        CHECK(rays > 1000);
        CHECK(blocked == 0);
      }
    }
  }

  TEST_CASE("a point at the bottom of a closed room is fully occluded, an open sky is not") {
    const Mesh room = MakeBox(glm::vec3(-1.0f, 0.0f, -1.0f), glm::vec3(1.0f, 4.0f, 1.0f), BoxFacing::kInward, 2);
    const Bvh bvh = Bvh::Build(room);
    const RayFan fan = MakeRayFan(test::FibonacciDirections(1024));
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    std::vector<std::uint8_t> occluded;
    bvh.OccludedFan(fan, OffsetRayOrigin(glm::vec3(0.0f), n, bvh.SceneScale()), n,
                    std::numeric_limits<float>::infinity(), occluded);
    int above = 0, blocked = 0;
    for (std::size_t i = 0; i < occluded.size(); ++i)
      if (fan.directions[i].y > 0.0f) ++above, blocked += occluded[i];
    CHECK(above > 500);  // about half of the 1024 directions
    CHECK(blocked == above);
    // A ground plane alone blocks nothing above it.
    const Bvh ground = Bvh::Build(MakePlane(10.0f, 4));
    ground.OccludedFan(fan, OffsetRayOrigin(glm::vec3(1.0f, 0.0f, 2.0f), n, ground.SceneScale()), n,
                       std::numeric_limits<float>::infinity(), occluded);
    int any = 0;
    for (auto o : occluded) any += o;
    CHECK(any == 0);
  }

  TEST_CASE("bvh structure: 32-byte nodes, every triangle in exactly one leaf, boxes nest") {
    const Mesh m = MakeTorusKnot(2, 3, 0.16f, 128, 16);
    const Bvh bvh = Bvh::Build(m);
    std::vector<int> seen(m.triangle_count(), 0);
    int bad_nesting = 0;
    for (const BvhNode& n : bvh.nodes()) {
      if (n.count > 0) {
        for (std::uint32_t i = n.index; i < n.index + n.count; ++i) ++seen[bvh.prim_indices()[i]];
        continue;
      }
      for (std::uint32_t c = n.index; c < n.index + 2; ++c) {
        const BvhNode& child = bvh.nodes()[c];
        for (int a = 0; a < 3; ++a) bad_nesting += (child.lo[a] < n.lo[a] || child.hi[a] > n.hi[a]) ? 1 : 0;
      }
    }
    CHECK(bad_nesting == 0);
    CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(m.triangle_count()));
    CHECK(!Bvh::Build(Mesh{}).Occluded(Ray{}));
    CHECK(!Bvh::Build(Mesh{}).Intersect(Ray{}));
  }
}

}  // namespace prt
