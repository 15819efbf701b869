#include "farm/slurm_script.h"

#include "core/shell_word.h"

namespace prt {
namespace {

/// Seconds between two looks at the last merge's state (--wait).
constexpr int kWaitSeconds = 1;
/// Looks in a row whose state could not be read before --wait gives up.
constexpr int kUnreadStates = 30;

/// The words as one shell line.
std::string Line(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + ShellWord(w);
  return line;
}

}  // namespace

std::string FarmFolder(const std::string& out) {
  std::string trimmed = out;
  while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
  return trimmed + ".farm";
}

std::string SlurmScript(const SlurmJob& job) {
  const std::string farm = FarmFolder(job.out);
  // Slurm expands %j, %x, ... anywhere in --output: a % of the folder's own is written %%.
  std::string logs_dir;
  for (char c : farm) logs_dir += c == '%' ? std::string("%%") : std::string(1, c);
  const std::string extra = job.sbatch.empty() ? "" : " " + Line(job.sbatch);
  std::string s;
  s += "#!/bin/bash\n";
  s += "# Written by prt farm slurm: " + job.command + " as " + std::to_string(job.tasks) + " shards of an array job" +
       (job.stages > 1 ? " per stage (the direct pass, then each bounce)" : "") +
       ", each merged once all its shards have succeeded. The result in the output folder is what the same command "
       "run on one machine writes there.\n";
  s += "set -euo pipefail\n";
  // A submission that fails cancels what was submitted before it: no array runs without its merge.
  s += "submitted=()\n";
  s += "trap 'status=$?; if [ $status -ne 0 ] && [ ${#submitted[@]} -gt 0 ]; then scancel \"${submitted[@]}\" || true; "
       "echo \"prt farm: cancelled the jobs submitted before the failure: ${submitted[*]}\" >&2; fi' EXIT\n";
  s += "cd " + ShellWord(job.workdir) + "\n";
  s += "farm=" + ShellWord(farm) + "\n";
  s += "mkdir -p \"$farm\"\n";
  for (int stage = 0; stage < job.stages; ++stage) {
    const std::string tag = job.stages == 1 ? "" : std::to_string(stage);
    const std::string logs = job.stages == 1 ? "" : "stage-" + tag + "-";
    std::vector<std::string> task = {job.prt, job.command};
    task.insert(task.end(), job.options.begin(), job.options.end());
    task.insert(task.end(), {"--shard", "auto", "--quiet"});
    std::vector<std::string> merge = {job.prt, "merge", job.out, "--quiet"};
    if (job.stages > 1) {  // each stage named: a task or merge run again finds what is done
      for (auto* words : {&task, &merge}) words->insert(words->end(), {"--bounce-stage", tag});
    }
    s += "shards=$(sbatch --parsable --job-name=prt-shards" + tag + " --array=0-" + std::to_string(job.tasks - 1) +
         (stage > 0 ? " --dependency=afterok:$merge --kill-on-invalid-dep=yes" : "") + " --chdir=" +
         ShellWord(job.workdir) + " --output=" + ShellWord(logs_dir + "/" + logs + "shard-%a.log") + extra + " --wrap " +
         ShellWord(Line(task)) + ")\n";
    s += "shards=${shards%%;*}  # the job id without the cluster's name\n";
    s += "submitted+=(\"$shards\")\n";
    s += "echo \"prt farm: shards" + (tag.empty() ? "" : " of stage " + tag) + ": job $shards (" +
         std::to_string(job.tasks) + " tasks)\" >&2\n";
    s += "merge=$(sbatch --parsable --job-name=prt-merge" + tag +
         " --dependency=afterok:$shards --kill-on-invalid-dep=yes --chdir=" + ShellWord(job.workdir) +
         " --output=" + ShellWord(logs_dir + "/" + logs + "merge.log") + extra + " --wrap " + ShellWord(Line(merge)) + ")\n";
    s += "merge=${merge%%;*}\n";
    s += "submitted+=(\"$merge\")\n";
  }
  s += "last=$merge\n";
  if (job.frame_tasks > 0) {
    std::vector<std::string> frames = {job.prt, "render"};
    frames.insert(frames.end(), job.frame_options.begin(), job.frame_options.end());
    frames.insert(frames.end(), {"--frame-range", "auto", "--quiet"});
    s += "frames=$(sbatch --parsable --job-name=prt-frames --array=0-" + std::to_string(job.frame_tasks - 1) +
         " --dependency=afterok:$last --kill-on-invalid-dep=yes --chdir=" + ShellWord(job.workdir) +
         " --output=" + ShellWord(logs_dir + "/frames-%a.log") + extra + " --wrap " + ShellWord(Line(frames)) + ")\n";
    s += "frames=${frames%%;*}\n";
    s += "submitted+=(\"$frames\")\n";
    s += "echo \"prt farm: frames: job $frames (" + std::to_string(job.frame_tasks) + " ranges)\" >&2\n";
    s += "last=$frames\n";
  }
  if (!job.video.empty()) {
    std::vector<std::string> video = {job.prt, "video", job.out};
    video.insert(video.end(), job.video.begin(), job.video.end());
    video.push_back("--quiet");
    s += "video=$(sbatch --parsable --job-name=prt-video --dependency=afterok:$last --kill-on-invalid-dep=yes --chdir=" +
         ShellWord(job.workdir) + " --output=" + ShellWord(logs_dir + "/video.log") + extra + " --wrap " +
         ShellWord(Line(video)) + ")\n";
    s += "video=${video%%;*}\n";
    s += "submitted+=(\"$video\")\n";
    s += "last=$video\n";
  }
  s += "submitted=()  # all submitted: they stay, whatever happens next\n";
  if (job.wait) {
    // The last job's state, asked every kWaitSeconds until it has ended (sbatch --wait asks
    // ever less often, and exits 0 for a job cancelled before it ran, which is what a failed
    // job before it does). An array's tasks each have a state: it has ended well when every
    // one completed, badly as soon as one did not. A state not read (slurmctld busy) is asked
    // again, up to kUnreadStates times in a row.
    s += "unread=0\n";
    s += "while :; do\n";
    s += "  states=$(scontrol show job \"$last\" -o 2>/dev/null | grep -o 'JobState=[A-Z_]*' | sort -u || true)\n";
    s += "  if [ -z \"$states\" ]; then\n";
    s += "    unread=$((unread + 1))\n";
    s += "    [ $unread -lt " + std::to_string(kUnreadStates) +
         " ] || { echo \"prt farm: the state of the job $last cannot be read (scontrol show job)\" >&2; exit 1; }\n";
    s += "  else\n";
    s += "    unread=0\n";
    s += "    [ \"$states\" != JobState=COMPLETED ] || break\n";
    s += "    bad=$(echo \"$states\" | grep -E "
         "'=(CANCELLED|FAILED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED|BOOT_FAIL|DEADLINE)$' | head -n 1 || true)\n";
    s += "    if [ -n \"$bad\" ]; then\n";
    s += "      state=${bad#JobState=}\n";
    s += "      why='see its log'\n";
    s += "      [ \"$state\" != CANCELLED ] || why='it never ran: a job before it failed, see the logs'\n";
    s += "      echo \"prt farm: the job $last ended $state ($why in $farm/)\" >&2\n";
    s += "      exit 1\n";
    s += "    fi\n";
    s += "  fi\n";
    s += "  sleep " + std::to_string(kWaitSeconds) + "\n";
    s += "done\n";
  }
  s += "echo \"$last\"\n";
  return s;
}

}  // namespace prt
