#pragma once
/// \file
/// The job script `prt farm slurm` submits: a bash script that hands a precompute to Slurm as an
/// array job of N tasks, each `prt precompute ... --shard auto` (farm/shard_id.h reads its index
/// and count from the array), and a merge job that runs once every task has succeeded
/// (`--dependency=afterok`, `--kill-on-invalid-dep=yes`, so a failed task cancels the merge
/// instead of leaving it pending for ever). Jobs run in the folder the script was made from, on
/// the same prt binary, so the machines need the same file system at the same paths (what a
/// cluster's shared home or project folder is). The jobs' logs go to a folder beside the output
/// folder, `DIR.farm/`, so that DIR ends as one run writes it.

#include <string>
#include <vector>

namespace prt {

struct SlurmJob {
  std::string prt;                    ///< the prt binary the tasks run (an absolute path)
  std::string workdir;                ///< where the jobs run (absolute)
  std::string command;                ///< precompute
  std::vector<std::string> options;   ///< the command's options, --out DIR among them
  std::string out;                    ///< the command's --out DIR
  int tasks = 2;
  std::vector<std::string> sbatch;    ///< options given to every sbatch (--partition, --time, ...)
  bool wait = false;                  ///< the merge's sbatch waits for it and exits with its status
};

/// The folder of the jobs' logs and script: DIR.farm beside DIR.
std::string FarmFolder(const std::string& out);

/// The bash script that submits `job`; run, it prints the merge job's id on its last line. With
/// `wait`, it exits 1 unless the merge ran and succeeded (sbatch --wait alone exits 0 for a
/// merge that a failed shard cancelled: the script asks scontrol for the job's state).
std::string SlurmScript(const SlurmJob& job);

}  // namespace prt
