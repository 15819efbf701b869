// transfer_matrices_cpca.bin (precompute_io/cpca_matrix_file.h): written and read back exactly,
// and refused with one line naming the file when truncated, damaged or not one.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "cpca/cpca_transfer.h"
#include "precompute/transport.h"
#include "precompute_io/cpca_matrix_file.h"
#include "tests/precompute/glossy_test_util.h"
#include "tests/test_support.h"

using namespace prt;

TEST_SUITE_BEGIN("precompute_io");

namespace {

struct Compressed {
  Mesh mesh;
  Transport transport;
  CpcaTransfer cpca;
};

Compressed MakeCompressed(bool coloured) {
  Compressed c;
  test::GlossyMatrixScene scene = test::MakeGlossyMatrixScene(coloured, "phong:9,0.3");
  c.mesh = std::move(scene.mesh);
  c.transport = std::move(scene.transport);
  CpcaOptions co;
  co.clusters = 4;
  co.terms = 3;
  c.cpca = CompressTransferMatrices(c.transport, co);
  return c;
}

}  // namespace

TEST_CASE("transfer_matrices_cpca.bin: read back exactly as written, 1 and 3 channels") {
  for (bool coloured : {false, true}) {
    const Compressed c = MakeCompressed(coloured);
    const std::string path = test::ScratchDir("cpca_file") + "/transfer_matrices_cpca.bin";
    WriteCpcaMatrixFile(path, c.mesh, c.transport, c.cpca);
    const CpcaMatrixFile f = ReadCpcaMatrixFile(path);
    CHECK(f.exponent == 9);
    CHECK(f.ks == 0.3);
    CHECK(f.lobe == c.transport.material.lobe.ZonalCoefficients(2));
    CHECK(f.cpca.lmax == 2);
    CHECK(f.cpca.channels == c.transport.channels);
    CHECK(f.cpca.vertices == c.mesh.vertex_count());
    CHECK(f.cpca.model.clusters == 4);
    CHECK(f.cpca.model.terms == 3);
    CHECK(f.cpca.model.means == c.cpca.model.means);
    CHECK(f.cpca.model.principal == c.cpca.model.principal);
    CHECK(f.cpca.model.cluster == c.cpca.model.cluster);
    CHECK(f.cpca.model.weights == c.cpca.model.weights);
    CHECK(f.transfer == c.transport.coeffs);
    CHECK(f.positions == c.mesh.positions);
    CHECK(f.normals == c.mesh.normals);
    CHECK(f.albedo == c.mesh.albedo);
    CHECK(ReconstructMatrices(f.cpca) == ReconstructMatrices(c.cpca));
  }
}

TEST_CASE("transfer_matrices_cpca.bin: truncated, damaged or foreign files are refused with the path") {
  const Compressed c = MakeCompressed(false);
  const std::string dir = test::ScratchDir("cpca_file_bad");
  const std::string path = dir + "/c.bin";
  WriteCpcaMatrixFile(path, c.mesh, c.transport, c.cpca);
  const auto size = std::filesystem::file_size(path);
  // A cluster index out of range (the first vertex's, after its position, normal, albedo and T).
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    const std::size_t header = 48 + 3 * 8, clusters = 4 * 4 * 81 * 4;
    f.seekp(std::streamoff(header + clusters + 9 * 4 + 9 * 4));
    const std::uint32_t bad = 99;
    f.write(reinterpret_cast<const char*>(&bad), 4);
  }
  CHECK_THROWS_WITH_AS(ReadCpcaMatrixFile(path), doctest::Contains("names cluster 99 of 4"), Error);
  std::filesystem::resize_file(path, size - 4);
  const std::string named = path + ": ";
  CHECK_THROWS_WITH_AS(ReadCpcaMatrixFile(path), doctest::Contains(named.c_str()), Error);
  CHECK_THROWS_WITH_AS(ReadCpcaMatrixFile(path), doctest::Contains("bytes where the header implies"), Error);
  std::ofstream(dir + "/other.bin") << "PRTMATRX and more bytes than a header has, surely more than 48";
  CHECK_THROWS_WITH_AS(ReadCpcaMatrixFile(dir + "/other.bin"), doctest::Contains("not a compressed transfer matrix file"),
                       Error);
  CHECK_THROWS_WITH_AS(ReadCpcaMatrixFile(dir + "/missing.bin"), doctest::Contains("cannot be read"), Error);
}

TEST_SUITE_END();
