// transport.txt's numbers: the writer formats them itself (faster than printf), and must write
// exactly what printf("%.7g") writes, which the course's files and viewer were made with.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/rng.h"
#include "geometry/mesh.h"
#include "precompute/transport.h"
#include "precompute_io/transport_txt.h"
#include "sh/coeffs.h"

TEST_SUITE("precompute_io") {
  TEST_CASE("transport.txt numbers are printf's %.7g, for random, tied, tiny, huge and non-finite floats") {
    std::vector<float> values = {0.f, -0.f, 1.f, -1.f, 0.5f, 1e-7f, 9.9999995e-1f, 1234567.5f, 12345675.f,
                                 0.00012345675f, 1e-30f, 3e38f, 1e-45f, 1e28f, 1e-16f,
                                 std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::quiet_NaN()};
    prt::Pcg32 rng(8, 1);
    for (int i = 0; i < 20000; ++i) {  // random bit patterns and random magnitudes
      const auto bits = static_cast<std::uint32_t>(rng.NextU32());
      float f;
      std::memcpy(&f, &bits, sizeof f);
      values.push_back(f);
      values.push_back(static_cast<float>((rng.NextDouble() - 0.5) * std::pow(10.0, 12.0 * rng.NextDouble() - 8.0)));
    }
    // One face per 9 values: a mesh of values.size() / 9 faces over distinct vertices.
    const std::size_t faces = values.size() / 9, n = prt::CoeffCount(2);
    prt::Mesh mesh;
    prt::Transport t;
    t.lmax = 2;
    t.vertices = 3 * faces;
    t.coeffs.assign(t.vertices * n, 0.f);
    for (std::size_t f = 0; f < faces; ++f) {
      const auto v = static_cast<std::uint32_t>(3 * f);
      mesh.file_triangles.push_back({v, v + 1, v + 2});
      for (std::size_t k = 0; k < n; ++k) t.coeffs[v * n + k] = values[f * 9 + k];
    }
    mesh.positions.assign(t.vertices, glm::vec3(0.f));
    std::istringstream text(prt::FormatTransportTxt(mesh, t, 0));
    std::string token;
    text >> token;  // the vertex count
    int wrong = 0;
    for (std::size_t f = 0; f < faces; ++f)
      for (int corner = 0; corner < 3; ++corner)
        for (std::size_t k = 0; k < n; ++k) {
          text >> token;
          char expected[64];
          std::snprintf(expected, sizeof expected, "%.7g", double(t.coeffs[(3 * f + corner) * n + k]));
          if (token != expected && ++wrong <= 5) MESSAGE(token << " != " << expected);
        }
    CHECK(wrong == 0);
  }
}
