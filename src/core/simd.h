#pragma once
/// \file
/// PRT_VECTORIZED: compiles a hot loop twice, for AVX2 and for the baseline x86-64, and picks
/// one at run time (GCC function multiversioning). The build stays portable, and because the
/// project compiles with -ffp-contract=off (no fusing of a * b + c, CMakeLists.txt) both
/// versions round identically: outputs do not depend on the machine's vector width.
///
/// Sanitized builds compile one version only: the run-time choice is an ifunc resolver that the
/// dynamic loader calls before a sanitizer's runtime is initialised, which crashes ThreadSanitizer
/// at start-up and hides the function from AddressSanitizer's interception.

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define PRT_VECTORIZED __attribute__((target_clones("avx2", "default")))
#else
#define PRT_VECTORIZED
#endif
