#pragma once
/// \file
/// Four float lanes for the 4-wide BVH (internal to src/geometry): GCC/Clang vector types,
/// which compile to SSE on x86-64 and to NEON elsewhere, with the few operations the
/// traversal needs. Min and Max keep std::min/std::max's answer lane by lane, so the vector
/// slab test decides exactly as the scalar one of `box_test.h` [1].
///
/// References
///  [1] T. Ize, "Robust BVH Ray Traversal", Journal of Computer Graphics Techniques 2(2), 2013.

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

// Lane helpers are internal and forced inline so lanes stay in registers.
#define PRT_LANES inline __attribute__((always_inline))

namespace prt::lanes {

using V4 = float __attribute__((vector_size(16)));
using M4 = std::int32_t __attribute__((vector_size(16)));

PRT_LANES V4 Load(const float* p) {
  V4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
PRT_LANES V4 Splat(float x) { return V4{} + x; }

/// std::min(a, b) per lane: b < a ? b : a.
PRT_LANES V4 Min(V4 a, V4 b) {
#if defined(__SSE2__)
  return _mm_min_ps(b, a);  // b < a ? b : a
#else
  return b < a ? b : a;
#endif
}
/// std::max(a, b) per lane: a < b ? b : a.
PRT_LANES V4 Max(V4 a, V4 b) {
#if defined(__SSE2__)
  return _mm_max_ps(b, a);  // b > a ? b : a
#else
  return a < b ? b : a;
#endif
}

/// Bit l set iff lane l of the mask is set.
PRT_LANES std::uint32_t Bits(M4 m) {
#if defined(__SSE2__)
  return static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(reinterpret_cast<__m128i>(m))));
#else
  std::uint32_t b = 0;
  for (int l = 0; l < 4; ++l) b |= (m[l] != 0 ? 1u : 0u) << l;
  return b;
#endif
}

}  // namespace prt::lanes
