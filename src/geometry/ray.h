#pragma once
/// \file
/// Rays, hits, and where to start a ray that leaves a surface.
///
/// References
///  [1] C. Wächter, N. Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
///      Ray Tracing Gems, ch. 6, 2019.
///  [2] M. Pharr, W. Jakob, G. Humphreys, "Physically Based Rendering", 4th ed., sec. 6.8
///      (floating-point error bounds of intersection points and robust spawned rays).

#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

namespace prt {

/// The ray o + t d for t in the open interval (tmin, tmax). `dir` need not be unit length;
/// t is then measured in multiples of |dir|.
struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 dir{0.0f, 0.0f, 1.0f};
  float tmin = 0.0f;
  float tmax = std::numeric_limits<float>::infinity();
};

/// A ray-triangle hit. The point is (1 - u - v) p0 + u p1 + v p2 with p0, p1, p2 the positions
/// of triangle `triangle` in the mesh's order; t is the ray parameter.
struct Hit {
  float t = 0.0f;
  std::uint32_t triangle = 0;
  float u = 0.0f;
  float v = 0.0f;
};

/// Offset, in multiples of the float epsilon (2^-23) times the point's magnitude, by which a ray
/// origin is moved off a surface. Positions carry a rounding error of about half an ulp of their
/// largest coordinate, and the ray-triangle test adds a few ulps of the same magnitude [1, 2];
/// 256 ulps (a relative 3e-5, as the integer offset of [1]) clears both with a wide margin and
/// is far below anything visible in shading.
inline constexpr float kOffsetUlps = 256.0f;

/// Start point for rays leaving the surface point `p` with unit normal `n` (rays are then cast
/// only into the hemisphere dot(n, d) > 0). The offset along n is proportional to the
/// magnitude of the coordinates, max(|p.x|, |p.y|, |p.z|, scene_scale), so it works the same at
/// every scene scale; `scene_scale` (e.g. the scene's largest bounding-box side) covers points
/// near the world origin, whose own coordinates say nothing about the size of the triangles
/// around them. Unlike [1] there is no fixed absolute offset near the origin, which would be
/// huge for a scene 1e-4 units across.
glm::vec3 OffsetRayOrigin(const glm::vec3& p, const glm::vec3& n, float scene_scale);

}  // namespace prt
