#pragma once
/// \file
/// The 8-wide BVH that every traversal runs on, collapsed from the binary SAH tree of
/// `bvh_build.cpp` [1, 2], and its triangle blocks.
///
/// Collapse: a node of the wide tree starts with the two children of a binary node and
/// repeatedly replaces its interior child of largest surface area by that child's two children,
/// until it has eight children or only leaves [2]. One ray then tests eight boxes with one SIMD
/// slab test (one AVX register per plane row; two SSE registers on the baseline target), the
/// tree has about an eighth of the binary tree's nodes, and a ray takes fewer, wider steps
/// than in a 4-wide tree (measured on the PRT workload: 15 node visits per ray at width 4, and
/// 25-35 % more occlusion rays per second at width 8 with blocks of eight triangles).
///
/// Node layout (256 bytes, four cache lines): the eight child references, then the six planes
/// of the eight child boxes as rows (lo x, lo y, lo z, hi x, hi y, hi z; lane = child). A ray
/// whose direction component along an axis is negative enters a box through its hi plane, so
/// the slab test picks the "near" row per axis once per ray instead of taking a min and a max
/// per box [3]. Unused child slots hold an inverted box (lo = +inf, hi = -inf), which that
/// test never enters.
///
/// Leaves: a binary leaf (at most `max_leaf_size` triangles) becomes consecutive blocks of
/// eight triangles stored corner by corner and axis by axis (lane = triangle), so one ray tests
/// eight triangles at once with the watertight test of `triangle.h`. A block that is not full
/// repeats its last triangle: a copy gives the same answer as the original, so no lane mask is
/// needed.
///
/// References
///  [1] H. Dammertz, J. Hanika, A. Keller, "Shallow Bounding Volume Hierarchies for Fast SIMD
///      Ray Tracing of Incoherent Rays", Computer Graphics Forum 27(4), 2008 (QBVH).
///  [2] I. Wald, C. Benthin, S. Boulos, "Getting Rid of Packets: Efficient SIMD Single-Ray
///      Traversal using Multi-branching BVHs", IEEE Symposium on Interactive Ray Tracing, 2008.
///  [3] A. Williams, S. Barrus, R. K. Morley, P. Shirley, "An Efficient and Robust Ray-Box
///      Intersection Algorithm", Journal of Graphics Tools 10(1), 2005 (near plane by sign).

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
struct alignas(32) TriangleBlock {
  float p[3][3][kBlockWidth];
  std::uint32_t id[kBlockWidth];
};

/// The collapsed tree: nodes[0] is the root (always interior, even for a one-leaf tree).
struct WideBvh {
  std::vector<WideNode> nodes;
  std::vector<TriangleBlock> blocks;
};

/// Collapses the binary tree `nodes` (leaves index `prim_indices`, whose corners are
/// `corners`, in leaf order) into a wide tree. Leaves must hold at most
/// kBlockWidth * kWideMaxBlocks triangles. An empty binary tree gives an empty WideBvh.
WideBvh CollapseToWide(const std::vector<BvhNode>& nodes, const std::vector<std::uint32_t>& prim_indices,
                       const std::vector<std::array<glm::vec3, 3>>& corners);

}  // namespace prt
