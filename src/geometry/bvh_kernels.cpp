// The traversal kernels, one set per instruction set (bvh_kernels.h), and the choice among them.
//
// Fans: occlusion traces the directions in packets of eight consecutive ones (above the
// horizon, in the fan's face/Morton order) through bvh_packet_traverse.h; closest hit traces
// each direction alone (bvh_wide_traverse.h). Both use the inverse and shear the fan computed
// once per direction (ray_fan.h).
// Also measured and left out: testing first the triangles that stopped the previous direction
// (a shadow cache; 1024 directions are about 6 degrees apart, so the next ray hits the same
// block in 0.1 % of cases), and pushing a node's entered children onto the stack in one
// compress instruction (AVX-512) instead of a loop (8 % slower: the loop goes straight to a
// lone entered child without touching the stack).
#include "geometry/bvh_kernels.h"

#include <atomic>

#include <glm/geometric.hpp>

#include "geometry/box_test.h"
#include "geometry/bvh_packet_traverse.h"
#include "geometry/bvh_wide_traverse.h"
#include "geometry/ray_fan.h"

namespace prt {
namespace {

using lanes::Isa;

// The bodies, inlined into each instruction set's kernel below. Directions at or below the
// horizon of `normal` cast no ray.
// Traces the packet rays[0, n) and writes each ray's answer to occluded[index[r]].
template <Isa isa>
PRT_LANES void TracePacket(const WideBvh& bvh, const WideRay* rays, const std::uint32_t* index, int n, float tmax,
                           std::uint8_t* occluded) {
  const std::uint32_t hit = wide::OccludedPacket<isa>(bvh, rays, n, tmax);
  for (int r = 0; r < n; ++r) occluded[index[r]] = static_cast<std::uint8_t>((hit >> r) & 1u);
}

template <Isa isa>
PRT_LANES void OccludedFanBody(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal,
                               float tmax, std::uint8_t* occluded) {
  WideRay rays[wide::kPacketSize];
  std::uint32_t index[wide::kPacketSize];
  int n = 0;
  for (const FanRay& f : fan.rays) {
    if (!(glm::dot(normal, f.dir) > 0.0f)) continue;
    rays[n] = MakeWideRay(bvh, origin, f.inv, f.shear, 0.0f);
    index[n++] = f.index;
    if (n < wide::kPacketSize) continue;
    TracePacket<isa>(bvh, rays, index, n, tmax, occluded);
    n = 0;
  }
  if (n > 0) TracePacket<isa>(bvh, rays, index, n, tmax, occluded);  // the fan's last rays
}

template <Isa isa>
PRT_LANES void IntersectFanBody(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin,
                                const glm::vec3& normal, float tmax, std::optional<Hit>* hits) {
  for (const FanRay& f : fan.rays) {
    if (!(glm::dot(normal, f.dir) > 0.0f)) continue;
    const WideRay r = MakeWideRay(bvh, origin, f.inv, f.shear, 0.0f);
    Hit h;
    if (wide::Trace<isa, true>(bvh, r, tmax, h)) hits[f.index] = h;
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

#ifdef PRT_HAS_WIDE_KERNELS
// Whether this CPU runs code compiled for x86-64-v3 (`v4` false) or x86-64-v4 (`v4` true). GCC
// names the levels; clang 14 (the fuzzing builds) does not, nor LZCNT, MOVBE or F16C, so there
// the level is its other features: every CPU with AVX2, FMA and BMI1/2 has those three too.
bool CpuRunsLevel(bool v4) {
  __builtin_cpu_init();
#ifdef __clang__
  const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
                  __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("popcnt") &&
                  __builtin_cpu_supports("sse4.2");
  if (!v4) return v3;
  return v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
#else
  return v4 ? __builtin_cpu_supports("x86-64-v4") : __builtin_cpu_supports("x86-64-v3");
#endif
}
#endif

std::vector<Isa> SupportedIsas() {
  std::vector<Isa> isas;
#ifdef PRT_HAS_WIDE_KERNELS
  if (CpuRunsLevel(true)) isas.push_back(Isa::kAvx512);
  if (CpuRunsLevel(false)) isas.push_back(Isa::kAvx2);
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
