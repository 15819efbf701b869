// prt report --basis wavelet --quick as a command: the basis section, its rows and its chart, and
// none of them without --basis wavelet. (The study's numbers and writers: tests/wavelet/test_study.cpp.)
#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "io/png_io.h"
#include "tests/test_process.h"

namespace {

using prt::test::Q;

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("prt report --basis wavelet --quick writes the basis section, its rows and basis_error.png") {
    const std::string dir = prt::test::ScratchDir("report_wavelet");
    const std::string mesh = prt::test::WriteFloorAndWall(dir, glm::vec3(0.7f), glm::vec3(0.5f));
    // The SH sweep kept short; the basis study runs on the floor and wall (--mesh).
    const auto r = prt::test::RunPrt("report --quick --basis wavelet --max-lmax 1 --max-samples 16 --mesh " + Q(mesh) +
                                     " --quiet --out " + Q(dir + "/out"));
    REQUIRE(r.exit_code == 0);
    const prt::Image8 chart = prt::ReadPng(dir + "/out/basis_error.png");
    CHECK(chart.width == 2000);
    const std::string md = prt::ReadFile(dir + "/out/report.md");
    CHECK(md.find("## Basis: spherical harmonics against Haar wavelets") != std::string::npos);
    CHECK(md.find("basis_error.png") != std::string::npos);
    std::istringstream csv(prt::ReadFile(dir + "/out/report.csv"));
    std::string line;
    std::getline(csv, line);
    CHECK(line.find(",matrix_bytes,basis,budget,bytes_per_vertex,") != std::string::npos);  // then the timing columns
    const std::size_t columns = prt::test::CsvFields(line).size();
    std::vector<double> wavelet_error;
    std::size_t sh_rows = 0;
    while (std::getline(csv, line)) {
      const auto f = prt::test::CsvFields(line);
      INFO(line);
      REQUIRE(f.size() == columns);
      if (f[14] == "basis-wavelet") wavelet_error.push_back(std::stod(f[11]));
      sh_rows += f[14] == "basis-sh";
    }
    CHECK(sh_rows == 3);  // --quick: lmax 2, 4, 8
    CHECK(md.find("| shadowed | wavelet | 512 terms |") != std::string::npos);  // the default budget
    REQUIRE(wavelet_error.size() == 4);  // --quick: 64, 256, 512 (the default), 1024 terms
    CHECK(wavelet_error[3] < wavelet_error[0]);
    // Without --basis wavelet the report has no basis section, chart or columns.
    const auto plain = prt::test::RunPrt("report --quick --max-lmax 1 --max-samples 16 --mesh " + Q(mesh) +
                                         " --quiet --out " + Q(dir + "/plain"));
    REQUIRE(plain.exit_code == 0);
    CHECK_FALSE(std::filesystem::exists(dir + "/plain/basis_error.png"));
    CHECK(prt::ReadFile(dir + "/plain/report.csv").find(",basis,budget") == std::string::npos);
    CHECK(prt::ReadFile(dir + "/plain/report.md").find("## Basis") == std::string::npos);
  }
}
