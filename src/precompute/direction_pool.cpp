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

DirectionPlan MakeDirectionPlan(Sampler sampler, int samples, int hidden_samples, int count, std::uint64_t seed,
                                const std::vector<std::uint8_t>& seen, std::size_t vertices) {
  DirectionPlan plan;
  plan.pools.push_back(MakeDirectionPool(sampler, samples, count, seed));
  bool any_hidden = false;
  for (std::size_t v = 0; v < seen.size() && v < vertices; ++v) any_hidden |= seen[v] == 0;
  if (!any_hidden || hidden_samples == samples) return plan;
  plan.pools.push_back(MakeDirectionPool(sampler, hidden_samples, count, MixSeed(seed, 1)));
  plan.pool_of.resize(vertices);
  for (std::size_t v = 0; v < vertices; ++v) plan.pool_of[v] = v < seen.size() && seen[v] == 0 ? 1 : 0;
  return plan;
}

}  // namespace prt
