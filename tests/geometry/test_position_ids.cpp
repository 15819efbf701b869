// PositionIds and PositionEdges: connectivity by exact position, across split-normal vertices.
#include <doctest/doctest.h>

#include <algorithm>

#include "geometry/position_ids.h"
#include "geometry/procedural.h"

namespace prt {

TEST_SUITE("geometry") {
  TEST_CASE("position ids: equal positions share an id, numbered by first appearance") {
    Mesh m;
    m.positions = {{1, 2, 3}, {0.0f, 0, 0}, {1, 2, 3}, {-0.0f, 0, -0.0f}, {1, 2, 3.0000002f}};
    const std::vector<std::uint32_t> ids = PositionIds(m);
    CHECK(ids == std::vector<std::uint32_t>{0, 1, 0, 1, 2});  // -0 is 0; one ulp apart is not
  }

  TEST_CASE("position edges: a box with split normals is one closed surface") {
    // 24 vertices (4 per face) at 8 corners; 12 box edges and 6 face diagonals.
    const Mesh box = MakeBox(glm::vec3(-1), glm::vec3(1));
    const std::vector<std::uint32_t> ids = PositionIds(box);
    CHECK(*std::max_element(ids.begin(), ids.end()) == 7);
    const std::vector<PositionEdge> edges = PositionEdges(box, ids);
    CHECK(edges.size() == 18);
    std::size_t bad = 0;
    for (const PositionEdge& e : edges) bad += e.lo < e.hi && e.uses == 2 && e.balance == 0 ? 0 : 1;
    CHECK(bad == 0);
    // An open plane: its border edges are used once.
    const Mesh plane = MakePlane(1.0f, 3);
    std::size_t border = 0;
    for (const PositionEdge& e : PositionEdges(plane, PositionIds(plane))) border += e.uses == 1 ? 1 : 0;
    CHECK(border == 12);
  }
}

}  // namespace prt
