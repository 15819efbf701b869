// The threads tier of src/precompute_io (tests/README.md, "Tiers"): transport.txt, formatted a
// chunk of faces at a time, is the same text on one thread and on more threads than cores;
// ThreadSanitizer watches the many-thread run.
#include <doctest/doctest.h>

#include "precompute/transport.h"
#include "precompute_io/transport_txt.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/threads_util.h"

namespace prt {

TEST_SUITE("precompute_io") {
  TEST_CASE("threads: transport.txt is the same text on 1 and many threads") {
    test::SphereOverPlaneShape shape;
    shape.plane_divisions = 24;  // 1,000 faces and more: several chunks
    const Mesh mesh = test::SphereOverPlane(shape);
    TransportOptions o;
    o.mode = TransportMode::kUnshadowed;
    const Transport transport = ComputeTransport(mesh, o, nullptr);
    const auto [one, many] = test::OneAndMany([&] { return FormatTransportTxt(mesh, transport, 0); });
    CHECK(one == many);
    CHECK(one.size() > 10000);
  }
}

}  // namespace prt
