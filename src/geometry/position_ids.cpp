#include "geometry/position_ids.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace prt {
namespace {

using PositionBits = std::array<std::uint32_t, 3>;

// Bit patterns of a position's coordinates, with -0 read as +0 (they compare equal as floats).
PositionBits Bits(const glm::vec3& p) {
  PositionBits bits;
  for (int i = 0; i < 3; ++i) {
    const float x = p[i] + 0.0f;  // -0 + 0 = +0; any other value is unchanged
    std::memcpy(&bits[static_cast<std::size_t>(i)], &x, sizeof x);
  }
  return bits;
}

// Mixes the three words (multiply-xorshift); the table only needs well-spread slots.
std::uint64_t Hash(const PositionBits& p) {
  std::uint64_t h = p[0];
  h = (h ^ (h >> 29)) * 0xbf58476d1ce4e5b9ULL + p[1];
  h = (h ^ (h >> 31)) * 0x94d049bb133111ebULL + p[2];
  h = (h ^ (h >> 32)) * 0x9e3779b97f4a7c15ULL;
  return h ^ (h >> 29);
}

}  // namespace

std::vector<std::uint32_t> PositionIds(const Mesh& mesh) {
  // Open addressing with linear probing [2]: each slot holds the first vertex seen at a
  // position; the table is at most half full, so probe sequences stay short.
  constexpr std::uint32_t kEmpty = ~0u;
  std::size_t capacity = 16;
  while (capacity < 2 * mesh.positions.size()) capacity *= 2;
  std::vector<std::uint32_t> first_vertex(capacity, kEmpty);
  std::vector<PositionBits> bits(mesh.positions.size());
  std::vector<std::uint32_t> ids(mesh.positions.size());
  std::uint32_t next_id = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    bits[v] = Bits(mesh.positions[v]);
    std::size_t slot = static_cast<std::size_t>(Hash(bits[v])) & (capacity - 1);
    while (first_vertex[slot] != kEmpty && bits[first_vertex[slot]] != bits[v]) slot = (slot + 1) & (capacity - 1);
    if (first_vertex[slot] == kEmpty) {
      first_vertex[slot] = static_cast<std::uint32_t>(v);
      ids[v] = next_id++;
    } else {
      ids[v] = ids[first_vertex[slot]];
    }
  }
  return ids;
}

std::vector<PositionEdge> PositionEdges(const Mesh& mesh, const std::vector<std::uint32_t>& ids) {
  const std::size_t count = ids.empty() ? 0 : std::size_t{*std::max_element(ids.begin(), ids.end())} + 1;
  auto for_each_edge = [&](auto&& f) {
    for (const auto& t : mesh.triangles) {
      const std::uint32_t p[3] = {ids[t[0]], ids[t[1]], ids[t[2]]};
      if (p[0] == p[1] || p[1] == p[2] || p[2] == p[0]) continue;
      for (int c = 0; c < 3; ++c) f(p[c], p[(c + 1) % 3]);
    }
  };
  // Counting sort of the directed edges by their smaller end: start[lo] .. start[lo + 1] hold
  // (hi << 1 | 1 when the edge runs hi -> lo).
  std::vector<std::uint32_t> start(count + 1, 0);
  for_each_edge([&](std::uint32_t a, std::uint32_t b) { ++start[std::min(a, b) + 1]; });
  for (std::size_t i = 0; i < count; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> other(start[count]), cursor(start.begin(), start.end() - 1);
  for_each_edge([&](std::uint32_t a, std::uint32_t b) {
    other[cursor[std::min(a, b)]++] = std::max(a, b) << 1 | (a > b ? 1u : 0u);
  });

  // Within each smaller end, equal larger ends are now adjacent after a sort.
  std::vector<PositionEdge> edges;
  edges.reserve(other.size() / 2 + 1);
  for (std::uint32_t lo = 0; lo < count; ++lo) {
    const auto first = other.begin() + start[lo], last = other.begin() + start[lo + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it == first || (*it >> 1) != edges.back().hi) edges.push_back({lo, *it >> 1, 0, 0});
      ++edges.back().uses;
      edges.back().balance += (*it & 1u) ? -1 : 1;
    }
  }
  return edges;
}

}  // namespace prt
