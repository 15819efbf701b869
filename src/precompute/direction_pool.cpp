#include "precompute/direction_pool.h"

#include "core/rng.h"

namespace prt {

std::size_t DirectionPool::SetOf(std::size_t v) const {
  return static_cast<std::size_t>(MixSeed(seed ^ 0x5bd1e995ULL, v) % sets.size());
}

DirectionPool MakeDirectionPool(Sampler sampler, int samples, int count, std::uint64_t seed) {
  DirectionPool pool;
  pool.seed = seed;
  for (int s = 0; s < count; ++s) {
    Pcg32 rng(seed, static_cast<std::uint64_t>(s));
    pool.sets.push_back(SampleSphere(sampler, samples, rng));
    std::vector<glm::vec3> dirs(pool.sets.back().begin(), pool.sets.back().end());
    pool.fans.push_back(MakeRayFan(dirs));
  }
  return pool;
}

}  // namespace prt
