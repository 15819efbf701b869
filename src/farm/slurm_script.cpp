#include "farm/slurm_script.h"

#include "core/shell_word.h"

namespace prt {
namespace {

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
  std::vector<std::string> task = {job.prt, job.command};
  task.insert(task.end(), job.options.begin(), job.options.end());
  task.insert(task.end(), {"--shard", "auto", "--quiet"});
  const std::string extra = job.sbatch.empty() ? "" : " " + Line(job.sbatch);
  std::string s;
  s += "#!/bin/bash\n";
  s += "# Written by prt farm slurm: " + job.command + " as " + std::to_string(job.tasks) +
       " shards of an array job, then prt merge once every shard has succeeded.\n";
  s += "# Its result in " + job.out + " is what the same command run on one machine writes there.\n";
  s += "set -euo pipefail\n";
  s += "cd " + ShellWord(job.workdir) + "\n";
  s += "mkdir -p " + ShellWord(farm) + "\n";
  std::string after;  // the dependency of the next array: the merge before it
  for (int stage = 0; stage < job.stages; ++stage) {
    const std::string tag = job.stages == 1 ? "" : std::to_string(stage);
    const std::string logs = job.stages == 1 ? "" : "stage-" + tag + "-";
    s += "shards=$(sbatch --parsable --job-name=prt-shards" + tag + " --array=0-" + std::to_string(job.tasks - 1) +
         (after.empty() ? "" : " --dependency=afterok:$merge --kill-on-invalid-dep=yes") + " --chdir=" +
         ShellWord(job.workdir) + " --output=" + ShellWord(farm + "/" + logs + "shard-%a.log") + extra + " --wrap " +
         ShellWord(Line(task)) + ")\n";
    s += "shards=${shards%%;*}  # the job id without the cluster's name\n";
    s += "echo \"prt farm: shards" + (tag.empty() ? "" : " of stage " + tag) + ": job $shards (" +
         std::to_string(job.tasks) + " tasks)\" >&2\n";
    std::vector<std::string> merge = {job.prt, "merge", job.out, "--quiet"};
    if (stage > 0) merge.push_back("--bounce-stage");
    s += "merge=$(sbatch --parsable --job-name=prt-merge" + tag +
         " --dependency=afterok:$shards --kill-on-invalid-dep=yes --chdir=" + ShellWord(job.workdir) +
         " --output=" + ShellWord(farm + "/" + logs + "merge.log") + extra + " --wrap " + ShellWord(Line(merge)) + ")\n";
    s += "merge=${merge%%;*}\n";
    after = "$merge";
  }
  if (job.wait) {
    // The merge's state, asked every second until it has ended (sbatch --wait asks ever less
    // often, up to half a minute apart, and exits 0 for a job cancelled before it ran, which is
    // what a failed shard does to the merge).
    s += "while :; do\n";
    s += "  state=$(scontrol show job \"$merge\" -o 2>/dev/null | grep -o 'JobState=[A-Z_]*' || true)\n";
    s += "  case \"$state\" in\n";
    s += "    JobState=PENDING|JobState=CONFIGURING|JobState=RUNNING|JobState=COMPLETING|JobState=SUSPENDED|JobState=REQUEUED*) sleep 1 ;;\n";
    s += "    *) break ;;\n";
    s += "  esac\n";
    s += "done\n";
    s += "if [ \"$state\" != JobState=COMPLETED ]; then\n";
    s += "  echo \"prt farm: the merge job $merge ended ${state#JobState=} (a shard failed: see its log)\" >&2\n";
    s += "  exit 1\n";
    s += "fi\n";
  }
  s += "echo \"$merge\"\n";
  return s;
}

}  // namespace prt
