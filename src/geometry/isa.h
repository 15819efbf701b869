#pragma once
/// \file
/// The instruction sets the BVH traversal is compiled for (bvh_kernels.h picks one per CPU).

namespace prt::lanes {

enum class Isa {
  kBaseline,  ///< x86-64 (SSE2) or any other architecture: eight lanes are two registers
  kAvx2,      ///< x86-64-v3: AVX2 and FMA, eight lanes in one register
  kAvx512,    ///< x86-64-v4: AVX-512 F/BW/CD/DQ/VL (the compiler also uses mask registers)
};

/// True where one instruction moves a whole 8-lane mask and a fused multiply-add exists.
constexpr bool IsWide(Isa isa) { return isa != Isa::kBaseline; }

}  // namespace prt::lanes
