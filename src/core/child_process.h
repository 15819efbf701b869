#pragma once
/// \file
/// Another program run as a child process, for the one job prt hands to an outside program:
/// encoding video with Debian's `ffmpeg` (video/ffmpeg_encoder.h). The child is started with
/// posix_spawn (no shell, so paths need no quoting); prt writes its standard input through a
/// pipe, and its standard output and error go to a log file that prt reads when it fails.
///
/// A child that exits early closes the pipe: a write then fails with EPIPE. SIGPIPE, which
/// would kill prt, is held blocked on the writing thread and a pending one discarded, so the
/// failure comes back as a return value and becomes an error that quotes the child's log.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>

#include "core/signal_cleanup.h"

namespace prt {

/// The executable file `name` would run as, searched along $PATH as a shell does; empty when
/// no folder of $PATH holds an executable file of that name.
std::optional<std::string> FindProgram(const std::string& name);

/// Runs argv (argv[0] a path) to completion with no input, returning its exit code (128 + the
/// signal if one ended it, -1 if it could not start) and what it wrote to standard output.
struct ProgramResult {
  int status = -1;
  std::string out;
};
ProgramResult RunProgram(const std::vector<std::string>& argv);

class ChildProcess {
 public:
  /// Starts argv (argv[0] a path) with its standard input a pipe from this process and its
  /// standard output and error appended to `log` (created). Throws Error if it cannot start.
  ChildProcess(const std::vector<std::string>& argv, const std::string& log);
  /// Kills and reaps the child if Wait() was not called.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Writes all of `bytes` to the child's input. Returns false if the child no longer reads it
  /// (it exited or closed it); never raises SIGPIPE.
  bool Write(std::string_view bytes);
  /// Closes the child's input and waits for it to exit: its exit code, or 128 + the signal
  /// that ended it.
  int Wait();

 private:
  pid_t pid_ = -1;
  int input_ = -1;  ///< the write end of the child's standard input
  CleanupOnSignal cleanup_;  ///< a signal that stops prt kills the child first
};

/// The last non-empty line of the text file `path` (at most `limit` characters of it), or "" if
/// there is none: what a failed program said last.
std::string LastLine(const std::string& path, std::size_t limit = 300);

}  // namespace prt
