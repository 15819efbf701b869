// Single-ray traversal of Bvh: any hit (Occluded) and closest hit (Intersect).
#include <algorithm>
#include <limits>

#include "geometry/box_test.h"
#include "geometry/bvh.h"
#include "geometry/triangle.h"

namespace prt {
namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kStackSize = 128;  // > the build's depth limit
}  // namespace

bool Bvh::Occluded(const Ray& ray) const {
  if (nodes_.empty()) return false;
  const ShearedRay sr = MakeShearedRay(ray.dir);
  const glm::vec3 inv = SafeInverse(ray.dir);
  if (SlabEntry(nodes_[0].lo, nodes_[0].hi, ray.origin, inv, ray.tmin, ray.tmax) == kInf) return false;
  std::uint32_t stack[kStackSize];
  int top = 0;
  std::uint32_t node = 0;
  float t, u, v;
  for (;;) {
    const BvhNode& n = nodes_[node];
    if (n.count > 0) {
      // Leaf: any triangle hit ends the search.
      for (std::uint32_t i = n.index; i < n.index + n.count; ++i) {
        const auto& c = corners_[i];
        if (IntersectTriangle(ray.origin, sr, c[0], c[1], c[2], ray.tmin, ray.tmax, t, u, v)) return true;
      }
      if (top == 0) return false;
      node = stack[--top];
      continue;
    }
    // Interior: visit the nearer child first, keep the other for later.
    const BvhNode& l = nodes_[n.index];
    const BvhNode& r = nodes_[n.index + 1];
    const float tl = SlabEntry(l.lo, l.hi, ray.origin, inv, ray.tmin, ray.tmax);
    const float tr = SlabEntry(r.lo, r.hi, ray.origin, inv, ray.tmin, ray.tmax);
    if (tl != kInf && tr != kInf) {
      node = tl <= tr ? n.index : n.index + 1;
      stack[top++] = tl <= tr ? n.index + 1 : n.index;
    } else if (tl != kInf) {
      node = n.index;
    } else if (tr != kInf) {
      node = n.index + 1;
    } else {
      if (top == 0) return false;
      node = stack[--top];
    }
  }
}

std::optional<Hit> Bvh::Intersect(const Ray& ray) const {
  std::optional<Hit> best;
  if (nodes_.empty()) return best;
  const ShearedRay sr = MakeShearedRay(ray.dir);
  const glm::vec3 inv = SafeInverse(ray.dir);
  float tmax = ray.tmax;
  // Stack entries carry their entry distance so subtrees behind the current best are skipped.
  struct Entry {
    std::uint32_t node;
    float tnear;
  };
  Entry stack[kStackSize];
  int top = 0;
  const float troot = SlabEntry(nodes_[0].lo, nodes_[0].hi, ray.origin, inv, ray.tmin, tmax);
  if (troot == kInf) return best;
  stack[top++] = {0, troot};
  float t, u, v;
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.tnear > tmax * kSlabFarScale) continue;
    const BvhNode& n = nodes_[e.node];
    if (n.count > 0) {
      for (std::uint32_t i = n.index; i < n.index + n.count; ++i) {
        const auto& c = corners_[i];
        if (!IntersectTriangle(ray.origin, sr, c[0], c[1], c[2], ray.tmin, tmax, t, u, v)) continue;
        tmax = t;
        best = Hit{t, prim_indices_[i], u, v};
      }
      continue;
    }
    const float tl = SlabEntry(nodes_[n.index].lo, nodes_[n.index].hi, ray.origin, inv, ray.tmin, tmax);
    const float tr = SlabEntry(nodes_[n.index + 1].lo, nodes_[n.index + 1].hi, ray.origin, inv, ray.tmin, tmax);
    // Push the farther child first so the nearer one is popped next.
    if (tl <= tr) {
      if (tr != kInf) stack[top++] = {n.index + 1, tr};
      if (tl != kInf) stack[top++] = {n.index, tl};
    } else {
      if (tl != kInf) stack[top++] = {n.index, tl};
      if (tr != kInf) stack[top++] = {n.index + 1, tr};
    }
  }
  return best;
}

}  // namespace prt
