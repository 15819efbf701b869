#pragma once
/// \file
/// Single-ray traversal of the 8-wide BVH (internal to src/geometry; instantiated per
/// instruction set by bvh_kernels.cpp for Bvh::Occluded, Bvh::Intersect and the fans). Per
/// node, one SIMD slab test of the eight child boxes [1], fused on AVX2 (bvh_wide.h); of
/// the children the ray enters, closest hit visits the nearest first and pushes the others with
/// their entry distance [2], any hit takes them in lane order (see TraceWith). Per leaf block,
/// the watertight test of `triangle.h` runs on eight triangles at once with the same
/// operations in the same order as the scalar test, so every hit, miss, distance and
/// barycentric is bit-identical to IntersectTriangle; lanes with an edge function of exactly 0
/// are redone by the scalar test, which refines them in double [3].
///
/// Any hit stops at the first hit. Closest hit shrinks tmax at each hit and skips popped
/// entries that start beyond it; among triangles of one block at the same distance the first
/// lane wins.
///
/// References
///  [1] I. Wald, C. Benthin, S. Boulos, "Getting Rid of Packets: Efficient SIMD Single-Ray
///      Traversal using Multi-branching BVHs", IEEE Symposium on Interactive Ray Tracing, 2008.
///  [2] T. Ize, "Robust BVH Ray Traversal", Journal of Computer Graphics Techniques 2(2), 2013.
///  [3] S. Woop, C. Benthin, I. Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013.

#include <cmath>
#include <limits>

#include "geometry/box_test.h"
#include "geometry/bvh_wide.h"
#include "geometry/lanes.h"
#include "geometry/ray.h"
#include "geometry/triangle.h"

namespace prt {

/// Everything per ray that traversal needs, computed once.
struct WideRay {
  glm::vec3 origin;
  float org[3];          // origin by axis, indexable without glm's per-index branch
  float inv[3];          // SafeInverse(dir)
  float org_inv[3];      // org * inv rounded, for the fused slab test
  int near[3], far[3];   // plane rows of WideNode entered and left on each axis
  ShearedRay sr;         // watertight test constants
  float tmin;
  bool fused_ok;         // the fused slab test is conservative for this ray (bvh_wide.h)
};

/// From the direction's inverse and shear (as the fan precomputes them), for tracing `bvh`.
inline WideRay MakeWideRay(const WideBvh& bvh, const glm::vec3& origin, const glm::vec3& inv,
                           const ShearedRay& sr, float tmin) {
  WideRay r;
  r.origin = origin;
  r.fused_ok = true;
  for (int a = 0; a < 3; ++a) {
    r.org[a] = origin[a];
    r.inv[a] = inv[a];
    r.org_inv[a] = origin[a] * inv[a];
    // The padding covers a relative rounding error of org * inv for |org| within the bound;
    // an overflowing or subnormal product (an almost axis-parallel direction) is not covered.
    const float m = std::abs(r.org_inv[a]);
    r.fused_ok = r.fused_ok && std::abs(origin[a]) <= bvh.fused_origin_bound &&
                 m <= std::numeric_limits<float>::max() && (origin[a] == 0.0f || m >= std::numeric_limits<float>::min());
    // Rounding is monotonic, so for inv >= 0 the lo plane gives the smaller slab distance.
    r.near[a] = std::signbit(inv[a]) ? 3 + a : a;
    r.far[a] = std::signbit(inv[a]) ? a : 3 + a;
  }
  r.sr = sr;
  r.tmin = tmin;
  return r;
}

namespace wide {

using lanes::Isa;
using lanes::V8;
static_assert(lanes::kLanes == kBvhWidth && lanes::kLanes == kBlockWidth, "one lane per child and per triangle");

constexpr int kStackSize = 1024;  // > 7 x the build's depth bound (128) + 8

/// Distance along the ray to plane row `row` of `n` on `axis`: fused (one multiply-add on the
/// padded boxes, bvh_wide.h) or exact ((plane - origin) * inverse, [2]).
template <Isa isa, bool fused>
PRT_LANES V8 PlaneDistance(const WideNode& n, int row, int axis, const WideRay& r) {
  if constexpr (fused) return lanes::MulSub<isa>(lanes::Load(n.planes[row]), r.inv[axis], r.org_inv[axis]);
  else return (lanes::Load(n.planes[row]) - r.org[axis]) * r.inv[axis];
}

/// The slab test of the eight child boxes, the one both traversals use: each lane's entry
/// distance into `tnear`, and as a lane mask the lanes whose box the ray enters within
/// (tmin, tmax).
template <Isa isa, bool fused>
PRT_LANES auto SlabLanes(const WideNode& n, const WideRay& r, float tmax, V8& tnear) {
  using namespace lanes;
  const V8 nx = PlaneDistance<isa, fused>(n, r.near[0], 0, r);
  const V8 ny = PlaneDistance<isa, fused>(n, r.near[1], 1, r);
  const V8 nz = PlaneDistance<isa, fused>(n, r.near[2], 2, r);
  const V8 fx = PlaneDistance<isa, fused>(n, r.far[0], 0, r);
  const V8 fy = PlaneDistance<isa, fused>(n, r.far[1], 1, r);
  const V8 fz = PlaneDistance<isa, fused>(n, r.far[2], 2, r);
  tnear = Max(Max(nx, ny), Max(nz, Splat(r.tmin)));
  const V8 tfar = Min(Min(fx, fy), Min(fz, Splat(tmax))) * kSlabFarScale;
  return tnear <= tfar;
}

/// Lanes whose child box the ray enters within (tmin, tmax); their entry distances in tnear.
template <Isa isa, bool fused>
PRT_LANES std::uint32_t BoxHits(const WideNode& n, const WideRay& r, float tmax, V8& tnear) {
  return lanes::Bits<isa>(SlabLanes<isa, fused>(n, r, tmax, tnear));
}

/// Watertight test of one ray against the eight triangles of `b`: the lanes hit within
/// (tmin, tmax), and when `closest`, their t, u, v.
template <Isa isa, bool closest>
PRT_LANES std::uint32_t BlockHits(const TriangleBlock& b, const WideRay& r, float tmax, V8& t, V8& u, V8& v) {
  using namespace lanes;
  const int kx = r.sr.kx, ky = r.sr.ky, kz = r.sr.kz;
  // Corners relative to the origin, sheared so the ray is the +z axis.
  const V8 Az = Load(b.p[0][kz]) - r.org[kz], Bz = Load(b.p[1][kz]) - r.org[kz], Cz = Load(b.p[2][kz]) - r.org[kz];
  const V8 ax = (Load(b.p[0][kx]) - r.org[kx]) - r.sr.sx * Az, ay = (Load(b.p[0][ky]) - r.org[ky]) - r.sr.sy * Az;
  const V8 bx = (Load(b.p[1][kx]) - r.org[kx]) - r.sr.sx * Bz, by = (Load(b.p[1][ky]) - r.org[ky]) - r.sr.sy * Bz;
  const V8 cx = (Load(b.p[2][kx]) - r.org[kx]) - r.sr.sx * Cz, cy = (Load(b.p[2][ky]) - r.org[ky]) - r.sr.sy * Cz;
  const V8 e0 = cx * by - cy * bx;
  const V8 e1 = ax * cy - ay * cx;
  const V8 e2 = bx * ay - by * ax;
  const V8 zero = Splat(0.0f);
  const auto outside = ((e0 < zero) | (e1 < zero) | (e2 < zero)) & ((e0 > zero) | (e1 > zero) | (e2 > zero));
  std::uint32_t inside = Bits<isa>(~outside);
  const std::uint32_t exact = Bits<isa>((e0 == zero) | (e1 == zero) | (e2 == zero));
  if ((inside | exact) == 0) return 0;  // the common case: the ray passes beside all eight
  const V8 det = e0 + e1 + e2;
  const V8 T = e0 * (r.sr.sz * Az) + e1 * (r.sr.sz * Bz) + e2 * (r.sr.sz * Cz);
  const V8 lo = r.tmin * det, hi = tmax * det;
  const auto out_pos = (T <= lo) | (T >= hi), out_neg = (T >= lo) | (T <= hi);
  const auto out_of_range = (det > zero) ? out_pos : out_neg;
  std::uint32_t hit = inside & Bits<isa>((det != zero) & ~out_of_range) & ~exact;
  if constexpr (closest) {
    const V8 inv_det = 1.0f / det;
    t = T * inv_det;
    u = e1 * inv_det;
    v = e2 * inv_det;
  }
  // Lanes with an edge function of exactly 0: the scalar test, refined in double.
  for (std::uint32_t m = exact; m != 0; m &= m - 1) {
    const int l = __builtin_ctz(m);
    const glm::vec3 p0(b.p[0][0][l], b.p[0][1][l], b.p[0][2][l]);
    const glm::vec3 p1(b.p[1][0][l], b.p[1][1][l], b.p[1][2][l]);
    const glm::vec3 p2(b.p[2][0][l], b.p[2][1][l], b.p[2][2][l]);
    float tl, ul, vl;
    if (!IntersectTriangle(r.origin, r.sr, p0, p1, p2, r.tmin, tmax, tl, ul, vl)) continue;
    hit |= 1u << l;
    if constexpr (closest) t[l] = tl, u[l] = ul, v[l] = vl;
  }
  return hit;
}

/// Asks for the cache lines of child `ref`: a node's four, or the five of a leaf's first block.
PRT_LANES void Prefetch(const WideBvh& bvh, WideRef ref) {
  const char* p = IsLeaf(ref) ? reinterpret_cast<const char*>(bvh.blocks.data() + LeafFirstBlock(ref))
                              : reinterpret_cast<const char*>(bvh.nodes.data() + ref);
  __builtin_prefetch(p);
  __builtin_prefetch(p + 64);
  __builtin_prefetch(p + 128);
  __builtin_prefetch(p + 192);
  if (IsLeaf(ref)) __builtin_prefetch(p + 256);
}

struct Entry {
  WideRef ref;
  float tnear;
};

/// Traces one ray through `bvh` (non-empty) with the slab test `fused` or exact. Any hit:
/// returns whether the ray hits a triangle in (tmin, tmax). Closest: also writes the nearest
/// hit to `best`.
template <Isa isa, bool closest, bool fused>
PRT_LANES bool TraceWith(const WideBvh& bvh, const WideRay& r, float tmax, Hit& best) {
  Entry stack[kStackSize];
  int top = 0;
  WideRef cur = 0;
  bool found = false;
  const WideNode* nodes = bvh.nodes.data();
  for (;;) {
    // Down the tree: one entered child next, the others on the stack.
    while (!IsLeaf(cur)) {
      V8 tn;
      std::uint32_t mask = BoxHits<isa, fused>(nodes[cur], r, tmax, tn);
      const WideRef* child = nodes[cur].child;
      if (mask == 0) goto pop;
      // Start fetching every entered child now; the choice below hides part of the latency.
      for (std::uint32_t m = mask; m != 0; m &= m - 1) Prefetch(bvh, child[__builtin_ctz(m)]);
      int first = __builtin_ctz(mask);
      mask &= mask - 1;
      if (mask == 0) {
        cur = child[first];
        continue;
      }
      if constexpr (!closest) {
        // Any hit: the first entered child next, the others on the stack, in lane order. The
        // order decides only how soon an occluder is found. Nearest first, the natural choice,
        // was measured 20 % slower on the PRT workload (knot, 1 thread: 4.1-4.5 against
        // 5.1-5.3 million rays per second): the nearest box is the one around the ray's own
        // origin, whose surface lies below the horizon the ray leaves by and rarely blocks it.
        // Also measured slower: farthest first (5 %), leaves before interior children (12 %),
        // lanes sorted by box area at build time (5-8 %); lanes keep the binary tree's order.
        for (std::uint32_t m = mask; m != 0; m &= m - 1) {
          const int l = __builtin_ctz(m);
          stack[top++] = Entry{child[l], 0.0f};  // any hit never compares entry distances
        }
        cur = child[first];
        continue;
      }
      // Closest hit, two or more: insertion sort by entry distance, descending, onto the stack,
      // so the nearest comes next and the farthest deepest.
      Entry hits[kBvhWidth];
      int n = 0;
      for (std::uint32_t m = mask | (1u << first); m != 0; m &= m - 1) {
        const int l = __builtin_ctz(m);
        Entry e{child[l], tn[l]};
        int j = n++;
        for (; j > 0 && hits[j - 1].tnear < e.tnear; --j) hits[j] = hits[j - 1];
        hits[j] = e;
      }
      for (int i = 0; i < n - 1; ++i) stack[top++] = hits[i];
      cur = hits[n - 1].ref;
    }
    // A leaf: its blocks.
    {
      const TriangleBlock* b = bvh.blocks.data() + LeafFirstBlock(cur);
      const std::uint32_t count = LeafBlockCount(cur);
      for (std::uint32_t k = 0; k < count; ++k) {
        V8 t, u, v;
        const std::uint32_t hit = BlockHits<isa, closest>(b[k], r, tmax, t, u, v);
        if (hit == 0) continue;
        if constexpr (!closest) {
          return true;
        } else {
          int lbest = __builtin_ctz(hit);
          for (std::uint32_t m = hit & (hit - 1); m != 0; m &= m - 1) {
            const int l = __builtin_ctz(m);
            if (t[l] < t[lbest]) lbest = l;
          }
          tmax = t[lbest];
          best = Hit{t[lbest], b[k].id[lbest], u[lbest], v[lbest]};
          found = true;
        }
      }
    }
  pop:
    for (;;) {
      if (top == 0) return found;
      const Entry e = stack[--top];
      if (closest && e.tnear > tmax * kSlabFarScale) continue;
      cur = e.ref;
      break;
    }
  }
}

/// Traces one ray: the fused slab test where the instruction set has it and it is conservative
/// for this ray, else the exact one (the answers are the same; see bvh_wide.h).
template <Isa isa, bool closest>
PRT_LANES bool Trace(const WideBvh& bvh, const WideRay& r, float tmax, Hit& best) {
  if constexpr (lanes::IsWide(isa)) {
    if (r.fused_ok) return TraceWith<isa, closest, true>(bvh, r, tmax, best);
  }
  return TraceWith<isa, closest, false>(bvh, r, tmax, best);
}

}  // namespace wide
}  // namespace prt
