// prt report --basis wavelet: the basis study's numbers (report_wavelet.h), its report.md section,
// report.csv rows and chart, and the command that writes them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "env/procedural.h"
#include "io/png_io.h"
#include "wavelet/transport.h"
#include "report/report_wavelet.h"
#include "sh/coeffs.h"
#include "tests/test_process.h"

namespace {

using prt::test::Q;

/// A small version of the wavelet scene (48 x 8 knot on a 12 x 12 ground, 553 vertices) under the
/// default sky, a cube of 6 x 16^2 texels, both modes; the largest budget keeps every coefficient.
/// About 3 s in Release on 2 cores; run once and shared by the tests below.
const prt::WaveletStudy& SmallStudy() {
  static const prt::WaveletStudy study = [] {
    prt::WaveletStudyConfig c;
    c.sh_lmax = {1, 2, 4};
    c.sh_samples = 512;
    c.budgets = {16, 64, 256, 6 * 16 * 16};
    c.face_size = 16;
    c.bounce_lmax = 2;
    c.reference_samples = 1024;
    c.progress = false;
    const auto sky = prt::MakeSky(prt::SkyParams{});
    prt::WaveletStudy s = prt::RunWaveletStudy(prt::MakeSunScene(48, 8, 12), *sky, c);
    s.scene = "small sun scene";
    s.environment = "sky";
    return s;
  }();
  return study;
}

/// Bytes per vertex of SmallStudy's shadowed wavelet transport at `budget`, computed again here.
double WaveletBytes(int budget) {
  const prt::Mesh mesh = prt::MakeSunScene(48, 8, 12);
  prt::TransportOptions sh;
  prt::WaveletOptions w;
  w.face_size = 16;
  w.budget = budget;
  w.selection = prt::WaveletOptions{}.selection;
  const prt::WaveletTransport t = prt::ComputeWaveletTransport(mesh, sh, w, nullptr);
  return double(t.Bytes()) / double(mesh.vertex_count());
}

/// Count of pixels that are not pure white in columns [x0, x1).
std::size_t Inked(const prt::Image8& im, int x0, int x1) {
  std::size_t n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = x0; x < x1; ++x) n += prt::test::PixelAt(im, x, y) != glm::ivec3(255);
  return n;
}

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
