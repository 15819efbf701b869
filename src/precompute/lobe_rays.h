#pragma once
/// \file
/// The rays a glossy vertex traces: `m` directions drawn from its lobe about the mirrored view
/// direction r, a rank-1 lattice (i + 1/2)/m, frac(i / golden ratio) [reference.h, 2] mapped
/// through the lobe's inverse distribution (material/lobe.h), shifted by the vertex's own random
/// stream (seed, vertex) so neighbours do not share their error. Each comes with
/// weight = h(mu) / (m density(mu)), so sum_i weight_i g(s_i) estimates integral h(r.s) g(s) ds.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "material/lobe.h"

namespace prt {

/// The random stream lobe rays draw from (distinct from the direction pool's streams).
constexpr std::uint64_t kLobeStream = 0x6c6f6265;  // "lobe"

struct LobeRays {
  std::vector<glm::dvec3> dirs;
  std::vector<double> weights;
};

/// The lobe rays of vertex `vertex` (see above) into `out` (resized to m).
void DrawLobeRays(const Lobe& lobe, const glm::dvec3& r, int m, std::uint64_t seed, std::size_t vertex, LobeRays& out);

}  // namespace prt
