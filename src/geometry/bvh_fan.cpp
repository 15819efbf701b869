// Fan traversal of Bvh: one packet of kFanWidth directions from a shared origin goes down the
// tree together (see ray_fan.h). Lanes are GCC/Clang vector types, so the same source compiles
// to SSE2 by default and to AVX2 in the clone picked at run time on CPUs that have it.
#include <cstring>
#include <limits>

#include "geometry/box_test.h"
#include "geometry/bvh.h"
#include "geometry/ray_fan.h"
#include "geometry/triangle.h"

// The lane helpers below pass vectors by value; they are internal and inlined, so GCC's note
// that such an ABI differs with and without AVX does not concern them.
#pragma GCC diagnostic ignored "-Wpsabi"

// Every lane helper is forced inline so lanes stay in registers.
#define PRT_INLINE inline __attribute__((always_inline))

namespace prt {
namespace {

constexpr int K = kFanWidth;
using VF = float __attribute__((vector_size(4 * K)));
using VI = std::int32_t __attribute__((vector_size(4 * K)));
constexpr int kStackSize = 128;  // > the build's depth limit

PRT_INLINE VF Load(const float* p) {
  VF v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
PRT_INLINE VF Min(VF a, VF b) { return a < b ? a : b; }
PRT_INLINE VF Max(VF a, VF b) { return a > b ? a : b; }
PRT_INLINE VF Splat(float x) { return VF{} + x; }

// Lane mask <-> bits.
PRT_INLINE std::uint32_t Bits(VI m) {
  std::uint32_t b = 0;
  for (int l = 0; l < K; ++l) b |= (m[l] != 0 ? 1u : 0u) << l;
  return b;
}
PRT_INLINE VI LaneMask(std::uint32_t bits) {
  VI lane_bit;
  for (int l = 0; l < K; ++l) lane_bit[l] = 1 << l;
  return (lane_bit & static_cast<std::int32_t>(bits)) != 0;
}

// Lanes (among `mask`) whose ray enters the box [lo, hi] within (0, tmax).
PRT_INLINE std::uint32_t BoxLanes(const BvhNode& n, const glm::vec3& org, const FanPacket& p,
                              VF tmax, std::uint32_t mask) {
  const VF tx0 = (n.lo.x - org.x) * Load(p.inv[0]), tx1 = (n.hi.x - org.x) * Load(p.inv[0]);
  const VF ty0 = (n.lo.y - org.y) * Load(p.inv[1]), ty1 = (n.hi.y - org.y) * Load(p.inv[1]);
  const VF tz0 = (n.lo.z - org.z) * Load(p.inv[2]), tz1 = (n.hi.z - org.z) * Load(p.inv[2]);
  const VF tnear = Max(Max(Min(tx0, tx1), Min(ty0, ty1)), Max(Min(tz0, tz1), Splat(0.0f)));
  const VF tfar = Min(Min(Max(tx0, tx1), Max(ty0, ty1)), Min(Max(tz0, tz1), tmax)) * kSlabFarScale;
  return Bits(tnear <= tfar) & mask;
}

// Watertight test of triangle c on the lanes of `mask` (the lane-parallel form of
// IntersectTriangle, same operations in the same order). Returns the hit lanes; writes t, u, v.
PRT_INLINE std::uint32_t TriangleLanes(const std::array<glm::vec3, 3>& c, const glm::vec3& org,
                                   const FanPacket& p, VF tmax, std::uint32_t mask, VF& t, VF& u, VF& v) {
  const glm::vec3 A = c[0] - org, B = c[1] - org, C = c[2] - org;
  const VF sx = Load(p.shear[0]), sy = Load(p.shear[1]), sz = Load(p.shear[2]);
  const VF ax = A[p.kx] - sx * A[p.kz], ay = A[p.ky] - sy * A[p.kz];
  const VF bx = B[p.kx] - sx * B[p.kz], by = B[p.ky] - sy * B[p.kz];
  const VF cx = C[p.kx] - sx * C[p.kz], cy = C[p.ky] - sy * C[p.kz];
  const VF e0 = cx * by - cy * bx;
  const VF e1 = ax * cy - ay * cx;
  const VF e2 = bx * ay - by * ax;
  const VF zero = Splat(0.0f);
  const VI outside = ((e0 < zero) | (e1 < zero) | (e2 < zero)) & ((e0 > zero) | (e1 > zero) | (e2 > zero));
  const VF det = e0 + e1 + e2;
  const VF T = e0 * (sz * A[p.kz]) + e1 * (sz * B[p.kz]) + e2 * (sz * C[p.kz]);
  const VF lo = zero * det, hi = tmax * det;  // tmin = 0
  const VI out_of_range = (det > zero) ? ((T <= lo) | (T >= hi)) : ((T >= lo) | (T <= hi));
  const VI hit = ~outside & (det != zero) & ~out_of_range;
  const VF inv_det = 1.0f / det;
  t = T * inv_det;
  u = e1 * inv_det;
  v = e2 * inv_det;
  std::uint32_t bits = Bits(hit) & mask;
  // Lanes with an edge function of exactly 0 redo the scalar test (which refines in double).
  const std::uint32_t exact = Bits((e0 == zero) | (e1 == zero) | (e2 == zero)) & mask;
  for (std::uint32_t m = exact; m != 0; m &= m - 1) {
    const int l = __builtin_ctz(m);
    ShearedRay r;
    r.kx = p.kx, r.ky = p.ky, r.kz = p.kz, r.sx = p.shear[0][l], r.sy = p.shear[1][l], r.sz = p.shear[2][l];
    float tl, ul, vl;
    const bool h = IntersectTriangle(org, r, c[0], c[1], c[2], 0.0f, tmax[l], tl, ul, vl);
    bits = h ? bits | (1u << l) : bits & ~(1u << l);
    if (h) t[l] = tl, u[l] = ul, v[l] = vl;
  }
  return bits;
}

// Which child to visit first: the one whose centre lies further along the packet's first
// direction is behind the other.
PRT_INLINE bool LeftFirst(const BvhNode& l, const BvhNode& r, const FanPacket& p) {
  const glm::vec3 d(p.dir[0][0], p.dir[1][0], p.dir[2][0]);
  const glm::vec3 delta = (l.lo + l.hi) - (r.lo + r.hi);
  return delta.x * d.x + delta.y * d.y + delta.z * d.z <= 0.0f;
}

struct StackEntry {
  std::uint32_t node;
  std::uint32_t mask;
};

// Traces one packet. `closest` false: any hit, returns the occluded lanes. `closest` true:
// closest hit per lane in (t, tri, u, v), returns the lanes that hit.
template <bool closest>
PRT_INLINE
std::uint32_t TracePacket(const std::vector<BvhNode>& nodes, const std::vector<std::array<glm::vec3, 3>>& corners,
                          const FanPacket& p, const glm::vec3& org, std::uint32_t active, VF tmax,
                          VF& best_t, VI& best_tri, VF& best_u, VF& best_v) {
  std::uint32_t found = 0;
  StackEntry stack[kStackSize];
  int top = 0;
  stack[top++] = {0, active};
  while (top > 0) {
    const StackEntry e = stack[--top];
    const std::uint32_t mask = BoxLanes(nodes[e.node], org, p, tmax, e.mask & active);
    if (mask == 0) continue;
    const BvhNode& n = nodes[e.node];
    if (n.count == 0) {
      const bool left_first = LeftFirst(nodes[n.index], nodes[n.index + 1], p);
      stack[top++] = {left_first ? n.index + 1 : n.index, mask};
      stack[top++] = {left_first ? n.index : n.index + 1, mask};
      continue;
    }
    std::uint32_t live = mask;
    for (std::uint32_t i = n.index; i < n.index + n.count && live != 0; ++i) {
      VF t, u, v;
      const std::uint32_t hit = TriangleLanes(corners[i], org, p, tmax, live, t, u, v);
      if (hit == 0) continue;
      found |= hit;
      if constexpr (closest) {
        const VI h = LaneMask(hit);
        tmax = h ? t : tmax;
        best_t = h ? t : best_t;
        best_u = h ? u : best_u;
        best_v = h ? v : best_v;
        best_tri = h ? static_cast<std::int32_t>(i) : best_tri;
      } else {
        active &= ~hit;  // occluded lanes are done
        live &= ~hit;
      }
    }
    if (!closest && active == 0) break;
  }
  return found;
}

PRT_INLINE std::uint32_t HorizonLanes(const FanPacket& p, const glm::vec3& normal) {
  const VF c = normal.x * Load(p.dir[0]) + normal.y * Load(p.dir[1]) + normal.z * Load(p.dir[2]);
  return Bits(c > Splat(0.0f)) & ((1u << p.count) - 1u);
}

// The two traversals, compiled twice: for AVX2 (one instruction per 8 lanes) and for the
// baseline x86-64 (two SSE instructions per 8 lanes); the loader picks the clone the CPU runs.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PRT_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define PRT_CLONES
#endif

// Occlusion of the lanes of `active`: returns the occluded ones.
PRT_CLONES std::uint32_t OccludedPacket(const std::vector<BvhNode>& nodes,
                                        const std::vector<std::array<glm::vec3, 3>>& corners,
                                        const FanPacket& p, const glm::vec3& org, std::uint32_t active,
                                        float tmax) {
  VF t{}, u{}, v{};
  VI tri{};
  return TracePacket<false>(nodes, corners, p, org, active, Splat(tmax), t, tri, u, v);
}

// Closest hits of the lanes of `active`: returns the lanes that hit, fills the per-lane arrays.
PRT_CLONES std::uint32_t IntersectPacket(const std::vector<BvhNode>& nodes,
                                         const std::vector<std::array<glm::vec3, 3>>& corners,
                                         const FanPacket& p, const glm::vec3& org, std::uint32_t active,
                                         float tmax, float* t_out, std::int32_t* tri_out, float* u_out,
                                         float* v_out) {
  VF t{}, u{}, v{};
  VI tri{};
  const std::uint32_t hit = TracePacket<true>(nodes, corners, p, org, active, Splat(tmax), t, tri, u, v);
  std::memcpy(t_out, &t, sizeof t);
  std::memcpy(tri_out, &tri, sizeof tri);
  std::memcpy(u_out, &u, sizeof u);
  std::memcpy(v_out, &v, sizeof v);
  return hit;
}

}  // namespace

void Bvh::OccludedFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                      std::vector<std::uint8_t>& occluded) const {
  occluded.assign(fan.directions.size(), 0);
  if (nodes_.empty()) return;
  for (const FanPacket& p : fan.packets) {
    const std::uint32_t active = HorizonLanes(p, normal);
    if (active == 0) continue;
    const std::uint32_t hit = OccludedPacket(nodes_, corners_, p, origin, active, tmax);
    for (std::uint32_t m = hit; m != 0; m &= m - 1) occluded[p.index[__builtin_ctz(m)]] = 1;
  }
}

void Bvh::IntersectFan(const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal, float tmax,
                       std::vector<std::optional<Hit>>& hits) const {
  hits.assign(fan.directions.size(), std::nullopt);
  if (nodes_.empty()) return;
  for (const FanPacket& p : fan.packets) {
    const std::uint32_t active = HorizonLanes(p, normal);
    if (active == 0) continue;
    float t[K], u[K], v[K];
    std::int32_t tri[K];
    const std::uint32_t hit = IntersectPacket(nodes_, corners_, p, origin, active, tmax, t, tri, u, v);
    for (std::uint32_t m = hit; m != 0; m &= m - 1) {
      const int l = __builtin_ctz(m);
      hits[p.index[l]] = Hit{t[l], prim_indices_[static_cast<std::uint32_t>(tri[l])], u[l], v[l]};
    }
  }
}

}  // namespace prt
