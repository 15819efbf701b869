#pragma once
/// \file
/// Eight float lanes for the wide BVH (internal to src/geometry): GCC/Clang vector types with
/// the few operations the traversal needs. Min and Max keep std::min/std::max's answer lane by
/// lane, so the vector slab test decides exactly as the scalar one of `box_test.h` [1].
///
/// The same code is compiled once per instruction set (bvh_kernels.cpp): inside a function
/// compiled for x86-64-v3 (AVX2, FMA) or x86-64-v4 (AVX-512) a V8 is one register; on the
/// baseline x86-64 it is two SSE registers, on ARM two NEON registers. Two operations differ by
/// instruction set and take it as a template argument, because the instruction that does them
/// in one step only exists in the wider sets:
///  - Bits: one `vmovmskps` on AVX, two SSE movemasks and a shift on the baseline (measured on
///    the PRT workload: the single instruction is worth 3-5 % of the occlusion rate);
///  - MulSub (a b - c): one fused multiply-add on AVX2, used only by the slab test, whose boxes
///    are padded for it (bvh_wide.h); the triangle test never fuses, so hits stay bit-identical
///    on every instruction set.
///
/// Known cost: the baseline lowers eight-lane comparisons and selects lane by lane, at about a
/// fifth of the AVX2 rate (measured one after the other on the knot: 0.8 against 4.4 million
/// occlusion rays per second per core). Every x86 CPU since 2013 runs the AVX2 code; the
/// baseline serves older ones and other architectures.
///
/// References
///  [1] T. Ize, "Robust BVH Ray Traversal", Journal of Computer Graphics Techniques 2(2), 2013.

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "geometry/isa.h"

// Lane helpers are internal and forced inline, so lanes stay in registers and the code takes
// the instruction set of the kernel that inlines it.
#define PRT_LANES inline __attribute__((always_inline))

namespace prt::lanes {

inline constexpr int kLanes = 8;
using V8 = float __attribute__((vector_size(4 * kLanes)));
using M8 = std::int32_t __attribute__((vector_size(4 * kLanes)));

PRT_LANES V8 Load(const float* p) {
  V8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
PRT_LANES V8 Splat(float x) { return V8{} + x; }

/// std::min(a, b) per lane: b < a ? b : a.
PRT_LANES V8 Min(V8 a, V8 b) { return b < a ? b : a; }
/// std::max(a, b) per lane: a < b ? b : a.
PRT_LANES V8 Max(V8 a, V8 b) { return a < b ? b : a; }

/// Bit l set iff lane l of the mask is set.
template <Isa isa>
PRT_LANES std::uint32_t Bits(M8 m) {
#if defined(__x86_64__)
  if constexpr (IsWide(isa)) {
#if defined(__clang__)
    // clang checks a builtin's instruction set in the function that names it, not in the
    // kernel it is inlined into: the generic loop stands in (clang builds prt for fuzzing).
    std::uint32_t b = 0;
    for (int l = 0; l < kLanes; ++l) b |= (m[l] != 0 ? 1u : 0u) << l;
    return b;
#else
    V8 f;
    std::memcpy(&f, &m, sizeof f);
    return static_cast<std::uint32_t>(__builtin_ia32_movmskps256(f));
#endif
  } else {
    __m128 lo, hi;  // movemask per half: one instruction each on the baseline
    std::memcpy(&lo, &m, sizeof lo);
    std::memcpy(&hi, reinterpret_cast<const char*>(&m) + sizeof lo, sizeof hi);
    return static_cast<std::uint32_t>(_mm_movemask_ps(lo)) | (static_cast<std::uint32_t>(_mm_movemask_ps(hi)) << 4);
  }
#else
  std::uint32_t b = 0;
  for (int l = 0; l < kLanes; ++l) b |= (m[l] != 0 ? 1u : 0u) << l;
  return b;
#endif
}

/// a * b - c per lane with one rounding (fused multiply-add). Only for wide kernels, which
/// compile it to one `vfmsub` (the baseline would call the C library's fmaf per lane).
template <Isa isa>
PRT_LANES V8 MulSub(V8 a, float b, float c) {
  static_assert(IsWide(isa), "fused multiply-add is only used where the hardware has it");
  V8 r;
  for (int l = 0; l < kLanes; ++l) r[l] = __builtin_fmaf(a[l], b, -c);
  return r;
}

}  // namespace prt::lanes
