#include "env/environment_hash.h"

#include <vector>

#include "core/hash.h"

namespace prt {

std::uint64_t EnvironmentHash(const Environment& env) {
  // Texel and LightDisk are doubles only: no padding bytes in what is hashed.
  static_assert(sizeof(Texel) == 7 * sizeof(double), "Texel holds doubles only");
  static_assert(sizeof(LightDisk) == 7 * sizeof(double), "LightDisk holds doubles only");
  std::uint64_t h = kFnvOffset;
  std::vector<Texel> row;
  for (std::size_t i = 0; i < env.RowCount(); ++i) {
    env.Row(i, row);
    h = Fnv1a(row.data(), row.size() * sizeof(Texel), h);
  }
  const std::vector<LightDisk> disks = env.Disks();
  return Fnv1a(disks.data(), disks.size() * sizeof(LightDisk), h);
}

}  // namespace prt
