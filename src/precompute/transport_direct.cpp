// Direct (shadowed) transfer: the closed form minus the Monte Carlo estimate of what is blocked.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <string>

#include <glm/geometric.hpp>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/parallel.h"
#include "core/progress.h"
#include "geometry/ray.h"
#include "precompute/transport_direct.h"
#include "sh/basis.h"
#include "sh/zonal.h"

namespace prt {

// Declared in hit_light.h; defined here, where the direct pass's loop calls it.
bool FrontSide(const Mesh& mesh, const Hit& hit, const glm::vec3& dir) {
  const auto& tri = mesh.triangles[hit.triangle];
  const glm::vec3& p0 = mesh.positions[tri[0]];
  glm::vec3 g = glm::cross(mesh.positions[tri[1]] - p0, mesh.positions[tri[2]] - p0);
  if (glm::dot(g, mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]]) < 0.0f) g = -g;
  return glm::dot(g, dir) < 0.0f;
}

namespace {

/// dot(n, d) of each of the `size` directions (x, y, z arrays at xyz, xyz + size, xyz + 2 size)
/// into `c`, evaluated as glm::dot does ((x + y) + z, no fused steps), and how many are above
/// the horizon (c > 0): the rays traced. Two directions at a time with SSE2 (every x86-64; GCC
/// does not vectorise this loop by itself), each lane rounding exactly as the scalar code.
std::size_t HorizonDots(const glm::dvec3& n, const double* xyz, std::size_t size, double* c) {
  const double* x = xyz;
  const double* y = xyz + size;
  const double* z = xyz + 2 * size;
  const double nx = n.x, ny = n.y, nz = n.z;
  std::size_t above = 0, i = 0;
#if defined(__SSE2__)
  const __m128d vx = _mm_set1_pd(nx), vy = _mm_set1_pd(ny), vz = _mm_set1_pd(nz), zero = _mm_setzero_pd();
  for (; i + 4 <= size; i += 4) {
    const __m128d c0 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, _mm_loadu_pd(x + i)), _mm_mul_pd(vy, _mm_loadu_pd(y + i))),
                                  _mm_mul_pd(vz, _mm_loadu_pd(z + i)));
    const __m128d c1 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(vx, _mm_loadu_pd(x + i + 2)), _mm_mul_pd(vy, _mm_loadu_pd(y + i + 2))),
                                  _mm_mul_pd(vz, _mm_loadu_pd(z + i + 2)));
    _mm_storeu_pd(c + i, c0);
    _mm_storeu_pd(c + i + 2, c1);
    const int mask = _mm_movemask_pd(_mm_cmpgt_pd(c0, zero)) | (_mm_movemask_pd(_mm_cmpgt_pd(c1, zero)) << 2);
    above += static_cast<std::size_t>((0x4332322132212110ULL >> (4 * mask)) & 0xF);  // popcount of 4 bits
  }
#endif
  for (; i < size; ++i) {
    c[i] = (nx * x[i] + ny * y[i]) + nz * z[i];
    above += c[i] > 0.0 ? 1 : 0;
  }
  return above;
}

/// Appends to `list` the directions i (increasing) with occluded[i] != 0 and c[i] > 0; returns
/// the new end. Eight flags at a time, the set ones found by their lowest bit.
std::uint32_t* ListBlocked(const std::uint8_t* occluded, const double* c, std::size_t size, std::uint32_t* list) {
  std::size_t i0 = 0;
  for (; i0 + 8 <= size; i0 += 8) {
    std::uint64_t w;
    std::memcpy(&w, occluded + i0, sizeof w);
    w = (((w & 0x7F7F7F7F7F7F7F7FULL) + 0x7F7F7F7F7F7F7F7FULL) | w) & 0x8080808080808080ULL;  // byte != 0
    while (w) {
      const std::size_t i = i0 + (static_cast<std::size_t>(__builtin_ctzll(w)) >> 3);
      *list = static_cast<std::uint32_t>(i);
      list += c[i] > 0.0 ? 1 : 0;  // the fan traces none at or below the horizon; float/double edge cases
      w &= w - 1;
    }
  }
  for (; i0 < size; ++i0)
    if (occluded[i0] && c[i0] > 0.0) *list++ = static_cast<std::uint32_t>(i0);
  return list;
}

/// t[k] -= (weight * c[i]) * basis[i][k] for the directions i of list[0 .. m) in that order:
/// the same operations, in the same order, as subtracting each blocked direction as it comes;
/// the sums kept in registers.
template <int kCount>
void SubtractBlocked(double* t, double weight, const double* c, const std::uint32_t* list, std::size_t m,
                     const double* basis) {
  double acc[kCount];
  for (int k = 0; k < kCount; ++k) acc[k] = t[k];
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = list[j];
    const double wc = weight * c[i];
    for (int k = 0; k < kCount; ++k) acc[k] -= wc * basis[i * kCount + k];
  }
  for (int k = 0; k < kCount; ++k) t[k] = acc[k];
}

void SubtractBlocked(int count, double* t, double weight, const double* c, const std::uint32_t* list, std::size_t m,
                     const double* basis) {
  if (count == 9) return SubtractBlocked<9>(t, weight, c, list, m, basis);
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t i = list[j];
    const double wc = weight * c[i];
    for (int k = 0; k < count; ++k) t[k] -= wc * basis[i * count + k];
  }
}

/// Largest basis table of one direction set (doubles: 2 MiB, lmax 2 up to 29127 directions;
/// 1024 directions up to lmax 15) kept per thread; beyond it the basis is evaluated per blocked
/// direction.
constexpr std::size_t kMaxBasisTable = std::size_t(1) << 18;

}  // namespace

namespace {

/// The direct transfer of the vertices of `vertices`, each traced with its set of `pool`.
void RunPass(const Mesh& mesh, const Bvh& bvh, const DirectionPool& pool, int lmax, bool keep_hits,
             const std::vector<std::uint32_t>& vertices, const std::string& what, DirectResult& result) {
  const int count = CoeffCount(lmax);
  const float scene_scale = bvh.SceneScale();
  const double weight = 4.0 / double(pool.size());  // (4 pi / N) * (1 / pi)
  std::atomic<std::uint64_t> rays{0}, evaluations{0};
  Progress progress(what, vertices.size());

  // Any-hit rays: the directions of each set as three arrays, so that the horizon test of all
  // of a vertex's directions (the count of rays it traces) is one vectorised pass; then only the
  // blocked directions above the horizon are visited, in increasing order, their basis taken from
  // a table of the set's directions (made once per run of the set's vertices, see `order`) and
  // subtracted with the sums in registers: the same operations in the same order as one
  // direction at a time, so the same transfer to the bit.
  std::vector<std::vector<double>> soa;
  if (!keep_hits) {
    soa.resize(pool.sets.size());
    for (std::size_t s = 0; s < pool.sets.size(); ++s) {
      const auto& dirs = pool.sets[s];
      const std::size_t n = dirs.size();
      soa[s].resize(3 * n);
      for (std::size_t i = 0; i < n; ++i) soa[s][i] = dirs[i].x, soa[s][n + i] = dirs[i].y, soa[s][2 * n + i] = dirs[i].z;
    }
  }

  // Vertices in the order of their direction sets (then by index): consecutive vertices then
  // share a set, whose fan and arrays stay in the cache. Each vertex's result is its own, so the
  // order changes nothing else.
  std::vector<std::uint32_t> order(vertices.size());
  {
    std::vector<std::uint32_t> start(pool.sets.size() + 1, 0);
    for (std::uint32_t v : vertices) ++start[pool.SetOf(v) + 1];
    for (std::size_t s = 0; s < pool.sets.size(); ++s) start[s + 1] += start[s];
    for (std::uint32_t v : vertices) order[start[pool.SetOf(v)]++] = v;
  }

  ParallelFor(order.size(), 64, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint8_t> blocked;
    std::vector<std::optional<Hit>> hits;
    std::vector<double> y(count), t(count);
    // Any-hit path: dot products, blocked directions, and the basis of the last set's directions.
    std::vector<double> dots, table;
    std::vector<std::uint32_t> list;
    std::size_t table_set = std::numeric_limits<std::size_t>::max();
    std::uint64_t local_rays = 0, local_evaluations = 0;
    for (std::size_t o = begin; o < end; ++o) {
      const std::size_t v = order[o];
      const std::size_t set = pool.SetOf(v);
      const auto& dirs = pool.sets[set];
      const glm::vec3 n = mesh.normals[v];
      const glm::vec3 origin = OffsetRayOrigin(mesh.positions[v], n, scene_scale);
      if (!keep_hits) {
        bvh.OccludedFan(pool.fans[set], origin, n, std::numeric_limits<float>::infinity(), blocked);
        UnshadowedTransfer(lmax, glm::dvec3(n), t.data());
        const std::size_t size = dirs.size();
        const double* xyz = soa[set].data();
        dots.resize(size);
        list.resize(size);
        const std::size_t above = HorizonDots(glm::dvec3(n), xyz, size, dots.data());
        const std::size_t blocked_above =
            static_cast<std::size_t>(ListBlocked(blocked.data(), dots.data(), size, list.data()) - list.data());
        if (size * count <= kMaxBasisTable) {
          if (table_set != set) {  // the basis of every direction of the set, once per run of its vertices
            table.resize(size * count);
            for (std::size_t i = 0; i < size; ++i)
              EvalBasis(lmax, glm::dvec3(xyz[i], xyz[size + i], xyz[2 * size + i]), table.data() + i * count);
            table_set = set;
            local_evaluations += size;
          }
          SubtractBlocked(count, t.data(), weight, dots.data(), list.data(), blocked_above, table.data());
        } else {  // a table would be too large: each blocked direction's basis as it comes
          for (std::size_t j = 0; j < blocked_above; ++j) {
            const std::size_t i = list[j];
            EvalBasis(lmax, dirs[i], y.data());
            ++local_evaluations;
            const double wc = weight * dots[i];
            for (int k = 0; k < count; ++k) t[k] -= wc * y[k];
          }
        }
        local_rays += above;
        result.unoccluded[v] = blocked_above == 0;
        const bool any_open = above > blocked_above;
        result.sees_sky[v] = any_open;
        if (!any_open) std::fill(t.begin(), t.end(), 0.0);  // as below
        std::copy(t.begin(), t.end(), result.transfer.begin() + v * count);
        continue;
      }
      bvh.IntersectFan(pool.fans[set], origin, n, std::numeric_limits<float>::infinity(), hits);
      UnshadowedTransfer(lmax, glm::dvec3(n), t.data());
      bool any_blocked = false, any_open = false;
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        const double c = glm::dot(glm::dvec3(n), dirs[i]);
        if (c <= 0.0) continue;
        ++local_rays;
        const bool is_blocked = hits[i].has_value();
        any_open |= !is_blocked;
        if (!is_blocked) continue;
        any_blocked = true;
        EvalBasis(lmax, dirs[i], y.data());
        ++local_evaluations;
        for (int k = 0; k < count; ++k) t[k] -= weight * c * y[k];
        const Hit& h = *hits[i];
        result.hits[v].push_back({h.triangle, h.u, h.v, static_cast<std::uint32_t>(i),
                                  FrontSide(mesh, h, glm::vec3(dirs[i]))});
      }
      result.unoccluded[v] = !any_blocked;
      result.sees_sky[v] = any_open;
      // Nothing open: the transfer is exactly zero (the estimate of the blocked part would
      // only cancel the closed form up to its sampling noise).
      if (!any_open) std::fill(t.begin(), t.end(), 0.0);
      std::copy(t.begin(), t.end(), result.transfer.begin() + v * count);
    }
    rays += local_rays;
    evaluations += local_evaluations;
    progress.Advance(end - begin);
  });
  result.rays += rays;
  result.basis_evaluations += evaluations;
}

}  // namespace

DirectResult ComputeDirect(const Mesh& mesh, const Bvh& bvh, const DirectionPlan& plan, int lmax,
                           bool keep_hits, const VertexBlock& block) {
  const std::size_t nv = mesh.vertex_count();
  DirectResult result;
  result.transfer.resize(nv * CoeffCount(lmax));
  if (keep_hits) result.hits.resize(nv);
  result.sees_sky.resize(nv);
  result.unoccluded.resize(nv);
  const std::string what = keep_hits ? "direct transfer (closest hits)" : "shadowed transfer";
  for (std::size_t p = 0; p < plan.pools.size(); ++p) {
    std::vector<std::uint32_t> vertices;
    vertices.reserve(nv);
    for (std::size_t v = std::min(block.begin, nv); v < std::min(block.end, nv); ++v)
      if ((plan.pool_of.empty() ? 0 : plan.pool_of[v]) == p) vertices.push_back(static_cast<std::uint32_t>(v));
    const std::string label =
        plan.pools.size() == 1 ? what : what + (p == 0 ? ", vertices the camera sees" : ", vertices it does not");
    RunPass(mesh, bvh, plan.pools[p], lmax, keep_hits, vertices, label, result);
  }
  return result;
}

}  // namespace prt
