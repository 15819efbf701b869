// The slurm tier (tests/README.md, "Tiers"): prt farm slurm submits to a real Slurm of one node
// (tests/farm/slurm_cluster.h), waits, and the output folder holds what one run writes, byte for
// byte (interreflection: a chain of six jobs, the direct pass and two bounces); a job one of
// whose tasks fails ends with the merge cancelled, a failing exit status and nothing final
// written.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
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

/// Every name in `dir`, folders too.
std::set<std::string> Names(const std::string& dir) {
  std::set<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
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

TEST_CASE("slurm: a render as shards, a merge, frame ranges and a video on a real Slurm writes what one run writes" *
          test::NeedsSlurm()) {
  const std::string dir = test::ScratchDir("slurm_render");
  test::OneNodeSlurm slurm(dir + "/cluster");
  // Seen and hidden vertices cast different counts (blocks balanced by work); 7 frames in 3
  // ranges (3, 2, 2), the first written by the merge; the video assembled from them.
  const std::string scene = test::SmallSceneOption("slurm_render_scene") +
                            " --samples 128 --hidden-samples 32 --frames 7 --size 48x32";
  const std::string one = dir + "/one", farmed = dir + "/farmed";
  REQUIRE(test::RunPrt("render" + scene + " --out " + Q(one) + " --video " + Q(one + "/turn.png") + " --quiet")
              .exit_code == 0);
  const test::RunResult r = test::RunCommand(slurm.Env() + " " + Q(test::PrtBinary()) + " farm slurm render" + scene +
                                             " --out " + Q(farmed) + " --video " + Q(farmed + "/turn.png") +
                                             " --tasks 2 --frame-tasks 3 --wait");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err << slurm.Logs());
  CHECK(r.err.find("video job") != std::string::npos);
  CHECK(test::FolderFiles(farmed) == test::FolderFiles(one));
  // No folder left either: the parts' staging folders and lock files are gone.
  CHECK(Names(farmed) == Names(one));
  for (const char* log : {"shard-0.log", "shard-1.log", "merge.log", "frames-0.log", "frames-1.log", "frames-2.log", "video.log"})
    CHECK_MESSAGE(fs::exists(farmed + ".farm/" + log), log);
}
}  // TEST_SUITE

}  // namespace prt
