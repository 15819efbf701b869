// Binned SAH build of Bvh (see bvh.h for the cost model).
#include <algorithm>
#include <numeric>

#include <glm/common.hpp>

#include "geometry/bvh.h"
#include "geometry/mesh_ops.h"

namespace prt {
namespace {

// From this depth on, nodes are halved at the median centroid instead of by SAH, which ends
// within 32 more levels: the depth stays below 128 and leaves within max_leaf_size.
constexpr int kSahDepth = 96;

// Triangles rounded up to whole blocks: traversal tests a block of kBlockWidth triangles at
// the cost of one, so SAH counts a leaf's blocks, not its triangles.
float BlockSlots(std::uint32_t n) {
  return static_cast<float>((n + kBlockWidth - 1) / kBlockWidth * kBlockWidth);
}

struct Builder {
  const BvhOptions& opt;
  std::vector<Bounds3> boxes;        // per triangle
  std::vector<glm::vec3> centroids;  // per triangle
  std::vector<std::uint32_t>& prims;
  std::vector<BvhNode>& nodes;

  int BinOf(const glm::vec3& c, int axis, const Bounds3& cb, float scale) const {
    const int b = static_cast<int>((c[axis] - cb.lo[axis]) * scale);
    return std::clamp(b, 0, opt.bins - 1);
  }

  void MakeLeaf(std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
    nodes[node].index = begin;
    nodes[node].count = end - begin;
  }

  void Split(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
    // Node box and the box of the centroids.
    Bounds3 box, cbox;
    for (std::uint32_t i = begin; i < end; ++i) {
      box.Extend(boxes[prims[i]].lo);
      box.Extend(boxes[prims[i]].hi);
      cbox.Extend(centroids[prims[i]]);
    }
    nodes[node].lo = box.lo;
    nodes[node].hi = box.hi;
    const std::uint32_t n = end - begin;
    if (n <= 1) return MakeLeaf(node, begin, end);
    if (depth >= kSahDepth) return SplitAtMedian(node, begin, end, depth, cbox);

    // Find the cheapest bin border over the three axes.
    const int nb = opt.bins;
    float best_cost = std::numeric_limits<float>::infinity();
    int best_axis = -1, best_border = 0;
    const float node_area = std::max(BoxArea(box.lo, box.hi), 1e-30f);
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = cbox.hi[axis] - cbox.lo[axis];
      if (!(extent > 0.0f)) continue;
      const float scale = static_cast<float>(nb) / extent;
      std::vector<Bounds3> bin_box(nb);
      std::vector<std::uint32_t> bin_count(nb, 0);
      for (std::uint32_t i = begin; i < end; ++i) {
        const int b = BinOf(centroids[prims[i]], axis, cbox, scale);
        bin_box[b].Extend(boxes[prims[i]].lo);
        bin_box[b].Extend(boxes[prims[i]].hi);
        ++bin_count[b];
      }
      // Sweep from the right: cost of everything right of each border.
      std::vector<float> right_cost(nb, 0.0f);
      Bounds3 acc;
      std::uint32_t count = 0;
      // (An empty bin's box is inverted: extending by its corners would blow `acc` up.)
      for (int b = nb - 1; b > 0; --b) {
        if (bin_count[b] > 0) acc.Extend(bin_box[b].lo), acc.Extend(bin_box[b].hi);
        count += bin_count[b];
        right_cost[b] = count == 0 ? 0.0f : BoxArea(acc.lo, acc.hi) * BlockSlots(count);
      }
      // Sweep from the left; border b puts bins [0, b) left.
      acc = Bounds3();
      count = 0;
      for (int b = 1; b < nb; ++b) {
        if (bin_count[b - 1] > 0) acc.Extend(bin_box[b - 1].lo), acc.Extend(bin_box[b - 1].hi);
        count += bin_count[b - 1];
        if (count == 0 || count == n) continue;
        const float cost = opt.traversal_cost + opt.intersection_cost *
                               (BoxArea(acc.lo, acc.hi) * BlockSlots(count) + right_cost[b]) /
                               node_area;
        if (cost < best_cost) best_cost = cost, best_axis = axis, best_border = b;
      }
    }

    // Partition by the best border, or by the median index when binning cannot separate.
    std::uint32_t mid = begin;
    if (best_axis >= 0) {
      if (best_cost >= opt.intersection_cost * BlockSlots(n) &&
          n <= static_cast<std::uint32_t>(opt.max_leaf_size))
        return MakeLeaf(node, begin, end);
      const float scale = static_cast<float>(nb) / (cbox.hi[best_axis] - cbox.lo[best_axis]);
      auto* split = std::partition(prims.data() + begin, prims.data() + end, [&](std::uint32_t p) {
        return BinOf(centroids[p], best_axis, cbox, scale) < best_border;
      });
      mid = static_cast<std::uint32_t>(split - prims.data());
    }
    if (mid == begin || mid == end) {
      if (n <= static_cast<std::uint32_t>(opt.max_leaf_size)) return MakeLeaf(node, begin, end);
      mid = begin + n / 2;  // all centroids coincide: any halving is as good as another
    }

    Children(node, begin, mid, end, depth);
  }

  // Makes `node` interior with children [begin, mid) and [mid, end).
  void Children(std::uint32_t node, std::uint32_t begin, std::uint32_t mid, std::uint32_t end, int depth) {
    const auto left = static_cast<std::uint32_t>(nodes.size());
    nodes.push_back(BvhNode{});
    nodes.push_back(BvhNode{});
    nodes[node].index = left;
    nodes[node].count = 0;
    Split(left, begin, mid, depth + 1);
    Split(left + 1, mid, end, depth + 1);
  }

  // Past kSahDepth: a leaf when small enough, else halves at the median along the longest axis.
  void SplitAtMedian(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth,
                     const Bounds3& cbox) {
    if (end - begin <= static_cast<std::uint32_t>(opt.max_leaf_size)) return MakeLeaf(node, begin, end);
    const glm::vec3 e = cbox.hi - cbox.lo;
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(prims.data() + begin, prims.data() + mid, prims.data() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return centroids[a][axis] < centroids[b][axis] ||
                              (centroids[a][axis] == centroids[b][axis] && a < b);
                     });
    Children(node, begin, mid, end, depth);
  }
};

}  // namespace

float BoxArea(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 d = glm::max(hi - lo, glm::vec3(0.0f));
  return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

Bvh Bvh::Build(const Mesh& mesh, const BvhOptions& options) {
  Bvh bvh;
  const std::size_t n = mesh.triangle_count();
  if (n == 0) return bvh;
  BvhOptions opt = options;
  opt.bins = std::max(2, opt.bins);
  opt.max_leaf_size = std::clamp(opt.max_leaf_size, 1, static_cast<int>(kBlockWidth * kWideMaxBlocks));
  Builder b{opt, {}, {}, bvh.prim_indices_, bvh.nodes_};
  b.boxes.resize(n);
  b.centroids.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int c = 0; c < 3; ++c) b.boxes[t].Extend(mesh.positions[mesh.triangles[t][c]]);
    b.centroids[t] = 0.5f * (b.boxes[t].lo + b.boxes[t].hi);
  }
  bvh.prim_indices_.resize(n);
  std::iota(bvh.prim_indices_.begin(), bvh.prim_indices_.end(), 0u);
  bvh.nodes_.reserve(2 * n);
  bvh.nodes_.push_back(BvhNode{});
  b.Split(0, 0, static_cast<std::uint32_t>(n), 0);
  // Corners in leaf order, then the wide tree that stores them in blocks (bvh_wide.h).
  std::vector<std::array<glm::vec3, 3>> corners(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& tri = mesh.triangles[bvh.prim_indices_[i]];
    corners[i] = {mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]};
  }
  const CollapseCosts costs{opt.traversal_cost, opt.intersection_cost * static_cast<float>(kBlockWidth)};
  bvh.wide_ = CollapseToWide(bvh.nodes_, bvh.prim_indices_, corners, costs);
  return bvh;
}

float Bvh::SceneScale() const {
  if (nodes_.empty()) return 0.0f;
  const glm::vec3 d = nodes_[0].hi - nodes_[0].lo;
  return std::max(d.x, std::max(d.y, d.z));
}

}  // namespace prt
