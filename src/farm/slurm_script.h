#pragma once
/// \file
/// The job script `prt farm slurm` submits: a bash script that hands a precompute to Slurm as an
/// array job of N tasks, each `prt precompute ... --shard auto` (farm/shard_id.h reads its index
/// and count from the array), and a merge job that runs once every task has succeeded
/// (`--dependency=afterok`, `--kill-on-invalid-dep=yes`, so a failed task cancels the merge
/// instead of leaving it pending for ever). Jobs run in the folder the script was made from, on
/// the same prt binary, so the machines need the same file system at the same paths (what a
/// cluster's shared home or project folder is). The jobs' logs go to a folder beside the output
/// folder, `DIR.farm/`, so that DIR ends as one run writes it. Interreflection chains a pair
/// of jobs per stage (the direct pass, then each bounce), each array after the merge before it;
/// a stage after the bounces ended early finds nothing to do and succeeds. A render goes on
/// after its last merge: an array of frame ranges (`render --frame-range`), then `prt video`.

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
  /// The stages the tasks and the merge run: 1, or for interreflection 1 + --bounces (its direct
  /// pass, then each bounce: precompute/bounce_stages.h), each stage's tasks after the merge
  /// before them.
  int stages = 1;
  std::vector<std::string> sbatch;    ///< options given to every sbatch (--partition, --time, ...)
  bool wait = false;                  ///< the script waits for the last job and fails unless it succeeded
  /// A render's frames after its last merge (which writes the cache and frame 0): an array of
  /// `frame_tasks` tasks, each `prt render frame_options --frame-range auto`. 0: none.
  int frame_tasks = 0;
  std::vector<std::string> frame_options;
  /// `prt video`'s words after the folder (--video FILE --fps F --frames N), run once every frame
  /// is written; empty: no video.
  std::vector<std::string> video;
};

/// The folder of the jobs' logs and script: DIR.farm beside DIR.
std::string FarmFolder(const std::string& out);

/// The bash script that submits `job`; run, it prints the last job's id on its last line (the
/// last merge's, or of a render the frames' or the video's). With `wait`, it asks scontrol for
/// that job's state (every task's, for an array) every second until it ends, and exits 1 unless
/// it completed (sbatch --wait exits 0 for a job that a failed one before it cancelled).
std::string SlurmScript(const SlurmJob& job);

}  // namespace prt
