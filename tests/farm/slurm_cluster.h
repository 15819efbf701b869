#pragma once
/// \file
/// A real Slurm of one node on this machine, for the slurm tier (tests/README.md, "Tiers"):
/// Debian's munged with a fresh key, slurmctld and slurmd, with a minimal slurm.conf in a scratch
/// folder (free ports, proctrack/linuxproc, task/none: no cgroups, no systemd), started by the
/// test as root and stopped, every daemon it started, when it goes. Its client commands (sbatch,
/// squeue) find it through SLURM_CONF, which Env() gives.

#include <string>

#include "tests/test_support.h"

namespace prt::test {

class OneNodeSlurm {
 public:
  /// Starts the daemons in `dir` and waits until the node takes jobs (REQUIREd, within a minute:
  /// a liveness bound, not a time limit on Slurm).
  explicit OneNodeSlurm(const std::string& dir);
  /// Stops every daemon it started (SIGTERM, then SIGKILL after 10 s).
  ~OneNodeSlurm();
  OneNodeSlurm(const OneNodeSlurm&) = delete;
  OneNodeSlurm& operator=(const OneNodeSlurm&) = delete;

  /// "SLURM_CONF=DIR/slurm.conf": the prefix of a shell command that talks to this cluster.
  std::string Env() const { return "SLURM_CONF=" + dir_ + "/slurm.conf"; }
  /// The daemons' logs, for a failure's message.
  std::string Logs() const;

 private:
  std::string dir_;
};

}  // namespace prt::test
