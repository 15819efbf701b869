#pragma once
/// \file
/// FNV-1a, 64 bit (Fowler, Noll, Vo): a fast non-cryptographic hash for cache keys and
/// checksums. Detects accidental corruption (any single bit flip changes it); not meant to
/// resist deliberate tampering.

#include <cstddef>
#include <cstdint>
#include <string>

namespace prt {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ULL;

/// Continues the hash `h` over `size` bytes at `data`.
inline std::uint64_t Fnv1a(const void* data, std::size_t size, std::uint64_t h = kFnvOffset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

inline std::uint64_t Fnv1a(const std::string& s, std::uint64_t h = kFnvOffset) {
  return Fnv1a(s.data(), s.size(), h);
}

}  // namespace prt
