// prt farm slurm as a process, before a stand-in sbatch on PATH that records its arguments and
// answers job ids as Slurm's does ("ID;CLUSTER"): the script's two submissions, in order, the
// merge depending on the shards' job; --dry-run submits nothing; options a task would refuse,
// and a missing or failing sbatch, refused with nothing submitted. The real scheduler runs the
// job in the slurm tier (test_slurm_farm.cpp).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/test_process.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using test::Q;

/// A folder holding a stand-in `sbatch` that appends its arguments, one call a line, to
/// `dir/calls` and prints the next job id (101, 102, ...) with a cluster name; its call
/// `fail_at` (1: the first, 0: none) exits 1 instead, with sbatch's kind of message. Beside it a
/// stand-in `scancel` appends "scancel ARGS" to `dir/cancels`.
std::string StandInSbatch(const std::string& dir, int fail_at = 0) {
  fs::create_directories(dir + "/bin");
  const std::string path = dir + "/bin/sbatch", cancel = dir + "/bin/scancel";
  std::ofstream(path) << "#!/bin/bash\n"
                      << "printf '%s\\n' \"$*\" >> " << Q(dir + "/calls") << "\n"
                      << "n=$(( $(cat " << Q(dir + "/count") << " 2>/dev/null || echo 100) + 1 ))\n"
                      << "[ $n -ne $((100 + " << fail_at << ")) ] || { echo 'sbatch: error: invalid partition' >&2; exit 1; }\n"
                      << "echo $n > " << Q(dir + "/count") << "\n"
                      << "echo \"$n;prt\"\n";
  std::ofstream(cancel) << "#!/bin/bash\necho \"scancel $*\" >> " << Q(dir + "/cancels") << "\n";
  for (const std::string& tool : {path, cancel}) fs::permissions(tool, fs::perms::owner_all);
  return dir + "/bin";
}

std::vector<std::string> Calls(const std::string& dir) {
  std::vector<std::string> calls;
  std::ifstream in(dir + "/calls");
  for (std::string line; std::getline(in, line);) calls.push_back(line);
  return calls;
}

test::RunResult Farm(const std::string& bin, const std::string& arguments) {
  return test::RunCommand("PATH=" + Q(bin) + ":/usr/bin:/bin " + Q(test::PrtBinary()) + " farm slurm " + arguments);
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("farm slurm: the shards' array job, then the merge depending on it, submitted by the script it writes") {
  const std::string dir = test::ScratchDir("farm_stub");
  const std::string bin = StandInSbatch(dir);
  const std::string out = dir + "/out";
  const test::RunResult r = Farm(bin, "precompute" + test::SmallSceneOption("farm_stub_scene") + " --samples 64 --out " +
                                          Q(out) + " --tasks 3 --sbatch '--partition=long --time=1:00:00'");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::vector<std::string> calls = Calls(dir);
  REQUIRE(calls.size() == 2);
  CHECK(calls[0].find("--array=0-2 ") != std::string::npos);
  CHECK(calls[0].find(" --partition=long --time=1:00:00 ") != std::string::npos);
  CHECK(calls[0].find(" precompute --mesh ") != std::string::npos);
  CHECK(calls[0].find(" --samples 64 --out " + out + " --shard auto --quiet") != std::string::npos);
  CHECK(calls[1].find("--dependency=afterok:101 ") != std::string::npos);  // the shards' id, cluster name cut
  CHECK(calls[1].find(" --kill-on-invalid-dep=yes ") != std::string::npos);
  CHECK(calls[1].find(" merge " + out + " --quiet") != std::string::npos);
  CHECK(calls[1].find("--wait") == std::string::npos);
  CHECK(r.err.find("merge job 102 submitted") != std::string::npos);
  CHECK(fs::exists(out + ".farm/submit.sh"));
  CHECK_FALSE(fs::exists(out));  // the stand-in ran nothing

  // --dry-run: the same script on stdout, nothing submitted or written.
  const std::string dry = dir + "/dry";
  const test::RunResult d = Farm(bin, "precompute --out " + Q(dry) + " --tasks 2 --dry-run");
  CHECK(d.exit_code == 0);
  CHECK(d.out.rfind("#!/bin/bash\n", 0) == 0);
  CHECK(d.out.find("--array=0-1 ") != std::string::npos);
  CHECK(Calls(dir).size() == 2);
  CHECK_FALSE(fs::exists(dry + ".farm"));
}

TEST_CASE("farm slurm: what a task would refuse, a missing or failing sbatch, refused with nothing submitted") {
  const std::string dir = test::ScratchDir("farm_stub_refused");
  const std::string bin = StandInSbatch(dir);
  const std::string out = " --out " + Q(dir + "/out");
  struct Case {
    std::string arguments, message;
  };
  const Case cases[] = {
      {"precompute" + out + " --tasks 2 --transport interreflection --albedo 0.5,0.5,0.5 --material phong:10,0.3",
       "not with --transport interreflection and a glossy material"},
      {"precompute" + out, "--tasks N is required"},
      {"precompute" + out + " --tasks 0", "--tasks 0: expected a whole number"},
      {"precompute" + out + " --tasks 2 --shard 0/2", "--shard: prt farm gives each task its own"},
      {"precompute --tasks 2", "--out DIR is required"},
      {"precompute" + out + " --tasks 2 --lmax x", "--lmax"},
      {"view" + out + " --tasks 2", "expected precompute, render or reference"},
      {"reference --tasks 2", "--out DIR is required"},
      {"render" + out + " --tasks 2 --frame-range 0-3", "--frame-range: prt farm gives each task its own"},
      {"precompute" + out + " --tasks 2 --frame-tasks 2", "--frame-tasks: only with render"},
      {"render" + out + " --tasks 2 --frame-tasks 0", "--frame-tasks 0: expected a whole number"},
      {"render" + out + " --tasks 2 --basis wavelet", "does not split into vertex blocks"},
      {"render" + out + " --tasks 2 --frames 0", "--frames"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.arguments);
    const test::RunResult r = Farm(bin, c.arguments);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
  }
  CHECK(Calls(dir).empty());
  // No sbatch on PATH, and one that fails: exit 1, saying which.
  test::RunResult r =
      test::RunCommand("PATH=" + Q(dir) + " " + Q(test::PrtBinary()) + " farm slurm precompute" + out + " --tasks 2");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("sbatch: not found on PATH") != std::string::npos);
  const std::string failing = test::ScratchDir("farm_stub_failing");
  r = Farm(StandInSbatch(failing, 1), "precompute" + out + " --tasks 2");
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("submitting failed") != std::string::npos);
  CHECK(r.err.find("sbatch: error: invalid partition") != std::string::npos);  // sbatch's own words
  CHECK(Calls(failing).size() == 1);  // the script stops at the first failure
  CHECK_FALSE(fs::exists(failing + "/cancels"));  // nothing submitted, nothing to cancel
  // The merge's submission fails after the shards' array was submitted: the array is cancelled,
  // so that no shards run without their merge.
  const std::string second = test::ScratchDir("farm_stub_second_fails");
  r = Farm(StandInSbatch(second, 2), "precompute" + out + " --tasks 2");
  CHECK(r.exit_code == 1);
  CHECK(Calls(second).size() == 2);
  std::ifstream cancels(second + "/cancels");
  std::string line;
  CHECK(std::getline(cancels, line));
  CHECK(line == "scancel 101");
}

TEST_CASE("farm slurm: a render's shards, merge, frame ranges and video submitted in order, each after the one before") {
  const std::string dir = test::ScratchDir("farm_stub_render");
  const std::string bin = StandInSbatch(dir);
  const std::string out = dir + "/out";
  fs::create_directories(out);  // --vertex-radiance's folder is checked before any work
  const test::RunResult r = Farm(bin, "render" + test::SmallSceneOption("farm_stub_render_scene") +
                                          " --frames 10 --out " + Q(out) + " --tasks 3 --frame-tasks 4 --video " +
                                          Q(out + "/turn.png") + " --fps 12 --vertex-radiance " + Q(out + "/r.txt"));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::vector<std::string> calls = Calls(dir);
  REQUIRE(calls.size() == 4);
  // The shards: the merge they feed writes the cache, frame 0 and frame 0's --vertex-radiance.
  CHECK(calls[0].find("--array=0-2 ") != std::string::npos);
  CHECK(calls[0].find(" render --mesh ") != std::string::npos);
  CHECK(calls[0].find("--vertex-radiance " + out + "/r.txt --frame-range 0-0 --shard auto --quiet") != std::string::npos);
  CHECK(calls[0].find("--video") == std::string::npos);  // the video is the last job's
  CHECK(calls[1].find("--dependency=afterok:101 ") != std::string::npos);
  CHECK(calls[1].find(" merge " + out + " --quiet") != std::string::npos);
  // The ranges, after the merge: no --vertex-radiance (frame 0's) nor --video.
  CHECK(calls[2].find("--array=0-3 ") != std::string::npos);
  CHECK(calls[2].find("--dependency=afterok:102 ") != std::string::npos);
  CHECK(calls[2].find(" --frames 10 --out " + out + " --frame-range auto --quiet") != std::string::npos);
  CHECK(calls[2].find("--vertex-radiance") == std::string::npos);
  // The video, after every range, of the whole sequence.
  CHECK(calls[3].find("--dependency=afterok:103 ") != std::string::npos);
  CHECK(calls[3].find(" video " + out + " --video " + out + "/turn.png --frames 10 --fps 12 --quiet") !=
        std::string::npos);
  CHECK(r.err.find("video job 104 submitted") != std::string::npos);
  // More frame tasks than frames: one a frame.
  const std::string few = test::ScratchDir("farm_stub_render_few");
  const test::RunResult f = Farm(StandInSbatch(few), "render --frames 3 --out " + Q(few + "/out") +
                                                         " --tasks 2 --frame-tasks 9 --dry-run");
  CHECK(f.exit_code == 0);
  CHECK(f.out.find("--array=0-2 ") != std::string::npos);
}

TEST_CASE("farm slurm: a reference's shards and merge, one pass even with bounces (each vertex path-traced alone)") {
  const std::string dir = test::ScratchDir("farm_stub_reference");
  const std::string bin = StandInSbatch(dir);
  const std::string out = dir + "/out";
  const test::RunResult r = Farm(bin, "reference --transport interreflection --bounces 3 --out " + Q(out) + " --tasks 5");
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::vector<std::string> calls = Calls(dir);
  REQUIRE(calls.size() == 2);
  CHECK(calls[0].find("--array=0-4 ") != std::string::npos);
  CHECK(calls[0].find(" reference --transport interreflection --bounces 3 --out " + out + " --shard auto --quiet") !=
        std::string::npos);
  CHECK(calls[0].find("--bounce-stage") == std::string::npos);
  CHECK(calls[1].find(" merge " + out + " --quiet") != std::string::npos);
  CHECK(r.err.find("merge job 102 submitted") != std::string::npos);
}
}  // TEST_SUITE

}  // namespace prt
