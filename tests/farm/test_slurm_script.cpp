// The job script of prt farm slurm (farm/slurm_script.h): one array job of N shard tasks, each
// `--shard auto`, and a merge that depends on every task's success, both in the job's folder with
// the same binary and the site's sbatch options, their logs beside the output folder.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "farm/slurm_script.h"

namespace prt {
namespace {

/// The script's line that starts with `start` (REQUIREd to be there once).
std::string LineStarting(const std::string& script, const std::string& start) {
  const std::size_t at = script.find("\n" + start);
  REQUIRE(at != std::string::npos);
  REQUIRE(script.find("\n" + start, at + 1) == std::string::npos);
  return script.substr(at + 1, script.find('\n', at + 1) - at - 1);
}

SlurmJob Job() {
  SlurmJob job;
  job.prt = "/opt/prt/bin/prt";
  job.workdir = "/home/me/my scans";
  job.command = "precompute";
  job.options = {"--mesh", "scan 1.obj", "--out", "out/scan", "--samples", "4096"};
  job.out = "out/scan";
  job.tasks = 16;
  return job;
}

}  // namespace

TEST_SUITE("farm") {
TEST_CASE("slurm script: an array of N shard tasks, then the merge after all of them, in the job's folder") {
  const std::string s = SlurmScript(Job());
  // The output folder's name is in no comment: a name with a newline would be a command there.
  CHECK(s.find("# Its result") == std::string::npos);
  CHECK(s.rfind("#!/bin/bash\n", 0) == 0);
  CHECK(s.find("\nset -euo pipefail\n") != std::string::npos);
  CHECK(LineStarting(s, "cd ") == "cd '/home/me/my scans'");
  CHECK(LineStarting(s, "farm=") == "farm=out/scan.farm");
  CHECK(LineStarting(s, "mkdir ") == "mkdir -p \"$farm\"");
  const std::string shards = LineStarting(s, "shards=$(sbatch");
  CHECK(shards.find(" --array=0-15 ") != std::string::npos);
  CHECK(shards.find(" --chdir='/home/me/my scans' ") != std::string::npos);
  CHECK(shards.find(" --output=out/scan.farm/shard-%a.log ") != std::string::npos);
  // Each task: the same binary and options, its shard from the array.
  CHECK(shards.find("--wrap '/opt/prt/bin/prt precompute --mesh '\\''scan 1.obj'\\'' --out out/scan --samples 4096 "
                    "--shard auto --quiet')") != std::string::npos);
  const std::string merge = LineStarting(s, "merge=$(sbatch");
  CHECK(merge.find(" --dependency=afterok:$shards ") != std::string::npos);
  CHECK(merge.find(" --kill-on-invalid-dep=yes ") != std::string::npos);
  CHECK(merge.find(" --output=out/scan.farm/merge.log ") != std::string::npos);
  CHECK(merge.find("--wrap '/opt/prt/bin/prt merge out/scan --quiet')") != std::string::npos);
  CHECK(merge.find("--wait") == std::string::npos);
  // The merge is submitted after the shards, whose id it names.
  CHECK(s.find("shards=$(sbatch") < s.find("shards=${shards%%;*}"));
  CHECK(s.find("shards=${shards%%;*}") < s.find("merge=$(sbatch"));
  CHECK(s.substr(s.size() - 13) == "echo \"$last\"\n");
  CHECK(LineStarting(s, "last=") == "last=$merge");
  CHECK(s.find("scontrol") == std::string::npos);
}

TEST_CASE("slurm script: the site's sbatch options on both jobs, waiting on the merge's state, one task, DIR/ trimmed") {
  SlurmJob job = Job();
  job.sbatch = {"--partition=long", "--time=2:00:00"};
  job.wait = true;
  job.tasks = 1;
  job.out = "out/scan/";
  const std::string s = SlurmScript(job);
  const std::string shards = LineStarting(s, "shards=$(sbatch"), merge = LineStarting(s, "merge=$(sbatch");
  CHECK(shards.find(" --array=0-0 ") != std::string::npos);
  for (const std::string& line : {shards, merge}) CHECK(line.find(" --partition=long --time=2:00:00 ") != std::string::npos);
  CHECK(shards.find("--wait") == std::string::npos);
  CHECK(merge.find("--wait") == std::string::npos);
  // Waiting, the last job's state decides, asked until it ended: sbatch --wait exits 0 for a
  // job cancelled before it ran.
  CHECK(LineStarting(s, "last=") == "last=$merge");
  CHECK(s.find("scontrol show job \"$last\"") > s.find("last=$merge"));
  CHECK(s.find("[ \"$states\" != JobState=COMPLETED ] || break") != std::string::npos);
  CHECK(s.find("'=(CANCELLED|FAILED|") != std::string::npos);
  CHECK(FarmFolder("out/scan/") == "out/scan.farm");
  CHECK(FarmFolder("/") == "/.farm");
  // A % of the folder's own reaches Slurm's --output as %%, which it does not expand.
  job.out = "out/50%";
  const std::string percent = SlurmScript(job);
  CHECK(percent.find("--output=out/50%%.farm/shard-%a.log ") != std::string::npos);
  CHECK(LineStarting(percent, "farm=") == "farm=out/50%.farm");
  CHECK(LineStarting(s, "farm=") == "farm=out/scan.farm");
  CHECK(LineStarting(s, "mkdir ") == "mkdir -p \"$farm\"");
}
TEST_CASE("slurm script: interreflection's stages chained, each array after the merge before it") {
  SlurmJob job = Job();
  job.stages = 3;  // the direct pass and two bounces
  const std::string s = SlurmScript(job);
  std::vector<std::size_t> arrays, merges;
  for (std::size_t at = s.find("\nshards=$(sbatch"); at != std::string::npos; at = s.find("\nshards=$(sbatch", at + 1))
    arrays.push_back(at);
  for (std::size_t at = s.find("\nmerge=$(sbatch"); at != std::string::npos; at = s.find("\nmerge=$(sbatch", at + 1))
    merges.push_back(at);
  REQUIRE(arrays.size() == 3);
  REQUIRE(merges.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    CAPTURE(k);
    const std::string array = s.substr(arrays[k] + 1, s.find('\n', arrays[k] + 1) - arrays[k] - 1);
    const std::string merge = s.substr(merges[k] + 1, s.find('\n', merges[k] + 1) - merges[k] - 1);
    CHECK(arrays[k] < merges[k]);
    if (k > 0) CHECK(merges[k - 1] < arrays[k]);
    // Every array but the first waits for the merge before it; every merge for its array.
    CHECK((array.find(" --dependency=afterok:$merge --kill-on-invalid-dep=yes ") != std::string::npos) == (k > 0));
    CHECK(merge.find(" --dependency=afterok:$shards ") != std::string::npos);
    CHECK(array.find("--output=out/scan.farm/stage-" + std::to_string(k) + "-shard-%a.log") != std::string::npos);
    CHECK(merge.find("--output=out/scan.farm/stage-" + std::to_string(k) + "-merge.log") != std::string::npos);
    // Each task and merge names its stage: one run again, or after the bounces ended, finds
    // nothing to do.
    CHECK(merge.find(" --quiet --bounce-stage " + std::to_string(k) + "')") != std::string::npos);
    CHECK(array.find("--shard auto --quiet --bounce-stage " + std::to_string(k) + "')") != std::string::npos);
  }
}

TEST_CASE("slurm script: a render's frame ranges after its merge, then the video after every range") {
  SlurmJob job = Job();
  job.command = "render";
  job.options = {"--mesh", "scan 1.obj", "--out", "out/scan", "--frames", "240", "--frame-range", "0-0"};
  job.frame_tasks = 8;
  job.frame_options = {"--mesh", "scan 1.obj", "--out", "out/scan", "--frames", "240"};
  job.video = {"--video", "out/scan/turn.mp4", "--frames", "240", "--fps", "24"};
  job.wait = true;
  const std::string s = SlurmScript(job);
  const std::string merge = LineStarting(s, "merge=$(sbatch"), frames = LineStarting(s, "frames=$(sbatch"),
                    video = LineStarting(s, "video=$(sbatch");
  CHECK(s.find("merge=$(sbatch") < s.find("frames=$(sbatch"));
  CHECK(s.find("frames=$(sbatch") < s.find("video=$(sbatch"));
  // The frames' array after the merge (then $last), each task its range from the array.
  CHECK(s.find("last=$merge") < s.find("frames=$(sbatch"));
  CHECK(frames.find(" --array=0-7 ") != std::string::npos);
  CHECK(frames.find(" --dependency=afterok:$last --kill-on-invalid-dep=yes ") != std::string::npos);
  CHECK(frames.find(" --output=out/scan.farm/frames-%a.log ") != std::string::npos);
  CHECK(frames.find("--wrap '/opt/prt/bin/prt render --mesh '\\''scan 1.obj'\\'' --out out/scan --frames 240 "
                    "--frame-range auto --quiet')") != std::string::npos);
  // The video after every range, from the folder's frames.
  CHECK(s.find("last=$frames") < s.find("video=$(sbatch"));
  CHECK(video.find(" --dependency=afterok:$last --kill-on-invalid-dep=yes ") != std::string::npos);
  CHECK(video.find("--wrap '/opt/prt/bin/prt video out/scan --video out/scan/turn.mp4 --frames 240 --fps 24 --quiet')") !=
        std::string::npos);
  CHECK(merge.find("--wrap '/opt/prt/bin/prt merge out/scan --quiet')") != std::string::npos);
  // The wait and the job id printed are the video's: the job that ends last.
  CHECK(s.find("last=$video") < s.find("scontrol show job \"$last\""));
  CHECK(s.substr(s.size() - 13) == "echo \"$last\"\n");
  // A failed submission cancels every job submitted before it, the frames' and the video's too.
  CHECK(LineStarting(s, "submitted+=(\"$frames\")") == "submitted+=(\"$frames\")");
  CHECK(LineStarting(s, "submitted+=(\"$video\")") == "submitted+=(\"$video\")");
  // Without a video, the frames' array is the last job.
  job.video.clear();
  const std::string no_video = SlurmScript(job);
  CHECK(no_video.find("video=") == std::string::npos);
  CHECK(no_video.find("last=$frames") < no_video.find("scontrol show job \"$last\""));
}
}  // TEST_SUITE

}  // namespace prt
