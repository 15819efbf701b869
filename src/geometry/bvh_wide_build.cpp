// Collapse of the binary SAH tree into the wide tree of bvh_wide.h: the optimal choice of wide
// nodes and leaves by dynamic programming, then the nodes, blocks and padded boxes it chose.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/bvh.h"
#include "geometry/bvh_wide.h"

namespace prt {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr std::uint32_t kMaxLeafTriangles = kBlockWidth * kWideMaxBlocks;

std::uint32_t BlocksOf(std::uint32_t triangles) { return (triangles + kBlockWidth - 1) / kBlockWidth; }

// x - delta rounded down / x + delta rounded up to a float (a box grown, never shrunk).
float PadDown(float x, float delta) {
  if (std::isinf(x)) return x;
  const double want = static_cast<double>(x) - delta;
  const auto f = static_cast<float>(want);
  return static_cast<double>(f) > want ? std::nextafter(f, -kInf) : f;
}
float PadUp(float x, float delta) {
  if (std::isinf(x)) return x;
  const double want = static_cast<double>(x) + delta;
  const auto f = static_cast<float>(want);
  return static_cast<double>(f) < want ? std::nextafter(f, kInf) : f;
}

// The dynamic programme of bvh_wide.h over the binary nodes. cost[n][i - 1] is the least cost
// of standing for n's subtree with at most i subtrees; how it was reached is kept to rebuild it.
struct OptimalCollapse {
  const std::vector<BvhNode>& bin;
  CollapseCosts c;
  std::vector<std::uint32_t> first, count;              // n's triangles in leaf order
  std::vector<std::array<float, kBvhWidth>> cost;
  std::vector<std::array<std::uint8_t, kBvhWidth>> left;  // subtrees given to the left child; 0: i - 1 do
  std::vector<std::uint8_t> is_leaf;                    // cost[n][0] is n as one leaf
  std::vector<std::uint8_t> node_left;                  // n as a wide node: its children's split

  void Solve() {
    const std::size_t n = bin.size();
    first.resize(n), count.resize(n), cost.resize(n), left.resize(n), is_leaf.resize(n), node_left.resize(n);
    // Children follow their parent in `bin`, so a backward sweep sees children first.
    for (std::size_t q = n; q-- > 0;) {
      const BvhNode& b = bin[q];
      const float area = BoxArea(b.lo, b.hi);
      if (b.count > 0) {  // a binary leaf cannot be split: one leaf, whatever i
        first[q] = b.index, count[q] = b.count;
        cost[q].fill(c.block * area * static_cast<float>(BlocksOf(b.count)));
        left[q].fill(0);
        is_leaf[q] = 1;
        continue;
      }
      const std::uint32_t l = b.index, r = b.index + 1;
      first[q] = first[l], count[q] = count[l] + count[r];
      // split[j]: the best j subtrees taken from the two children together.
      float split[kBvhWidth + 1];
      std::uint8_t split_left[kBvhWidth + 1];
      for (int j = 2; j <= kBvhWidth; ++j) {
        split[j] = kInf, split_left[j] = 1;
        for (int k = 1; k < j; ++k) {
          const float v = cost[l][k - 1] + cost[r][j - k - 1];
          if (v < split[j]) split[j] = v, split_left[j] = static_cast<std::uint8_t>(k);
        }
      }
      const float as_leaf = count[q] <= kMaxLeafTriangles ? c.block * area * static_cast<float>(BlocksOf(count[q])) : kInf;
      const float as_node = c.node * area + split[kBvhWidth];
      is_leaf[q] = as_leaf <= as_node ? 1 : 0;
      node_left[q] = split_left[kBvhWidth];
      cost[q][0] = std::min(as_leaf, as_node);
      left[q][0] = 0;
      for (int i = 2; i <= kBvhWidth; ++i) {
        const bool split_better = split[i] < cost[q][i - 2];
        cost[q][i - 1] = split_better ? split[i] : cost[q][i - 2];
        left[q][i - 1] = split_better ? split_left[i] : 0;
      }
    }
  }

  // Appends the (at most i) subtrees that stand for q in the optimum, in leaf order.
  void Subtrees(std::uint32_t q, int i, std::vector<std::uint32_t>& out) const {
    while (i > 1 && left[q][i - 1] == 0) --i;
    if (i == 1) return out.push_back(q);
    const int k = left[q][i - 1];
    Subtrees(bin[q].index, k, out);
    Subtrees(bin[q].index + 1, i - k, out);
  }
};

struct Emitter {
  const OptimalCollapse& opt;
  const std::vector<std::uint32_t>& prims;
  const std::vector<std::array<glm::vec3, 3>>& corners;
  float delta;  // box padding (bvh_wide.h)
  WideBvh& out;

  // Blocks of the triangles [index, index + n) in leaf order; returns the leaf's reference.
  WideRef EmitLeaf(std::uint32_t index, std::uint32_t n) {
    const auto first = static_cast<std::uint32_t>(out.blocks.size());
    const std::uint32_t count = BlocksOf(n);
    for (std::uint32_t b = 0; b < count; ++b) {
      TriangleBlock block{};
      for (std::uint32_t l = 0; l < kBlockWidth; ++l) {
        // A short block repeats its last triangle (see bvh_wide.h).
        const std::uint32_t i = index + std::min(kBlockWidth * b + l, n - 1);
        for (int c = 0; c < 3; ++c)
          for (int a = 0; a < 3; ++a) block.p[c][a][l] = corners[i][c][a];
        block.id[l] = prims[i];
      }
      out.blocks.push_back(block);
    }
    return kWideLeafBit | ((count - 1) << kWideCountShift) | first;
  }

  // Fills out.nodes[slot] with the children `kids` (binary nodes), then their wide nodes.
  void EmitNode(std::uint32_t slot, const std::vector<std::uint32_t>& kids) {
    WideNode node{};
    std::uint32_t interior[kBvhWidth];
    int interior_count = 0;
    for (int i = 0; i < kBvhWidth; ++i) {
      if (i >= static_cast<int>(kids.size())) {  // an unused slot: an inverted box
        for (int a = 0; a < 3; ++a) node.planes[a][i] = kInf, node.planes[3 + a][i] = -kInf;
        node.child[i] = kWideEmpty;
        continue;
      }
      const std::uint32_t q = kids[i];
      for (int a = 0; a < 3; ++a) {
        node.planes[a][i] = PadDown(opt.bin[q].lo[a], delta);
        node.planes[3 + a][i] = PadUp(opt.bin[q].hi[a], delta);
      }
      if (opt.is_leaf[q]) {
        node.child[i] = EmitLeaf(opt.first[q], opt.count[q]);
      } else {
        node.child[i] = static_cast<WideRef>(out.nodes.size());
        out.nodes.push_back(WideNode{});
        interior[interior_count++] = static_cast<std::uint32_t>(i);
      }
    }
    out.nodes[slot] = node;
    for (int j = 0; j < interior_count; ++j) EmitNode(node.child[interior[j]], ChildrenOf(kids[interior[j]]));
  }

  // The children of binary node q as a wide node: the best split of its two children.
  std::vector<std::uint32_t> ChildrenOf(std::uint32_t q) const {
    std::vector<std::uint32_t> kids;
    const int k = opt.node_left[q];
    opt.Subtrees(opt.bin[q].index, k, kids);
    opt.Subtrees(opt.bin[q].index + 1, kBvhWidth - k, kids);
    return kids;
  }
};

}  // namespace

WideBvh CollapseToWide(const std::vector<BvhNode>& nodes, const std::vector<std::uint32_t>& prim_indices,
                       const std::vector<std::array<glm::vec3, 3>>& corners, const CollapseCosts& costs) {
  WideBvh out;
  if (nodes.empty()) return out;
  float largest = 0.0f;
  for (int a = 0; a < 3; ++a) largest = std::max({largest, std::abs(nodes[0].lo[a]), std::abs(nodes[0].hi[a])});
  out.fused_origin_bound = 2.0f * largest;
  const double delta = 2.0 * 0x1.0p-24 * out.fused_origin_bound;

  OptimalCollapse opt{nodes, costs, {}, {}, {}, {}, {}, {}};
  opt.Solve();
  out.nodes.reserve(nodes.size() / 4 + 1);
  out.blocks.reserve(prim_indices.size() / 4 + 1);
  Emitter e{opt, prim_indices, corners, static_cast<float>(delta), out};
  out.nodes.push_back(WideNode{});
  // The root is always a wide node: the binary root's best split, or the binary root alone
  // (as one leaf) when a single leaf is cheapest.
  e.EmitNode(0, opt.is_leaf[0] ? std::vector<std::uint32_t>{0} : e.ChildrenOf(0));
  return out;
}

}  // namespace prt
