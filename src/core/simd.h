#pragma once
/// \file
/// Compiling hot loops for several x86-64 instruction sets. Because the project compiles with
/// -ffp-contract=off (no fusing of a * b + c, CMakeLists.txt), every version rounds the same
/// way: outputs do not depend on the machine's vector width.
///
/// PRT_VECTORIZED: compiles a loop twice, for AVX2 and for the baseline x86-64, and picks one at
/// run time (GCC function multiversioning). Sanitized builds compile one version only: the
/// run-time choice is an ifunc resolver that the dynamic loader calls before a sanitizer's
/// runtime is initialised, which crashes ThreadSanitizer at start-up and hides the function from
/// AddressSanitizer's interception.
///
/// PRT_TARGET_AVX2 and PRT_TARGET_X86_64_V4 (defined on x86-64 with GCC only): compile one
/// function for AVX2 or for x86-64-v4 (AVX-512 F/BW/CD/DQ/VL), for a kernel written per
/// instruction set with the vector types below. The caller picks one by hand from
/// CpuVectorLevel(), without an ifunc, so sanitized builds keep them.
///
/// V2, V4, V8: vectors of 2, 4 and 8 doubles (GCC/Clang vector types). Use each only where it is
/// one register: V2 anywhere (SSE2, NEON), V4 under PRT_TARGET_AVX2, V8 under
/// PRT_TARGET_X86_64_V4. A vector wider than the registers is lowered poorly (measured on light
/// projection: V4 compiled for SSE2 took 1.4 times as long as scalar loops, V8 for AVX2 5 times
/// as long as V4). The helpers are forced inline, so each kernel compiles them for its own
/// instruction set and no vector crosses a function boundary (what -Wpsabi warns about).

#include <cmath>
#include <cstddef>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#include <immintrin.h>  // declares the instruction-set builtins used below
#endif

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define PRT_VECTORIZED __attribute__((target_clones("avx2", "default")))
#define PRT_VECTORIZED_CLONES 1
#else
#define PRT_VECTORIZED
#endif

#define PRT_SIMD_INLINE inline __attribute__((always_inline))

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PRT_TARGET_AVX2 __attribute__((target("avx2")))
#define PRT_TARGET_X86_64_V4 __attribute__((target("arch=x86-64-v4")))
#endif

namespace prt {

enum class VectorLevel { kBaseline, kAvx2, kX86_64V4 };

/// The widest level this CPU runs that the build has PRT_TARGET_ kernels for (kBaseline where
/// it has none).
inline VectorLevel CpuVectorLevel() {
#ifdef PRT_TARGET_X86_64_V4
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v4")) return VectorLevel::kX86_64V4;
  if (__builtin_cpu_supports("avx2")) return VectorLevel::kAvx2;
#endif
  return VectorLevel::kBaseline;
}

/// "x86-64-v4", "avx2" or "baseline".
inline const char* VectorLevelName(VectorLevel level) {
  switch (level) {
    case VectorLevel::kX86_64V4: return "x86-64-v4";
    case VectorLevel::kAvx2: return "avx2";
    default: return "baseline";
  }
}

/// The version of the PRT_VECTORIZED functions this CPU runs: "avx2" or "baseline" (the only
/// version of a sanitized or non-x86 build).
inline const char* VectorizedLoopsName() {
#ifdef PRT_VECTORIZED_CLONES
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) return "avx2";
#endif
  return "baseline";
}

namespace simd {

using V2 = double __attribute__((vector_size(16)));
using V4 = double __attribute__((vector_size(32)));
using V8 = double __attribute__((vector_size(64)));

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

/// Unaligned load and store: a vector type's alignment depends on the instruction set.
template <class V>
PRT_SIMD_INLINE V Load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
PRT_SIMD_INLINE void Store(double* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}

/// Correctly rounded square root lane by lane, as std::sqrt rounds.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
PRT_SIMD_INLINE V2 Sqrt(const V2& v) { return __builtin_ia32_sqrtpd(v); }
PRT_SIMD_INLINE V4 Sqrt(const V4& v) { return __builtin_ia32_sqrtpd256(v); }
#else
template <class V>
PRT_SIMD_INLINE V Sqrt(V v) {
  for (std::size_t j = 0; j < sizeof(V) / sizeof(double); ++j) v[j] = std::sqrt(v[j]);
  return v;
}
#endif

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

}  // namespace simd
}  // namespace prt
