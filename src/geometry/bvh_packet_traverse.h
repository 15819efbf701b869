#pragma once
/// \file
/// Traversal of up to 32 rays with one origin together, any hit and closest hit, for the fans
/// (internal to src/geometry; instantiated per instruction set by bvh_kernels.cpp). The PRT
/// workload casts ~500 directions from each vertex: near the origin they all cross the same
/// boxes, and neighbouring directions (the fan's face/Morton order, ray_fan.h) part only slowly.
///
/// Per node, each ray of the active set runs its own slab test of the eight child boxes
/// (bvh_wide_traverse.h), exactly as alone; the per-ray masks are transposed into, per child,
/// the rays that enter it, and a child is visited once, with that subset only [1]. What the
/// rays share is the node fetch, the stack and the branches; each does the box and triangle
/// tests it would do alone.
///
/// Any hit: children in lane order, as single rays; at a leaf each ray of the subset tests the
/// blocks until it hits, and a ray that has hit leaves every set. A ray therefore tests exactly
/// the boxes and triangles it would alone, in the same order of leaves up to its first hit, and
/// gets the same answer.
///
/// Closest hit: each ray keeps its own nearest hit and tests boxes and triangles only up to it
/// (its `reach`). Children are visited nearest first for the packet: ranked by the nearest
/// entry distance of any ray entering them. A ray's entry distances into a node's children are
/// kept with the node while its children wait on the stack, so a popped child is skipped by
/// each ray that entered it beyond its reach by then, as a single ray skips it. The order of
/// leaves is then the packet's, not the ray's own, and it may decide between two hits at
/// (almost) the same distance: the single ray keeps the first block's hit unless a later one
/// is nearer, and two distances a few ulps apart may round either way in the triangle test's
/// comparison T < tmax det. So a ray looks a little beyond its nearest hit (reach = 1 + 2^-15
/// times it) and is marked tied when the nearest hits of two blocks lie within a factor of
/// 1 + 2^-16 of each other; the caller traces a tied ray again alone. For a ray not tied, one
/// block's nearest hit is nearer than every other block's by more than 2^-16 relative, far
/// beyond those few ulps: alone, in any order of leaves, it ends with that hit too (within a
/// block both take the nearest lane, the first among equals), so every answer is the single
/// ray's, bit for bit. The tests compare the two on rays aimed exactly at vertices and on a pile
/// of coincident triangles, and fail without the second trace, with no look beyond (reach = the
/// nearest hit) or with ties only at equal distances. On the knot 1 ray in 1.6 million is tied.
///
/// Measured on the PRT workload (knot of 102,400 triangles, 1 thread, AMD EPYC Zen 4,
/// AVX-512 kernel), CPU time of one build against another: packets of 16 trace occlusion 8 %
/// faster than packets of 8, packets of 32 9 % faster again, packets of 64 as fast as 32; for
/// closest hit, packets of 32 are 14 % faster than packets of 8. Per closest-hit ray, packets
/// test as many boxes and blocks as single rays (9.3 boxes and 3.5 blocks); what grows is the
/// number of rays that share a node visit, 8.0 in packets of 32 against 4.3 in packets of 8
/// (6.8 for occlusion). Also measured, with packets of 8: the branch-free ranking above is 4 %
/// faster than an insertion sort; ranking by the first ray's entry distances instead of the
/// nearest of any ray, 5 % slower; prefetching the entered children, as single rays do, no
/// faster (left out). Side by side against Embree: bvh_kernels.cpp.
///
/// References
///  [1] I. Wald, P. Slusallek, C. Benthin, M. Wagner, "Interactive Rendering with Coherent Ray
///      Tracing", Computer Graphics Forum 20(3), 2001 (packets); here with per-child ray subsets.
///  [2] H. S. Warren, "Hacker's Delight", 2nd ed., section 7-3 (transposing an 8x8 bit matrix).

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "geometry/bvh_wide_traverse.h"

namespace prt::wide {

/// Rays per packet; bit r of a RayMask stands for ray r.
inline constexpr int kPacketSize = 32;
using RayMask = std::uint32_t;

/// Transposes the 8x8 bit matrix held in x (byte i = row i) [2].
PRT_LANES std::uint64_t TransposeBits8x8(std::uint64_t x) {
  std::uint64_t t;
  t = (x ^ (x >> 7)) & 0x00AA00AA00AA00AAull;
  x = x ^ t ^ (t << 7);
  t = (x ^ (x >> 14)) & 0x0000CCCC0000CCCCull;
  x = x ^ t ^ (t << 14);
  t = (x ^ (x >> 28)) & 0x00000000F0F0F0F0ull;
  x = x ^ t ^ (t << 28);
  return x;
}

/// Which rays of a packet enter which children of one node: filled ray by ray, then read child
/// by child. Word w holds rays 8w..8w+7, a byte per ray (bit c: child c) until Transpose, a
/// byte per child (bit r: ray 8w + r) after.
struct ChildRays {
  std::uint64_t w[kPacketSize / 8] = {};

  PRT_LANES void Add(int ray, std::uint32_t children) {
    w[ray >> 3] |= static_cast<std::uint64_t>(children) << (8 * (ray & 7));
  }
  /// The children any ray enters (before Transpose).
  PRT_LANES std::uint32_t Entered() const {
    std::uint64_t any = 0;
    for (const std::uint64_t x : w) any |= x;
    any |= any >> 32;  // OR of the eight bytes
    any |= any >> 16;
    return static_cast<std::uint32_t>((any | (any >> 8)) & 0xFFu);
  }
  PRT_LANES void Transpose() {
    for (std::uint64_t& x : w) x = TransposeBits8x8(x);
  }
  /// The rays entering child c (after Transpose).
  PRT_LANES RayMask Rays(int c) const {
    RayMask m = 0;
    for (int k = 0; k < kPacketSize / 8; ++k) m |= static_cast<RayMask>((w[k] >> (8 * c)) & 0xFFu) << (8 * k);
    return m;
  }
};

/// The rays r < n.
PRT_LANES RayMask FirstRays(int n) { return n >= 32 ? ~RayMask{0} : (RayMask{1} << n) - 1u; }

/// Rays r < n of `rays` (one origin, n <= kPacketSize) against `bvh` (non-empty) with the slab
/// test `fused` or exact: bit r of the result is set iff ray r hits a triangle in (tmin, tmax).
template <Isa isa, bool fused>
PRT_LANES RayMask OccludedPacketWith(const WideBvh& bvh, const WideRay* rays, int n, float tmax) {
  struct PacketEntry {
    WideRef ref;
    RayMask rays;  // the rays that entered this child
  };
  PacketEntry stack[kStackSize];
  int top = 0;
  const RayMask all = FirstRays(n);
  RayMask done = 0;  // rays that have hit
  WideRef cur = 0;
  RayMask active = all;
  const WideNode* nodes = bvh.nodes.data();
  for (;;) {
    while (!IsLeaf(cur)) {
      const WideNode& node = nodes[cur];
      ChildRays sets;
      for (RayMask s = active; s != 0; s &= s - 1) {
        const int r = __builtin_ctz(s);
        V8 unused;
        sets.Add(r, BoxHits<isa, fused>(node, rays[r], tmax, unused));
      }
      const std::uint32_t entered = sets.Entered();
      if (entered == 0) goto pop;
      sets.Transpose();
      {
        // As single rays do (bvh_wide_traverse.h): the first entered child next, the others
        // on the stack in lane order.
        const int first = __builtin_ctz(entered);
        for (std::uint32_t m = entered & (entered - 1); m != 0; m &= m - 1) {
          const int c = __builtin_ctz(m);
          stack[top++] = PacketEntry{node.child[c], sets.Rays(c)};
        }
        cur = node.child[first];
        active = sets.Rays(first);
      }
    }
    {  // A leaf: each ray of the set tests its blocks until it hits.
      const TriangleBlock* b = bvh.blocks.data() + LeafFirstBlock(cur);
      const std::uint32_t count = LeafBlockCount(cur);
      for (RayMask s = active; s != 0; s &= s - 1) {
        const int r = __builtin_ctz(s);
        for (std::uint32_t k = 0; k < count; ++k) {
          V8 t, u, v;
          if (BlockHits<isa, false>(b[k], rays[r], tmax, t, u, v) != 0) {
            done |= RayMask{1} << r;
            break;
          }
        }
      }
      if (done == all) return done;
    }
  pop:
    for (;;) {
      if (top == 0) return done;
      const PacketEntry e = stack[--top];
      active = e.rays & ~done;
      if (active == 0) continue;
      cur = e.ref;
      break;
    }
  }
}

/// As OccludedPacketWith, fused when every ray of the packet allows it (bvh_wide.h).
template <Isa isa>
PRT_LANES RayMask OccludedPacket(const WideBvh& bvh, const WideRay* rays, int n, float tmax) {
  if constexpr (lanes::IsWide(isa)) {
    bool fused = true;
    for (int r = 0; r < n; ++r) fused = fused && rays[r].fused_ok;
    if (fused) return OccludedPacketWith<isa, true>(bvh, rays, n, tmax);
  }
  return OccludedPacketWith<isa, false>(bvh, rays, n, tmax);
}

/// As BoxHits (bvh_wide_traverse.h), with the entry distance of every lane the ray does not
/// enter set to +inf.
template <Isa isa, bool fused>
PRT_LANES std::uint32_t BoxEntries(const WideNode& n, const WideRay& r, float tmax, V8& tnear) {
  using namespace lanes;
  V8 tn;
  const auto in = SlabLanes<isa, fused>(n, r, tmax, tn);
  tnear = in ? tn : Splat(std::numeric_limits<float>::infinity());
  return Bits<isa>(in);
}

/// Nearest hits of two blocks within this factor of each other are tied (see the file comment).
inline constexpr float kTieWindow = 1.0f + 0x1.0p-16f;
/// A ray whose nearest hit so far is at t tests boxes and triangles up to t times this, so it
/// sees every hit tied with that one.
inline constexpr float kTieReach = 1.0f + 0x1.0p-15f;

/// Closest hit of rays r < n of `rays` (one origin, n <= kPacketSize) against `bvh`
/// (non-empty) with the slab test `fused` or exact. Bit r of `found` is set iff ray r hits a
/// triangle in (tmin, tmax), its nearest hit then in hits[r]. Returns the tied rays (see the
/// file comment), whose hits[r] may not be the single ray's: the caller traces them alone.
template <Isa isa, bool fused>
PRT_LANES RayMask IntersectPacketWith(const WideBvh& bvh, const WideRay* rays, int n, float tmax, Hit* hits,
                                      RayMask& found) {
  using namespace lanes;
  struct PacketEntry {
    WideRef ref;
    RayMask rays;         // the rays that entered this child
    std::uint16_t child;  // its lane in the node
    std::uint16_t frame;  // the node's entry distances: frames[frame]
  };
  // Entry distances of each ray into each child of one node (row = ray), kept while children
  // of that node wait on the stack. Only nodes on the path from the root to the current node
  // hold one, so the tree's depth, below 128 (bvh.h), bounds how many are in use (6 on the
  // knot, 7 on a knot of 409,600 triangles: only those are touched).
  struct alignas(32) Frame {
    float t[kPacketSize][kBvhWidth];
  };
  constexpr int kFrames = 128;
  PacketEntry stack[kStackSize];
  Frame frames[kFrames];
  int top = 0, frame_top = 0;  // frames[frame_top ..] are free
  float reach[kPacketSize];    // per ray: tmax, or kTieReach times its nearest hit
  for (float& x : reach) x = tmax;
  RayMask tied = 0;
  found = 0;
  WideRef cur = 0;
  RayMask active = FirstRays(n);
  const WideNode* nodes = bvh.nodes.data();
  for (;;) {
    while (!IsLeaf(cur)) {
      const WideNode& node = nodes[cur];
      Frame& frame = frames[frame_top];
      ChildRays sets;
      V8 key = Splat(std::numeric_limits<float>::infinity());  // per child: nearest entry of any ray
      for (RayMask s = active; s != 0; s &= s - 1) {
        const int r = __builtin_ctz(s);
        V8 tn;
        sets.Add(r, BoxEntries<isa, fused>(node, rays[r], reach[r], tn));
        key = Min(key, tn);
        std::memcpy(frame.t[r], &tn, sizeof tn);
      }
      const std::uint32_t entered = sets.Entered();
      if (entered == 0) goto pop;
      sets.Transpose();
      if ((entered & (entered - 1)) == 0) {  // one child: straight down, nothing to keep
        const int c = __builtin_ctz(entered);
        cur = node.child[c];
        active = sets.Rays(c);
        continue;
      }
      {
        // Nearest first for the packet: each entered child's rank by its key, descending,
        // without branches. The rank compares the key's bits (monotonic for the distances,
        // which are >= 0) with the lane in the low three bits, so no two are equal; children
        // not entered get 0, below all. The entries go to the stack at their ranks, the
        // nearest on top, and that one is taken at once.
        M8 bits;
        std::memcpy(&bits, &key, sizeof bits);
        const M8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
        const M8 in = ((M8{} + static_cast<std::int32_t>(entered)) >> lane & 1) != 0;
        const M8 order = in & (((bits & 0x7FFFFFF8) | lane) + 8);
        M8 rank = {};
        for (int j = 0; j < kBvhWidth; ++j) rank -= (M8{} + order[j]) > order;  // true is -1
        std::int32_t ranks[kBvhWidth];
        std::memcpy(ranks, &rank, sizeof ranks);
        const auto f = static_cast<std::uint16_t>(frame_top++);
        for (std::uint32_t m = entered; m != 0; m &= m - 1) {
          const int c = __builtin_ctz(m);
          stack[top + ranks[c]] = PacketEntry{node.child[c], sets.Rays(c), static_cast<std::uint16_t>(c), f};
        }
        top += __builtin_popcount(entered) - 1;
        cur = stack[top].ref;
        active = stack[top].rays;
      }
    }
    {  // A leaf: each ray of the set tests its blocks, as alone, keeping its nearest hit.
      const TriangleBlock* b = bvh.blocks.data() + LeafFirstBlock(cur);
      const std::uint32_t count = LeafBlockCount(cur);
      for (RayMask s = active; s != 0; s &= s - 1) {
        const int r = __builtin_ctz(s);
        const RayMask bit = RayMask{1} << r;
        for (std::uint32_t k = 0; k < count; ++k) {
          V8 t, u, v;
          const std::uint32_t hit = BlockHits<isa, true>(b[k], rays[r], reach[r], t, u, v);
          if (hit == 0) continue;
          int l = __builtin_ctz(hit);  // the nearest lane, the first among equals
          for (std::uint32_t m = hit & (hit - 1); m != 0; m &= m - 1) {
            const int j = __builtin_ctz(m);
            if (t[j] < t[l]) l = j;
          }
          if ((found & bit) != 0) {
            const float near = hits[r].t;  // from an earlier block
            if (std::max(t[l], near) <= std::min(t[l], near) * kTieWindow) tied |= bit;
            if (!(t[l] < near)) continue;
          }
          hits[r] = Hit{t[l], b[k].id[l], u[l], v[l]};
          found |= bit;
          reach[r] = std::min(tmax, t[l] * kTieReach);
        }
      }
    }
  pop:
    for (;;) {
      if (top == 0) return tied;
      const PacketEntry e = stack[--top];
      // As alone: a ray skips a child it entered beyond its reach by now (only a ray that has
      // hit has a reach below tmax). Frames above this entry's are no longer needed.
      frame_top = e.frame + 1;
      const Frame& fr = frames[e.frame];
      active = e.rays;
      for (RayMask s = e.rays & found; s != 0; s &= s - 1) {
        const int r = __builtin_ctz(s);
        if (fr.t[r][e.child] > reach[r] * kSlabFarScale) active &= ~(RayMask{1} << r);
      }
      if (active == 0) continue;
      cur = e.ref;
      break;
    }
  }
}

/// As IntersectPacketWith, fused when every ray of the packet allows it (bvh_wide.h).
template <Isa isa>
PRT_LANES RayMask IntersectPacket(const WideBvh& bvh, const WideRay* rays, int n, float tmax, Hit* hits,
                                  RayMask& found) {
  if constexpr (lanes::IsWide(isa)) {
    bool fused = true;
    for (int r = 0; r < n; ++r) fused = fused && rays[r].fused_ok;
    if (fused) return IntersectPacketWith<isa, true>(bvh, rays, n, tmax, hits, found);
  }
  return IntersectPacketWith<isa, false>(bvh, rays, n, tmax, hits, found);
}

}  // namespace prt::wide
