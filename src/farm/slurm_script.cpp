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
  s += "submitted=()  # all submitted: they stay, whatever happens next\n";
  if (job.wait) {
    // The last merge's state, asked every kWaitSeconds until it has ended (sbatch --wait asks
    // ever less often, and exits 0 for a job cancelled before it ran, which is what a failed
    // shard does to the merge). A state not read (slurmctld busy) is asked again, up to
    // kUnreadStates times in a row.
    s += "unread=0\n";
    s += "while :; do\n";
    s += "  state=$(scontrol show job \"$merge\" -o 2>/dev/null | grep -o 'JobState=[A-Z_]*' || true)\n";
    s += "  state=${state#JobState=}\n";
    s += "  case \"$state\" in\n";
    s += "    '') unread=$((unread + 1)); [ $unread -lt " + std::to_string(kUnreadStates) +
         " ] || { echo \"prt farm: the state of the merge job $merge cannot be read (scontrol show job)\" >&2; exit 1; } ;;\n";
    s += "    COMPLETED) break ;;\n";
    s += "    CANCELLED|FAILED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED|BOOT_FAIL|DEADLINE)\n";
    s += "      why='see its log'\n";
    s += "      [ \"$state\" != CANCELLED ] || why='it never ran: a shard before it failed, see the shard logs'\n";
    s += "      echo \"prt farm: the merge job $merge ended $state ($why in $farm/)\" >&2\n";
    s += "      exit 1 ;;\n";
    s += "    *) unread=0 ;;\n";
    s += "  esac\n";
    s += "  sleep " + std::to_string(kWaitSeconds) + "\n";
    s += "done\n";
  }
  s += "echo \"$merge\"\n";
  return s;
}

}  // namespace prt
