// The traversal kernels, one set per instruction set (bvh_kernels.h), and the choice among them.
//
// Fans: the directions above the horizon, in the fan's face/Morton order, go in packets of 32
// consecutive ones through bvh_packet_traverse.h, occlusion and closest hit alike (closest hit
// on the baseline ray by ray, see IntersectFanBody). The rays are filled from the inverse and
// shear the fan computed once per direction (ray_fan.h), in place, with the horizon test
// without branches: 12 % faster occlusion than building each ray on its own with a branch
// (packets of 8, knot, AMD EPYC Zen 4).
// Side by side against Embree 3 on the same rays (`prt bench bvh --threads 1`, knot, 1 thread,
// AMD EPYC Zen 4 on a busy shared machine, medians of six runs, AVX-512 kernel): closest hit
// at 1.78x rtcIntersect1's rate (1.74-1.83x; ray by ray before: 0.99-1.08x), occlusion at
// 1.58x rtcOccluded1's (1.44-1.71x; packets of 8 before: 1.19-1.31x). The AVX2 kernel, two
// runs: 1.42x and 1.74x, 1.55x and 1.79x (before: 0.95-0.97x and 1.27-1.28x).
// Also measured and left out: testing first the triangles that stopped the previous direction
// (a shadow cache; 1024 directions are about 6 degrees apart, so the next ray hits the same
// block in 0.1 % of cases), and pushing a node's entered children onto the stack in one
// compress instruction (AVX-512) instead of a loop (8 % slower: the loop goes straight to a
// lone entered child without touching the stack).
#include "geometry/bvh_kernels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/simd.h"
#include "geometry/box_test.h"
#include "geometry/bvh_packet_traverse.h"
#include "geometry/bvh_wide_traverse.h"
#include "geometry/ray_fan.h"

namespace prt {
namespace {

using lanes::Isa;

// A lambda inlined like the lane helpers, so it takes the instruction set of its kernel.
#define PRT_LANES_LAMBDA __attribute__((always_inline))

// The bodies, inlined into each instruction set's kernel below. Directions at or below the
// horizon of `normal` cast no ray.

// Hands the rays of the fan above the horizon of `normal` to emit(rays, index, n) in packets of
// kPacketSize consecutive ones (the last may be smaller), index[r] the direction of ray r. The
// directions above the horizon are picked without branches, a chunk at a time, and the rays
// are filled in place, what depends only on the origin once per fan.
template <class Emit>
PRT_LANES void ForEachPacket(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal,
                             const Emit& emit) {
  constexpr int kP = wide::kPacketSize;
  constexpr int kChunk = 64;
  WideRay rays[kP];
  std::uint32_t index[kP];
  const WideRay base = MakeWideRay(bvh, origin, glm::vec3(1.0f), ShearedRay{}, 0.0f);
  for (WideRay& r : rays) r = base;
  bool origin_ok = true;  // the origin within the fused test's bound (bvh_wide.h)
  for (int a = 0; a < 3; ++a) origin_ok = origin_ok && std::abs(origin[a]) <= bvh.fused_origin_bound;
  const FanRay* picked[kChunk + kP];
  int n = 0;  // picked, not yet traced
  const std::size_t count = fan.rays.size();
  for (std::size_t begin = 0; begin < count; begin += kChunk) {
    const std::size_t end = std::min(count, begin + kChunk);
    for (std::size_t i = begin; i < end; ++i) {
      picked[n] = &fan.rays[i];
      n += glm::dot(normal, fan.rays[i].dir) > 0.0f ? 1 : 0;
    }
    int first = 0;  // the next picked ray to trace
    while (n - first >= kP || (end == count && first < n)) {
      const int m = std::min(n - first, kP);
      for (int r = 0; r < m; ++r) {
        const FanRay& f = *picked[first + r];
        WideRay& w = rays[r];
        bool ok = origin_ok;
        for (int a = 0; a < 3; ++a) {  // as MakeWideRay
          w.inv[a] = f.inv[a];
          w.org_inv[a] = w.org[a] * f.inv[a];
          const float p = std::abs(w.org_inv[a]);
          ok = ok && p <= std::numeric_limits<float>::max() &&
               (w.org[a] == 0.0f || p >= std::numeric_limits<float>::min());
          const int neg = std::signbit(f.inv[a]) ? 1 : 0;
          w.near[a] = a + 3 * neg;
          w.far[a] = a + 3 - 3 * neg;
        }
        w.sr = f.shear;
        w.fused_ok = ok;
        index[r] = f.index;
      }
      emit(rays, index, m);
      first += m;
    }
    for (int k = first; k < n; ++k) picked[k - first] = picked[k];  // fewer than kP left over
    n -= first;
  }
}

template <Isa isa>
PRT_LANES void OccludedFanBody(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal,
                               float tmax, std::uint8_t* occluded) {
  ForEachPacket(bvh, fan, origin, normal, [&](const WideRay* rays, const std::uint32_t* index, int n) PRT_LANES_LAMBDA {
    const wide::RayMask hit = wide::OccludedPacket<isa>(bvh, rays, n, tmax);
    for (int r = 0; r < n; ++r) occluded[index[r]] = static_cast<std::uint8_t>((hit >> r) & 1u);
  });
}

// Closest hit: the wide kernels trace packets and trace the tied rays again alone, so every
// answer is the single ray's (bvh_packet_traverse.h). The baseline traces each ray alone:
// packets of 32 measured 3-5 % slower there (CPU time, knot, Zen 4).
template <Isa isa>
PRT_LANES void IntersectFanBody(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin,
                                const glm::vec3& normal, float tmax, std::optional<Hit>* hits) {
  if constexpr (!lanes::IsWide(isa)) {
    for (const FanRay& f : fan.rays) {
      if (!(glm::dot(normal, f.dir) > 0.0f)) continue;
      const WideRay r = MakeWideRay(bvh, origin, f.inv, f.shear, 0.0f);
      Hit h;
      if (wide::Trace<isa, true>(bvh, r, tmax, h)) hits[f.index] = h;
    }
  } else {
    ForEachPacket(bvh, fan, origin, normal, [&](const WideRay* rays, const std::uint32_t* index, int n)
                                                   PRT_LANES_LAMBDA {
      Hit h[wide::kPacketSize];
      wide::RayMask found = 0;
      const wide::RayMask tied = wide::IntersectPacket<isa>(bvh, rays, n, tmax, h, found);
      for (int r = 0; r < n; ++r) {
        if ((tied >> r) & 1u) {
          Hit one;
          if (wide::Trace<isa, true>(bvh, rays[r], tmax, one)) hits[index[r]] = one;
        } else if ((found >> r) & 1u) {
          hits[index[r]] = h[r];
        }
      }
    });
  }
}

template <Isa isa>
PRT_LANES bool TraceBody(const WideBvh& bvh, const Ray& ray, bool closest, Hit& best) {
  const WideRay r = MakeWideRay(bvh, ray.origin, SafeInverse(ray.dir), MakeShearedRay(ray.dir), ray.tmin);
  return closest ? wide::Trace<isa, true>(bvh, r, ray.tmax, best) : wide::Trace<isa, false>(bvh, r, ray.tmax, best);
}

// One kernel set per instruction set: the same bodies under a different `target`.
#define PRT_KERNEL_SET(NAME, ISA, TARGET)                                                                        \
  TARGET void NAME##OccludedFan(const WideBvh& b, const RayFan& f, const glm::vec3& o, const glm::vec3& n,       \
                                float tmax, std::uint8_t* out) {                                                 \
    OccludedFanBody<ISA>(b, f, o, n, tmax, out);                                                                 \
  }                                                                                                              \
  TARGET void NAME##IntersectFan(const WideBvh& b, const RayFan& f, const glm::vec3& o, const glm::vec3& n,      \
                                 float tmax, std::optional<Hit>* out) {                                          \
    IntersectFanBody<ISA>(b, f, o, n, tmax, out);                                                                \
  }                                                                                                              \
  TARGET bool NAME##Trace(const WideBvh& b, const Ray& r, bool closest, Hit& best) {                             \
    return TraceBody<ISA>(b, r, closest, best);                                                                  \
  }                                                                                                              \
  constexpr BvhKernels k##NAME{ISA, NAME##OccludedFan, NAME##IntersectFan, NAME##Trace};

PRT_KERNEL_SET(Baseline, Isa::kBaseline, )
#if defined(__x86_64__) && defined(__GNUC__)
#define PRT_HAS_WIDE_KERNELS 1
PRT_KERNEL_SET(Avx2, Isa::kAvx2, __attribute__((target("arch=x86-64-v3"))))
PRT_KERNEL_SET(Avx512, Isa::kAvx512, __attribute__((target("arch=x86-64-v4"))))
#endif
#undef PRT_KERNEL_SET

const BvhKernels* KernelsOf(Isa isa) {
#ifdef PRT_HAS_WIDE_KERNELS
  if (isa == Isa::kAvx512) return &kAvx512;
  if (isa == Isa::kAvx2) return &kAvx2;
#endif
  return isa == Isa::kBaseline ? &kBaseline : nullptr;
}

std::atomic<const BvhKernels*>& Active() {
  static std::atomic<const BvhKernels*> active{KernelsOf(SupportedIsas().front())};
  return active;
}

}  // namespace

// The sets up to CpuVectorLevel(): what this CPU runs, capped by PRT_CPU_LEVEL (core/simd.h).
std::vector<Isa> SupportedIsas() {
  std::vector<Isa> isas;
#ifdef PRT_HAS_WIDE_KERNELS
  const VectorLevel level = CpuVectorLevel();
  if (level >= VectorLevel::kX86_64V4) isas.push_back(Isa::kAvx512);
  if (level >= VectorLevel::kAvx2) isas.push_back(Isa::kAvx2);
#endif
  isas.push_back(Isa::kBaseline);
  return isas;
}

const BvhKernels& ActiveKernels() { return *Active().load(std::memory_order_relaxed); }

bool UseIsa(Isa isa) {
  for (Isa s : SupportedIsas()) {
    if (s != isa) continue;
    Active().store(KernelsOf(isa), std::memory_order_relaxed);
    return true;
  }
  return false;
}

const char* IsaName(Isa isa) {
  switch (isa) {
    case Isa::kAvx512: return "avx512";
    case Isa::kAvx2: return "avx2";
    case Isa::kBaseline: break;
  }
  return "baseline";
}

}  // namespace prt
