// transfer_matrices.bin (precompute_io/transfer_matrix_file.h): written and read back, shaded from the file
// by its documented formula alone, and refused when damaged.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "material/lobe_transfer.h"
#include "precompute/transfer_matrix.h"
#include "precompute/transport.h"
#include "precompute_io/transfer_matrix_file.h"
#include "sh/basis.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("precompute_io");

TEST_CASE("transfer_matrices.bin: read back as written, and its formula shades as prt does") {
  // Tolerance: float storage of M and T, summed over 16 x 16 terms.
  constexpr double kTol = 1e-5;
  Mesh mesh = test::SphereOverPlane();
  mesh.albedo[3] = glm::vec3(0.2f, 0.4f, 0.3f);  // coloured: three channels with interreflection
  TransportOptions o;
  o.mode = TransportMode::kInterreflection;
  o.lmax = 3;
  o.samples = 128;
  o.material = ParseMaterial("phong:12,0.3");
  o.matrices = true;
  const Transport t = ComputeTransport(mesh, o, nullptr);
  REQUIRE(t.channels == 3);
  const std::string path = test::ScratchDir("matrix_file") + "/transfer_matrices.bin";
  WriteTransferMatrixFile(path, mesh, t);
  const TransferMatrixFile f = ReadTransferMatrixFile(path);
  CHECK(f.lmax == 3);
  CHECK(f.channels == 3);
  CHECK(f.exponent == 12);
  CHECK(f.ks == 0.3);
  CHECK(f.matrices == t.matrices);
  CHECK(f.transfer == t.coeffs);
  CHECK(f.positions == mesh.positions);
  CHECK(f.albedo == mesh.albedo);

  // B = albedo (T . L) + KS sum_l h_l sum_m (M L)_lm Y_lm(r), from the file's numbers only.
  const ShRgb light = test::BandLimitedLight(3);
  const glm::dvec3 eye(3.0, 4.0, 2.0);
  const std::vector<glm::vec3> prt_glossy = GlossyFromMatrices(mesh, t, t.material, light, eye);
  const int n = 16;
  for (std::size_t v = 0; v < mesh.vertex_count(); v += 11) {
    const glm::dvec3 normal(f.normals[v]), view = glm::normalize(eye - glm::dvec3(f.positions[v]));
    const glm::dvec3 r = 2.0 * glm::dot(normal, view) * normal - view;
    std::vector<double> y(n);
    EvalBasis(3, glm::normalize(r), y.data());
    for (int c = 0; c < 3; ++c) {
      const float* m = f.matrices.data() + (v * 3 + c) * n * n;
      double glossy = 0.0;
      for (int i = 0; i < n; ++i) {
        double ml = 0.0;
        for (int j = 0; j < n; ++j) ml += m[i * n + j] * light[j][c];
        int l = 0;  // the band of index i = l(l+1) + m
        while ((l + 1) * (l + 1) <= i) ++l;
        glossy += f.lobe[l] * y[i] * ml;
      }
      CHECK(std::abs(f.ks * glossy - prt_glossy[v][c]) < kTol);
    }
  }
}

TEST_CASE("transfer_matrices.bin: a damaged file is refused with its path and what is wrong") {
  Mesh mesh = test::SphereOverPlane();
  TransportOptions o;
  o.mode = TransportMode::kUnshadowed;
  o.material = ParseMaterial("phong:5");
  o.matrices = true;
  const Transport t = ComputeTransport(mesh, o, nullptr);
  const std::string dir = test::ScratchDir("matrix_file_bad");
  const std::string path = dir + "/m.bin";
  WriteTransferMatrixFile(path, mesh, t);
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size - 4);
  CHECK_THROWS_WITH_AS(ReadTransferMatrixFile(path), doctest::Contains("bytes where the header implies"), Error);
  std::ofstream(dir + "/other.bin") << "PRTCACHE and more bytes than a header";
  CHECK_THROWS_WITH_AS(ReadTransferMatrixFile(dir + "/other.bin"), doctest::Contains("not a transfer matrix file"), Error);
}

TEST_SUITE_END();
