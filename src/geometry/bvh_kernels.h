#pragma once
/// \file
/// The BVH traversals compiled once per instruction set (AVX-512, AVX2, baseline) and the
/// choice among them for the CPU at hand (internal to src/geometry; Bvh calls them).
///
/// Why per instruction set, by hand: the slab test needs a fused multiply-add and the masks one
/// 8-lane movemask to be fast (lanes.h), and those exist only from AVX2 on. Each kernel is a
/// small function compiled with a `target` attribute around the same always-inlined template
/// code, so every helper it inlines takes that instruction set, and nothing is compiled with
/// wider instructions outside it. The choice is made once, from the CPU's features capped by
/// PRT_CPU_LEVEL (CpuVectorLevel, core/simd.h), without an ifunc resolver (which sanitizers do
/// not survive). All kernels return the same answers, bit for bit: the tests run each one the
/// CPU supports against brute force.

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/bvh_wide.h"
#include "geometry/isa.h"
#include "geometry/ray.h"

namespace prt {

struct RayFan;

/// Entry points of one instruction set's traversal (see Bvh for their contracts).
struct BvhKernels {
  lanes::Isa isa;
  /// Bvh::OccludedFan without the resizing: `occluded` has one entry per fan direction, zeroed.
  void (*occluded_fan)(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal,
                       float tmax, std::uint8_t* occluded);
  /// Bvh::IntersectFan likewise: `hits` has one entry per fan direction, empty.
  void (*intersect_fan)(const WideBvh& bvh, const RayFan& fan, const glm::vec3& origin, const glm::vec3& normal,
                        float tmax, std::optional<Hit>* hits);
  /// One ray: any hit, or (closest) the nearest hit written to `best`.
  bool (*trace)(const WideBvh& bvh, const Ray& ray, bool closest, Hit& best);
};

/// The instruction sets this CPU runs up to CpuVectorLevel() (PRT_CPU_LEVEL's cap), best first
/// (the baseline always last).
std::vector<lanes::Isa> SupportedIsas();

/// The kernels in use: the best set this CPU runs, unless chosen by UseIsa.
const BvhKernels& ActiveKernels();

/// Makes traversal use `isa` from now on (tests and benchmarks compare the sets); false, and
/// nothing changes, if it is not one of SupportedIsas(). Not to be called while rays are traced.
bool UseIsa(lanes::Isa isa);

/// "avx512", "avx2" or "baseline".
const char* IsaName(lanes::Isa isa);

}  // namespace prt
