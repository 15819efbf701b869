// The CPU's kernel level and its cap by PRT_CPU_LEVEL (simd.h).
#include "core/simd.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

#include "core/error.h"

namespace prt {
namespace {

constexpr VectorLevel kLevels[] = {VectorLevel::kBaseline, VectorLevel::kAvx2, VectorLevel::kX86_64V4};

// x86-64-v3 or -v4 (GCC names the levels). Clang 14 (the fuzzing builds) names neither, nor
// LZCNT, MOVBE or F16C, so there a level is its other features: every CPU with AVX2, FMA and
// BMI1/2 has those three too.
VectorLevel DetectLevel() {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
#ifdef __clang__
  const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
                  __builtin_cpu_supports("bmi2") && __builtin_cpu_supports("popcnt") &&
                  __builtin_cpu_supports("sse4.2");
  const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                  __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                  __builtin_cpu_supports("avx512vl");
#else
  const bool v3 = __builtin_cpu_supports("x86-64-v3");
  const bool v4 = __builtin_cpu_supports("x86-64-v4");
#endif
  if (v4) return VectorLevel::kX86_64V4;
  if (v3) return VectorLevel::kAvx2;
#endif
  return VectorLevel::kBaseline;
}

std::optional<VectorLevel> ParseLevel(const std::string& name) {
  for (VectorLevel level : kLevels)
    if (name == VectorLevelName(level)) return level;
  return std::nullopt;
}

// $PRT_CPU_LEVEL, read once ("" when unset).
const std::string& Request() {
  static const std::string request = [] {
    const char* value = std::getenv("PRT_CPU_LEVEL");
    return std::string(value ? value : "");
  }();
  return request;
}

}  // namespace

VectorLevel CpuMaxVectorLevel() {
  static const VectorLevel level = DetectLevel();
  return level;
}

VectorLevel CpuVectorLevel() {
  static const VectorLevel level = [] {
    if (Request().empty()) return CpuMaxVectorLevel();
    const std::optional<VectorLevel> asked = ParseLevel(Request());
    return asked ? std::min(*asked, CpuMaxVectorLevel()) : VectorLevel::kBaseline;
  }();
  return level;
}

bool CpuLevelCapped() { return CpuVectorLevel() < CpuMaxVectorLevel(); }

VectorLevel RequestedVectorLevel(const char* request, VectorLevel cpu_max) {
  if (!request || !*request) return cpu_max;
  const std::string what = std::string("PRT_CPU_LEVEL=") + request;
  const std::optional<VectorLevel> asked = ParseLevel(request);
  if (!asked) throw Error(what + ": unknown level (expected baseline, avx2 or avx512)");
  if (*asked > cpu_max) {
    std::string runs;
    for (VectorLevel level : kLevels)
      if (level <= cpu_max) runs += std::string(runs.empty() ? "" : ", ") + VectorLevelName(level);
    throw Error(what + ": this CPU cannot run it (expected one of: " + runs + ")");
  }
  return *asked;
}

void CheckCpuLevelRequest() { RequestedVectorLevel(Request().c_str(), CpuMaxVectorLevel()); }

const char* VectorLevelName(VectorLevel level) {
  switch (level) {
    case VectorLevel::kX86_64V4: return "avx512";
    case VectorLevel::kAvx2: return "avx2";
    case VectorLevel::kBaseline: break;
  }
  return "baseline";
}

}  // namespace prt
