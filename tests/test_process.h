#pragma once
/// \file
/// Helpers that start processes: the `prt` binary run the way a user runs it, a shell command,
/// a long render to watch and signal. Only the programs of the e2e and readme tiers link them
/// (tests/CMakeLists.txt): a unit or threads test that called one would not link, so those
/// tiers stay in-process (tests/README.md, "Tiers").

#include <string>
#include <vector>

#include "tests/test_support.h"

namespace prt::test {

/// The `prt` binary the command-line tests run: $PRT_BINARY if set (the sanitizer passes run
/// this program against their own build of prt), else the one built beside the tests (its path
/// is compiled in, so the tests need no runner to find it).
std::string PrtBinary();

struct RunResult {
  int exit_code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

/// Runs a shell command line, capturing its stdout and stderr.
RunResult RunCommand(const std::string& command);

/// Runs PrtBinary() with a shell-quoted argument string.
RunResult RunPrt(const std::string& arguments);

/// `render` of QuickScene(), `frames` frames of `size`, into `out`: the arguments for RunPrt.
std::string QuickRender(const std::string& out, int frames, const std::string& size = "16x12");

/// Starts, in a child process, a render of 9999 frames of `size` (QuickScene, one thread,
/// stderr silenced) into `out`: a run that lasts long enough to be watched and killed.
/// `extra` options are appended. Returns the child's process id (the caller waits for it).
int StartLongRender(const std::string& out, const std::string& size, const std::vector<std::string>& extra = {});

/// Waits until the file `path` exists (polling every millisecond) or the child `pid` has exited,
/// then kills the child with SIGKILL and reaps it. Returns true if the file appeared while the
/// child ran. The wait is bounded (a minute) only so that a broken build cannot hang the suite;
/// it is not a time limit on prt.
bool KillWhenFileAppears(int pid, const std::string& path);

/// The same with the signal `sig` (SIGTERM, SIGINT: prt cleans up, then ends by the signal).
/// Returns the child's wait status, or -1 if it exited before the file appeared.
int SignalWhenFileAppears(int pid, const std::string& path, int sig);

}  // namespace prt::test
