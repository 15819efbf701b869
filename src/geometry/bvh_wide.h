#pragma once
/// \file
/// The 8-wide BVH that every traversal runs on, collapsed from the binary SAH tree of
/// `bvh_build.cpp`, and its triangle blocks.
///
/// Collapse (SAH-optimal, by dynamic programming [4]): for every binary node n and every
/// i = 1..8, the cheapest way to stand for n's subtree with at most i subtrees, each a leaf or
/// a wide node, under the cost  C_node A(wide node) + C_block A(leaf) blocks(leaf)  summed over
/// the tree (A = surface area, blocks = triangles rounded up to eights). A wide node is then
/// the best split of its binary node's subtree into up to eight children, and a leaf may merge
/// binary leaves into full blocks. Measured on the PRT workload (knot, 102,400 triangles):
/// 2,681 wide nodes with 6.1 children on average against 4,461 with 4.1 from the usual greedy
/// collapse (open the largest child until there are eight [2]), and 2 % more occlusion rays
/// per second. One ray tests the eight child boxes of a node with one SIMD slab test [1, 2].
///
/// Node layout (256 bytes, four cache lines): the eight child references, then the six planes
/// of the eight child boxes as rows (lo x, lo y, lo z, hi x, hi y, hi z; lane = child). A ray
/// whose direction component along an axis is negative enters a box through its hi plane, so
/// the slab test picks the "near" row per axis once per ray instead of taking a min and a max
/// per box [3]. Unused child slots hold an inverted box (lo = +inf, hi = -inf), which that
/// test never enters.
///
/// Padded boxes, for the fused slab test. On AVX2 the distance to a plane p along an axis is
/// one fused multiply-add, p (1/d) - RN(o (1/d)), instead of RN(p - o) (1/d). The product
/// o (1/d) is rounded first, by a relative error of at most u = 2^-24, which moves the plane
/// by at most u |o| along the axis; so every stored box is grown by delta = 2 u B on each side
/// (B = `fused_origin_bound`, twice the largest |coordinate| of the mesh) and rounded outward.
/// For a ray whose origin has |o| <= B on every axis, the fused entry distance of the padded
/// box is then at most the correctly rounded entry distance of the true box, and its exit
/// distance at least the true exit's; rounding is monotonic, so the test enters every box the
/// ray truly touches. Other rays (far origins, directions so small that o (1/d) overflows)
/// take the exact test of [3], which the padding only makes more permissive. Boxes decide
/// only which triangles are tested, never a hit, so the padding changes no answer.
///
/// Leaves: consecutive blocks of eight triangles stored corner by corner and axis by axis
/// (lane = triangle), so one ray tests eight triangles at once with the watertight test of
/// `triangle.h`. A block that is not full repeats its last triangle: a copy gives the same
/// answer as the original, so no lane mask is needed.
///
/// References
///  [1] H. Dammertz, J. Hanika, A. Keller, "Shallow Bounding Volume Hierarchies for Fast SIMD
///      Ray Tracing of Incoherent Rays", Computer Graphics Forum 27(4), 2008 (QBVH).
///  [2] I. Wald, C. Benthin, S. Boulos, "Getting Rid of Packets: Efficient SIMD Single-Ray
///      Traversal using Multi-branching BVHs", IEEE Symposium on Interactive Ray Tracing, 2008.
///  [3] A. Williams, S. Barrus, R. K. Morley, P. Shirley, "An Efficient and Robust Ray-Box
///      Intersection Algorithm", Journal of Graphics Tools 10(1), 2005 (near plane by sign);
///      T. Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013 (the exact test's rounding bound).
///  [4] H. Ylitie, T. Karras, S. Laine, "Efficient Incoherent Ray Traversal on GPUs Through
///      Compressed Wide BVHs", High Performance Graphics 2017 (optimal collapse, section 4.1).

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace prt {

struct BvhNode;

/// Children per node, and triangles per leaf block.
inline constexpr int kBvhWidth = 8;
inline constexpr int kBlockWidth = 8;

/// A reference to a child of a wide node: an interior node's index, or (top bit set) a leaf
/// of `LeafBlockCount` triangle blocks starting at `LeafFirstBlock`.
using WideRef = std::uint32_t;
inline constexpr WideRef kWideLeafBit = 0x80000000u;
inline constexpr int kWideCountShift = 28;            // bits 28..30: block count - 1
inline constexpr std::uint32_t kWideMaxBlocks = 8;    // so leaves hold at most 64 triangles
inline constexpr WideRef kWideEmpty = 0xFFFFFFFFu;  // an unused slot (its box is never hit)

inline bool IsLeaf(WideRef r) { return (r & kWideLeafBit) != 0; }
inline std::uint32_t LeafFirstBlock(WideRef r) { return r & ((1u << kWideCountShift) - 1u); }
inline std::uint32_t LeafBlockCount(WideRef r) { return ((r >> kWideCountShift) & 7u) + 1u; }

/// Child references, then the child boxes as plane rows (see the file comment).
struct alignas(64) WideNode {
  WideRef child[kBvhWidth];
  float planes[6][kBvhWidth];  ///< rows lo x, lo y, lo z, hi x, hi y, hi z; column = child
};
static_assert(sizeof(WideNode) == 256, "WideNode must stay four cache lines");

/// Eight triangles, corner c, axis a, lane l at p[c][a][l]; `id` is the mesh's triangle index.
/// Aligned to cache lines, so a block test touches exactly its five lines.
struct alignas(64) TriangleBlock {
  float p[3][3][kBlockWidth];
  std::uint32_t id[kBlockWidth];
};
static_assert(sizeof(TriangleBlock) == 320, "TriangleBlock must stay five cache lines");

/// The collapsed tree: nodes[0] is the root (always interior, even for a one-leaf tree).
struct WideBvh {
  std::vector<WideNode> nodes;
  std::vector<TriangleBlock> blocks;
  /// Rays whose origin lies within this distance of 0 on every axis may take the fused slab
  /// test; the boxes are padded for it (see the file comment).
  float fused_origin_bound = 0.0f;
};

/// Costs of the collapse (see the file comment), in units of one node visit.
struct CollapseCosts {
  float node = 1.0f;   ///< C_node: one slab test of eight boxes
  float block = 2.0f;  ///< C_block: one test of a block of eight triangles
};

/// Collapses the binary tree `nodes` (leaves index `prim_indices`, whose corners are
/// `corners`, in leaf order) into a wide tree. Binary leaves must hold at most
/// kBlockWidth * kWideMaxBlocks triangles. An empty binary tree gives an empty WideBvh.
WideBvh CollapseToWide(const std::vector<BvhNode>& nodes, const std::vector<std::uint32_t>& prim_indices,
                       const std::vector<std::array<glm::vec3, 3>>& corners, const CollapseCosts& costs = {});

}  // namespace prt
