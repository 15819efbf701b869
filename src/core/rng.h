#pragma once
/// \file
/// Deterministic random numbers: PCG32 (O'Neill 2014, "PCG: A family of simple fast
/// space-efficient statistically good algorithms for random number generation").
/// Each vertex (or pixel, or texel) gets its own stream from (seed, index), so results never
/// depend on the order in which threads visit the work.

#include <cstdint>

namespace prt {

class Pcg32 {
 public:
  /// Stream `stream` of the generator seeded with `seed`. Distinct streams are independent.
  Pcg32(std::uint64_t seed, std::uint64_t stream) {
    inc_ = (stream << 1u) | 1u;
    state_ = 0;
    NextU32();
    state_ += seed;
    NextU32();
  }

  /// Uniform 32-bit integer.
  std::uint32_t NextU32() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  /// Uniform double in [0, 1) with 53 random bits.
  double NextDouble() {
    const std::uint64_t hi = NextU32() >> 5;  // 27 bits
    const std::uint64_t lo = NextU32() >> 6;  // 26 bits
    return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
  std::uint64_t inc_;
};

/// Mixes two integers into a well-spread 64-bit seed (SplitMix64 finaliser).
inline std::uint64_t MixSeed(std::uint64_t a, std::uint64_t b) {
  std::uint64_t z = a + 0x9E3779B97F4A7C15ULL * (b + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace prt
