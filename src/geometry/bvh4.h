#pragma once
/// \file
/// The 4-wide BVH that every traversal runs on, collapsed from the binary SAH tree of
/// `bvh_build.cpp` [1, 2], and its triangle blocks.
///
/// Collapse: a node of the 4-wide tree starts with the two children of a binary node and
/// repeatedly replaces its interior child of largest surface area by that child's two children,
/// until it has four children or only leaves [2]. One ray then tests four boxes with one SIMD
/// slab test (a single load of each plane row), the tree has about a third of the binary tree's
/// nodes, and a ray pops a third as many stack entries.
///
/// Node layout (128 bytes, two cache lines): the six planes of the four child boxes as rows
/// (lo x, lo y, lo z, hi x, hi y, hi z; lane = child), then the four child references. A ray
/// whose direction component along an axis is negative enters a box through its hi plane, so
/// the slab test picks the "near" row per axis once per ray instead of taking a min and a max
/// per box [3]. Unused child slots hold an inverted box (lo = +inf, hi = -inf), which that
/// test never enters.
///
/// Leaves: a binary leaf (at most `max_leaf_size` triangles) becomes consecutive blocks of four
/// triangles stored corner by corner and axis by axis (lane = triangle), so one ray tests four
/// triangles at once with the watertight test of `triangle.h`. A block that is not full repeats
/// its last triangle: a copy gives the same answer as the original, so no lane mask is needed.
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

/// A reference to a child of a 4-wide node: an interior node's index, or (top bit set) a leaf
/// of `LeafBlockCount` triangle blocks starting at `LeafFirstBlock`.
using Bvh4Ref = std::uint32_t;
inline constexpr Bvh4Ref kBvh4LeafBit = 0x80000000u;
inline constexpr int kBvh4CountShift = 28;            // bits 28..30: block count - 1
inline constexpr std::uint32_t kBvh4MaxBlocks = 8;    // so leaves hold at most 32 triangles
inline constexpr Bvh4Ref kBvh4Empty = 0xFFFFFFFFu;  // an unused slot (its box is never hit)

inline bool IsLeaf(Bvh4Ref r) { return (r & kBvh4LeafBit) != 0; }
inline std::uint32_t LeafFirstBlock(Bvh4Ref r) { return r & ((1u << kBvh4CountShift) - 1u); }
inline std::uint32_t LeafBlockCount(Bvh4Ref r) { return ((r >> kBvh4CountShift) & 7u) + 1u; }

/// Four child boxes as plane rows (see the file comment) and their references.
struct alignas(64) Bvh4Node {
  float planes[6][4];  ///< rows lo x, lo y, lo z, hi x, hi y, hi z; column = child
  Bvh4Ref child[4];
  std::uint32_t pad[4];
};
static_assert(sizeof(Bvh4Node) == 128, "Bvh4Node must stay two cache lines");

/// Four triangles, corner c, axis a, lane l at p[c][a][l]; `id` is the mesh's triangle index.
struct alignas(16) TriangleBlock {
  float p[3][3][4];
  std::uint32_t id[4];
};

/// The collapsed tree: nodes[0] is the root (always interior, even for a one-leaf tree).
struct Bvh4 {
  std::vector<Bvh4Node> nodes;
  std::vector<TriangleBlock> blocks;
};

/// Collapses the binary tree `nodes` (leaves index `prim_indices`, whose corners are
/// `corners`, in leaf order) into a 4-wide tree. Leaves must hold at most 4 kBvh4MaxBlocks
/// triangles. An empty binary tree gives an empty Bvh4.
Bvh4 CollapseToBvh4(const std::vector<BvhNode>& nodes, const std::vector<std::uint32_t>& prim_indices,
                    const std::vector<std::array<glm::vec3, 3>>& corners);

}  // namespace prt
