// Collapse of the binary SAH tree into the wide tree of bvh_wide.h.
#include <algorithm>
#include <limits>

#include "geometry/bvh.h"
#include "geometry/bvh_wide.h"

namespace prt {
namespace {

struct Collapser {
  const std::vector<BvhNode>& bin;
  const std::vector<std::uint32_t>& prims;
  const std::vector<std::array<glm::vec3, 3>>& corners;
  WideBvh& out;

  // Blocks of the binary leaf `n`; returns its reference.
  WideRef EmitLeaf(const BvhNode& n) {
    const auto first = static_cast<std::uint32_t>(out.blocks.size());
    const std::uint32_t count = (n.count + kBlockWidth - 1) / kBlockWidth;
    for (std::uint32_t b = 0; b < count; ++b) {
      TriangleBlock block{};
      for (std::uint32_t l = 0; l < kBlockWidth; ++l) {
        // A short block repeats its last triangle (see bvh_wide.h).
        const std::uint32_t i = n.index + std::min(kBlockWidth * b + l, n.count - 1);
        for (int c = 0; c < 3; ++c)
          for (int a = 0; a < 3; ++a) block.p[c][a][l] = corners[i][c][a];
        block.id[l] = prims[i];
      }
      out.blocks.push_back(block);
    }
    return kWideLeafBit | ((count - 1) << kWideCountShift) | first;
  }

  // Fills out.nodes[slot] from the binary interior node `b`, then its interior children.
  void Emit(std::uint32_t slot, std::uint32_t b) {
    // Open the largest interior child until there are kBvhWidth children or only leaves.
    std::uint32_t kids[kBvhWidth] = {bin[b].index, bin[b].index + 1};
    int n = 2;
    while (n < kBvhWidth) {
      int best = -1;
      float best_area = -1.0f;
      for (int i = 0; i < n; ++i) {
        const BvhNode& k = bin[kids[i]];
        const float area = BoxArea(k.lo, k.hi);
        if (k.count == 0 && area > best_area) best = i, best_area = area;
      }
      if (best < 0) break;
      const std::uint32_t opened = kids[best];
      kids[best] = bin[opened].index;
      kids[n++] = bin[opened].index + 1;
    }
    // Boxes and references; interior children get their slots first, then are filled.
    WideNode node{};
    std::uint32_t interior[kBvhWidth];
    int interior_count = 0;
    for (int i = 0; i < kBvhWidth; ++i) {
      if (i >= n) {
        for (int a = 0; a < 3; ++a) {
          node.planes[a][i] = std::numeric_limits<float>::infinity();
          node.planes[3 + a][i] = -std::numeric_limits<float>::infinity();
        }
        node.child[i] = kWideEmpty;
        continue;
      }
      const BvhNode& k = bin[kids[i]];
      for (int a = 0; a < 3; ++a) {
        node.planes[a][i] = k.lo[a];
        node.planes[3 + a][i] = k.hi[a];
      }
      if (k.count > 0) {
        node.child[i] = EmitLeaf(k);
      } else {
        node.child[i] = static_cast<WideRef>(out.nodes.size());
        out.nodes.push_back(WideNode{});
        interior[interior_count++] = static_cast<std::uint32_t>(i);
      }
    }
    out.nodes[slot] = node;
    for (int j = 0; j < interior_count; ++j) Emit(node.child[interior[j]], kids[interior[j]]);
  }
};

}  // namespace

WideBvh CollapseToWide(const std::vector<BvhNode>& nodes, const std::vector<std::uint32_t>& prim_indices,
                    const std::vector<std::array<glm::vec3, 3>>& corners) {
  WideBvh out;
  if (nodes.empty()) return out;
  out.nodes.reserve(nodes.size() / 2 + 1);
  out.blocks.reserve(prim_indices.size() / 2 + 1);
  Collapser c{nodes, prim_indices, corners, out};
  out.nodes.push_back(WideNode{});
  if (nodes[0].count == 0) {
    c.Emit(0, 0);
    return out;
  }
  // A one-leaf tree: a root whose only child is that leaf.
  WideNode root{};
  for (int i = 0; i < kBvhWidth; ++i) {
    for (int a = 0; a < 3; ++a) {
      root.planes[a][i] = i == 0 ? nodes[0].lo[a] : std::numeric_limits<float>::infinity();
      root.planes[3 + a][i] = i == 0 ? nodes[0].hi[a] : -std::numeric_limits<float>::infinity();
    }
    root.child[i] = kWideEmpty;
  }
  root.child[0] = c.EmitLeaf(nodes[0]);
  out.nodes[0] = root;
  return out;
}

}  // namespace prt
