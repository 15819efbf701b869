// The slurm tier (tests/README.md, "Tiers"): prt farm slurm submits to a real Slurm of one node
// (tests/farm/slurm_cluster.h), waits, and the output folder holds what one run writes, byte for
// byte (interreflection: a chain of six jobs, the direct pass and two bounces); a job one of
// whose tasks fails ends with the merge cancelled, a failing exit status and nothing final
// written.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "tests/farm/slurm_cluster.h"
#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

std::string Read(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("slurm: a precompute as shards and a merge on a real Slurm writes what one run writes; a failed task fails the job" *
          test::NeedsSlurm()) {
  const std::string dir = test::ScratchDir("slurm_farm");
  test::OneNodeSlurm slurm(dir + "/cluster");
  // Interreflection: the direct pass and two bounces, each stage's array after the merge before it.
  const std::string scene = test::SmallSceneOption("slurm_farm_scene") + " --samples 64 --transport interreflection --bounces 2";
  const std::string one = dir + "/one", farmed = dir + "/farmed";
  REQUIRE(test::RunPrt("precompute" + scene + " --out " + Q(one) + " --quiet").exit_code == 0);
  test::RunResult r = test::RunCommand(slurm.Env() + " " + Q(test::PrtBinary()) + " farm slurm precompute" + scene +
                                       " --out " + Q(farmed) + " --tasks 3 --wait");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err << slurm.Logs());
  CHECK(r.err.find("succeeded") != std::string::npos);
  CHECK(test::FolderFiles(farmed) == test::FolderFiles(one));
  for (int stage = 0; stage < 3; ++stage) {
    CAPTURE(stage);
    for (int i = 0; i < 3; ++i)
      CHECK(fs::exists(farmed + ".farm/stage-" + std::to_string(stage) + "-shard-" + std::to_string(i) + ".log"));
    CHECK(fs::exists(farmed + ".farm/stage-" + std::to_string(stage) + "-merge.log"));
  }

  // More tasks than a tetrahedron has vertices: every task refuses once it has read the mesh,
  // so the merge is cancelled, --wait fails, and nothing final is written.
  const std::string failed = dir + "/failed";
  r = test::RunCommand(slurm.Env() + " " + Q(test::PrtBinary()) + " farm slurm precompute " + test::QuickScene() +
                       " --out " + Q(failed) + " --tasks 5 --wait");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("the job failed") != std::string::npos);
  CHECK_FALSE(fs::exists(failed + "/transport.txt"));
  CHECK(Read(failed + ".farm/shard-0.log").find("at most one shard per vertex") != std::string::npos);
}
}  // TEST_SUITE

}  // namespace prt
