#pragma once
/// \file
/// A fixed set of directions prepared for tracing from many origins: the PRT workload, where
/// every vertex casts the same direction set (the part above its horizon) from its own position.
///
/// Directions are grouped into packets of kFanWidth that point roughly the same way: first by
/// the axis permutation of the watertight triangle test (largest |component| and its sign, i.e.
/// the cube face the direction goes through), then in Morton order of their position on that
/// face. A packet therefore shares one axis permutation, so the triangle test runs on all its
/// lanes at once with the triangle's corners translated to the shared origin a single time, and
/// its rays, leaving one point in nearby directions, visit nearly the same BVH nodes, so one box
/// fetch serves all lanes [1, 2]. Everything per direction (inverse, shear) is computed here
/// once instead of once per ray.
///
/// References
///  [1] I. Wald, P. Slusallek, C. Benthin, M. Wagner, "Interactive Rendering with Coherent Ray
///      Tracing", Computer Graphics Forum 20(3), 2001 (ray packets).
///  [2] S. Woop, C. Benthin, I. Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace prt {

/// Directions per packet: one AVX register of floats.
inline constexpr int kFanWidth = 8;

/// Up to kFanWidth directions sharing the axis permutation (kx, ky, kz) of the watertight test.
/// Unused lanes (lane >= count) repeat lane 0 and are never reported.
struct FanPacket {
  int kx = 0, ky = 1, kz = 2;
  std::uint32_t count = 0;
  std::uint32_t index[kFanWidth] = {};  ///< the direction's index in RayFan::directions
  alignas(32) float inv[3][kFanWidth] = {};    ///< SafeInverse of the direction, per axis
  alignas(32) float shear[3][kFanWidth] = {};  ///< sx, sy, sz of the watertight test
  alignas(32) float dir[3][kFanWidth] = {};    ///< the direction itself, per axis
};

/// A direction set arranged in packets. Build once, trace from any number of origins.
struct RayFan {
  std::vector<glm::vec3> directions;  ///< as given (need not be unit length)
  std::vector<FanPacket> packets;     ///< every direction in exactly one lane of one packet
};

/// Groups `directions` into packets (see the file comment). Zero directions are rejected by
/// the caller's contract: every direction must be non-zero and finite.
RayFan MakeRayFan(const std::vector<glm::vec3>& directions);

}  // namespace prt
