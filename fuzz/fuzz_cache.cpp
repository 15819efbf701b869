// Fuzzes the transport-cache reader. The expected key is taken from the input's own key field,
// so the fuzzer gets past the key check and into the size and checksum checks.
#include <cstring>

#include "core/error.h"
#include "fuzz/fuzz_support.h"
#include "precompute_io/transport_cache.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = prt::fuzz::WriteInput(data, size, ".cache");
  std::uint64_t key = 0;
  if (size >= 40) std::memcpy(&key, data + 32, sizeof key);
  std::string why;
  try {
    const auto t = prt::ReadTransportCache(path, key, why);
    if (t && t->coeffs.size() != t->vertices * t->channels * (t->lmax + 1) * (t->lmax + 1)) __builtin_trap();
    if (why.empty()) __builtin_trap();
  } catch (const prt::Error&) {
  }
  return 0;
}
