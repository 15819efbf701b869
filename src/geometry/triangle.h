#pragma once
/// \file
/// Watertight ray-triangle intersection [1]. A ray hitting an edge or a vertex shared by
/// several triangles hits at least one of them: no ray leaks through a closed mesh.
///
/// The idea: translate so the ray starts at the origin, permute axes so the ray's largest
/// direction component is z, and shear so the ray becomes the +z axis. The triangle's sheared
/// (x, y) corners A, B, C then give three 2D edge functions
///   U = C x B,  V = A x C,  W = B x A   (2D cross products, each the signed double area of the
/// triangle the ray forms with one edge). The ray hits iff U, V, W share a sign (zeros allowed);
/// the barycentric weights of A, B, C are U, V, W divided by det = U + V + W, and
/// t = (U Az + V Bz + W Cz) / det. An edge function that rounds to exactly 0 is recomputed in
/// double, so the sign decision is exact for points on shared edges: two triangles sharing an
/// edge evaluate that edge function with the same operands and opposite orientation.
///
/// Both the brute-force reference and every BVH traversal call the same code with the same
/// operations in the same order, so their hit/miss decisions agree bit for bit.
///
/// References
///  [1] S. Woop, C. Benthin, I. Wald, "Watertight Ray/Triangle Intersection", Journal of
///      Computer Graphics Techniques 2(1), 2013.

#include <cmath>
#include <utility>

#include <glm/vec3.hpp>

namespace prt {

/// The per-ray constants of [1]: axis permutation (kz = largest |dir| component, kx, ky the
/// others, swapped when dir[kz] < 0 to keep the winding) and shear (sx, sy, sz).
struct ShearedRay {
  int kx = 0, ky = 1, kz = 2;
  float sx = 0.0f, sy = 0.0f, sz = 1.0f;
};

/// Index of the largest |d| component, and the shear of [1] for that axis.
inline ShearedRay MakeShearedRay(const glm::vec3& dir) {
  ShearedRay r;
  const glm::vec3 a(std::abs(dir.x), std::abs(dir.y), std::abs(dir.z));
  r.kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
  r.kx = (r.kz + 1) % 3;
  r.ky = (r.kx + 1) % 3;
  if (dir[r.kz] < 0.0f) std::swap(r.kx, r.ky);
  r.sx = dir[r.kx] / dir[r.kz];
  r.sy = dir[r.ky] / dir[r.kz];
  r.sz = 1.0f / dir[r.kz];
  return r;
}

/// Edge functions recomputed in double when any float one is exactly zero [1, sec. 3].
inline void RefineEdgeFunctions(float ax, float ay, float bx, float by, float cx, float cy,
                                float& u, float& v, float& w) {
  u = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
  v = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
  w = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
}

/// Two-sided watertight test of the ray (org, r) against triangle (p0, p1, p2), accepting only
/// t in the open interval (tmin, tmax). On a hit, writes t and the barycentrics (u, v) of p1
/// and p2 and returns true.
inline bool IntersectTriangle(const glm::vec3& org, const ShearedRay& r, const glm::vec3& p0,
                              const glm::vec3& p1, const glm::vec3& p2, float tmin, float tmax,
                              float& t, float& u, float& v) {
  // Corners relative to the ray origin, then sheared so the ray is the +z axis.
  const glm::vec3 A = p0 - org, B = p1 - org, C = p2 - org;
  const float ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
  const float bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
  const float cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];
  // Edge functions (scaled barycentrics of p0, p1, p2).
  float e0 = cx * by - cy * bx;
  float e1 = ax * cy - ay * cx;
  float e2 = bx * ay - by * ax;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) RefineEdgeFunctions(ax, ay, bx, by, cx, cy, e0, e1, e2);
  if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;
  // Scaled hit distance; compare T with t * det without dividing (the sign of det flips it).
  const float T = e0 * (r.sz * A[r.kz]) + e1 * (r.sz * B[r.kz]) + e2 * (r.sz * C[r.kz]);
  if (det > 0.0f ? (T <= tmin * det || T >= tmax * det) : (T >= tmin * det || T <= tmax * det))
    return false;
  const float inv_det = 1.0f / det;
  t = T * inv_det;
  u = e1 * inv_det;
  v = e2 * inv_det;
  return true;
}

}  // namespace prt
