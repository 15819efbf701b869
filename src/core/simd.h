#pragma once
/// \file
/// Compiling hot loops for several x86-64 instruction sets, and the choice among them at run
/// time. Because the project compiles with -ffp-contract=off (no fusing of a * b + c,
/// CMakeLists.txt), every version rounds the same way: outputs do not depend on the machine's
/// vector width (tests/render/test_cpu_levels.cpp renders the same bytes at every level).
///
/// PRT_TARGET_AVX2 and PRT_TARGET_X86_64_V4 (defined on x86-64 with GCC only): compile one
/// function for AVX2 or for x86-64-v4 (AVX-512 F/BW/CD/DQ/VL), for a kernel written per
/// instruction set (with the vector types below, or a loop the compiler vectorises). The caller
/// picks one by hand from CpuVectorLevel(), without an ifunc: GCC's target_clones resolve in
/// the dynamic loader, before a sanitizer's runtime is initialised (ThreadSanitizer crashes
/// there) and beyond the reach of PRT_CPU_LEVEL.
///
/// PRT_CPU_LEVEL=baseline|avx2|avx512 in the environment caps every such choice (these kernels
/// and the BVH's, geometry/bvh_kernels.h) at that level, so a machine can produce what a
/// smaller one would: main refuses an unknown level or one this CPU cannot run
/// (CheckCpuLevelRequest) before any work.
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

#define PRT_SIMD_INLINE inline __attribute__((always_inline))

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PRT_TARGET_AVX2 __attribute__((target("avx2")))
#define PRT_TARGET_X86_64_V4 __attribute__((target("arch=x86-64-v4")))
#endif

namespace prt {

/// The kernel levels, in order: each runs on every CPU that runs the next one.
enum class VectorLevel {
  kBaseline,  ///< x86-64 (SSE2), or any other architecture
  kAvx2,      ///< x86-64-v3: AVX2, FMA, BMI1/2 (PRT_TARGET_AVX2 needs only AVX2)
  kX86_64V4,  ///< x86-64-v4: AVX-512 F/BW/CD/DQ/VL
};

/// The widest level this CPU runs, whatever PRT_CPU_LEVEL says (kBaseline off x86-64).
VectorLevel CpuMaxVectorLevel();

/// The level every run-time choice of kernel uses: CpuMaxVectorLevel(), capped at
/// $PRT_CPU_LEVEL when that names a level (read once). Never above what the CPU runs: a level
/// the CPU lacks gives CpuMaxVectorLevel(), an unknown name kBaseline (main refuses both first,
/// CheckCpuLevelRequest). A kernel with no version for this level takes the next one below.
VectorLevel CpuVectorLevel();

/// True when PRT_CPU_LEVEL holds CpuVectorLevel() below CpuMaxVectorLevel().
bool CpuLevelCapped();

/// Throws Error if $PRT_CPU_LEVEL is set, not empty, and is not a level this CPU runs:
/// `PRT_CPU_LEVEL=sse9: unknown level (expected baseline, avx2 or avx512)`, or
/// `PRT_CPU_LEVEL=avx512: this CPU cannot run it (expected one of: baseline, avx2)`.
/// main calls it before any work.
void CheckCpuLevelRequest();

/// The level a PRT_CPU_LEVEL value `request` asks for on a CPU whose widest level is `cpu_max`
/// (null or empty: `cpu_max`), or Error as CheckCpuLevelRequest throws it (tests).
VectorLevel RequestedVectorLevel(const char* request, VectorLevel cpu_max);

/// "avx512", "avx2" or "baseline": PRT_CPU_LEVEL's names.
const char* VectorLevelName(VectorLevel level);

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
