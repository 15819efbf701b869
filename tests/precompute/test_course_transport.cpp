#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "core/atomic_file.h"
#include "io/obj_loader.h"
#include "precompute/transport.h"
#include "precompute_io/transport_txt.h"
#include "tests/test_support.h"

using namespace prt;

namespace {

/// Rows of a course transport.txt (after the vertex-count line).
std::vector<std::vector<double>> Rows(const std::string& text, std::size_t* vertex_count) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  *vertex_count = std::stoul(line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream ls(line);
    std::vector<double> r;
    double v;
    while (ls >> v) r.push_back(v);
    rows.push_back(r);
  }
  return rows;
}

struct Agreement {
  double mean_difference[9];
  double standard_error[9];
};

/// Per-coefficient difference of the row means, and its standard error from the spread of the
/// per-row differences over the ~7905 independent vertices (three rows share a vertex).
Agreement Compare(const std::vector<std::vector<double>>& ours, const std::vector<std::vector<double>>& theirs,
                  double independent) {
  Agreement a{};
  for (int k = 0; k < 9; ++k) {
    double sum = 0, sum2 = 0;
    for (std::size_t r = 0; r < ours.size(); ++r) {
      const double d = ours[r][k] - theirs[r][k];
      sum += d, sum2 += d * d;
    }
    const double n = double(ours.size()), mean = sum / n;
    a.mean_difference[k] = mean;
    a.standard_error[k] = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / independent);
  }
  return a;
}

}  // namespace

TEST_SUITE("precompute") {
  TEST_CASE("mary: our transport.txt matches the published course files (rows, and means within noise)" * test::NeedsSharedData()) {
    const std::string data = *test::SharedData();
    const Mesh mary = LoadObj(data + "/games202/mary/mary.obj").mesh;
    const std::string peers = data + "/games202/peer-outputs/Remyuu_GAMES202-Homework/";
    // Both published files: 100 directions per vertex (the course's stratified sampler).
    for (TransportMode mode : {TransportMode::kUnshadowed, TransportMode::kShadowed}) {
      TransportOptions o;
      o.mode = mode;
      o.samples = 100;
      const std::string ours_text = FormatTransportTxt(mary, ComputeTransport(mary, o, nullptr), 0);
      const std::string path = mode == TransportMode::kUnshadowed
                                   ? peers + "unshadowed/GraceCathedral/transport_unshadowed.txt"
                                   : peers + "GraceCathedral/transport_shadowed.txt";
      std::size_t ours_count = 0, theirs_count = 0;
      const auto ours = Rows(ours_text, &ours_count);
      const auto theirs = Rows(ReadFile(path), &theirs_count);
      // The format: the welded vertex count, then three rows per face of the file, 9 numbers.
      CHECK(ours_count == 7905);
      CHECK(ours_count == theirs_count);
      REQUIRE(ours.size() == theirs.size());
      REQUIRE(ours[0].size() == 9);
      const Agreement a = Compare(ours, theirs, 7905.0);
      for (int k = 0; k < 9; ++k) {
        MESSAGE(TransportModeName(mode) << " T" << k << ": mean difference " << a.mean_difference[k]
                                        << " (standard error " << a.standard_error[k] << ")");
        // Unshadowed: ours is exact, theirs a 100-sample estimate: 4 standard errors.
        // Shadowed: the published caster sees 0.5% more of the hemisphere than ours at every
        // sample count and sampler we tried (ours is watertight and agrees with brute force;
        // moving our ray origins off the surface changes it by < 0.05%), a systematic 1.0% of
        // the mean T00; allowed as 0.002 on top of 4 standard errors.
        const double systematic = mode == TransportMode::kShadowed ? 2e-3 : 0.0;
        CHECK(std::abs(a.mean_difference[k]) < 4.0 * a.standard_error[k] + systematic);
      }
    }
  }
}
