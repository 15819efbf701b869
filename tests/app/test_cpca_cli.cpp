// --cpca from the command line: malformed values refused before any work, the orbit's run
// summary saying what was compressed and how well, --cpca off keeping the full matrices, and
// precompute writing transfer_matrices_cpca.bin only when asked.
#include <doctest/doctest.h>

#include <filesystem>

#include "precompute_io/cpca_matrix_file.h"
#include "tests/test_process.h"

using namespace prt;
using namespace prt::test;

namespace {

std::string Tetrahedron() { return "--mesh " + Q(Fixture("obj/tetra_no_normals.obj")); }

}  // namespace

TEST_SUITE("app") {
  TEST_CASE("--cpca: malformed values are usage errors before any work") {
    const std::string out = " --out " + Q(ScratchDir("cpca_bad"));
    for (const char* bad : {"0,4", "64", "64,-1", "x,2", "64,2.5", "70000,1", "on"}) {
      const RunResult r = RunPrt(std::string("render --material phong:10,0.2 --albedo 0.5,0.5,0.5 --orbit 30 --cpca ") + bad + out);
      CHECK_MESSAGE(r.exit_code == 2, bad);
      CHECK_MESSAGE(r.err.find("--cpca: '") != std::string::npos, r.err);
      CHECK(r.err.find("light:") == std::string::npos);  // before the light was loaded
    }
    // More terms than a matrix has numbers (lmax 2: 81).
    RunResult r = RunPrt("render --material phong:10,0.2 --albedo 0.5,0.5,0.5 --orbit 30 --cpca 8,82" + out);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("more than the 81 numbers of a transfer matrix at lmax 2") != std::string::npos);
    r = RunPrt("precompute " + Tetrahedron() + " --cpca 8,2" + out);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--cpca: compresses a glossy material's transfer matrices") != std::string::npos);
  }

  TEST_CASE("--cpca: the orbit's summary says the clusters, the memory and the error; off keeps the matrices") {
    const std::string dir = ScratchDir("cpca_orbit");
    const std::string scene = Tetrahedron() + " --env sky --albedo 0.5,0.5,0.5 --material phong:2,0.4 --transport unshadowed "
                                              "--frames 2 --size 16x16 --orbit 90 --cache none";
    RunResult r = RunPrt("render " + scene + " --out " + Q(dir + "/a"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("cpca: the transfer matrices compressed by clustered PCA") != std::string::npos);
    CHECK(r.err.find("relative error") != std::string::npos);
    r = RunPrt("render " + scene + " --cpca off --out " + Q(dir + "/b"));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("cpca:") == std::string::npos);
  }

  TEST_CASE("precompute --cpca C,K writes transfer_matrices_cpca.bin; without it, none") {
    const std::string dir = ScratchDir("cpca_precompute");
    const std::string scene = "precompute --quiet " + Tetrahedron() + " --env furnace --albedo 0.5,0.5,0.5 --material phong:7,0.25";
    RunResult r = RunPrt(scene + " --out " + Q(dir));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(!std::filesystem::exists(dir + "/transfer_matrices_cpca.bin"));
    r = RunPrt(scene + " --cpca 2,1 --out " + Q(dir));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const CpcaMatrixFile f = ReadCpcaMatrixFile(dir + "/transfer_matrices_cpca.bin");
    CHECK(f.exponent == 7);
    CHECK(f.cpca.model.terms == 1);
    CHECK(f.cpca.model.clusters >= 1);
    CHECK(std::filesystem::exists(dir + "/transfer_matrices.bin"));
  }
}
