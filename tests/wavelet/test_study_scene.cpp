// The wavelet study's scene (wavelet/study.h): the knot's vertices first, standing on the ground.
// (The whole study: test_study.cpp; the command: tests/report/test_report_wavelet_cli.cpp.)
#include <doctest/doctest.h>

#include <algorithm>

#include "wavelet/study.h"

TEST_SUITE("wavelet") {
  TEST_CASE("sun scene: the knot's vertices first, standing 2 units tall on the ground's plane") {
    // The study's probe vertices and the measured numbers of report.md were taken on this order:
    // the knot's (48 x 8) vertices, then the ground's (13 x 13) on y = 0.
    const prt::Mesh mesh = prt::MakeSunScene(48, 8, 12);
    const std::size_t knot = 48 * 8;
    REQUIRE(mesh.vertex_count() == knot + 13 * 13);
    float lo = 1e9f, hi = -1e9f;
    for (std::size_t v = 0; v < knot; ++v) lo = std::min(lo, mesh.positions[v].y), hi = std::max(hi, mesh.positions[v].y);
    CHECK(lo == doctest::Approx(0.05));  // lifted off the ground
    CHECK(hi == doctest::Approx(2.05));
    for (std::size_t v = knot; v < mesh.vertex_count(); ++v) CHECK(mesh.positions[v].y == 0.0f);
  }
}
