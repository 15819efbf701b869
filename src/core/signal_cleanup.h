#pragma once
/// \file
/// A run stopped by SIGINT (Ctrl-C), SIGTERM (what CI sends on cancel and timeout) or SIGHUP
/// leaves no temporary file behind (docs/CLI.md, "Outputs").
///
/// What a run would leave if it stopped now registers itself here for as long as it exists: the
/// temporary name of an AtomicFile, an output folder's staging folder and lock file, folders
/// the run created, the ffmpeg child and its log. `prt`'s main calls InstallSignalCleanup()
/// before any thread starts: the three signals are then blocked in every thread, and one
/// watcher thread waits for them with sigwait(2). When one arrives, the watcher (an ordinary
/// thread, not a signal handler, so it may take locks and call the file system) holds the
/// registry for good, kills and reaps the registered children first (so that no encoder
/// writes a file after it was removed), removes the registered files and folders, newest
/// first, then ends the process by the same signal with its default action (exit status
/// 128 + signal, as the shell expects).
///
/// A name is registered before the file is created (AtomicFile registers its name before it
/// opens it), and the watcher never lets go of the registry, so no file is registered after the
/// cleanup began; one registered just before and created during the first pass is removed by a
/// second pass 50 ms later. SignalCleanupHold defers the cleanup over a step that must not be
/// cut in half (OutputFolder::Finish moving the outputs into place). A SIGKILL cannot be
/// caught: the next run of prt sweeps what it left (OutputFolder::Finish for the output folder,
/// AtomicFile::RemoveStale beside single-file outputs and ffmpeg's log).
///
/// Without InstallSignalCleanup (the tests' own processes) the registry is kept and never used.

#include <cstdint>
#include <functional>
#include <string>

#include <sys/types.h>

namespace prt {

/// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread (and so in every thread it starts
/// later) and starts the watcher thread. Call once, first thing in main.
void InstallSignalCleanup();

/// The signal mask a child process should start with: the one the process had before
/// InstallSignalCleanup blocked the three signals (so ffmpeg still stops on Ctrl-C).
void ChildSignalMask(void* sigset_out);

/// What the cleanup does with a registered path.
enum class CleanupKind {
  kFile,         ///< unlink it
  kTree,         ///< remove it and everything in it
  kEmptyFolder,  ///< rmdir it, only if empty (a folder the run created)
};

/// Registers `path` for the cleanup while the object lives; Release() (or destruction)
/// withdraws it. Movable, not copyable.
class CleanupOnSignal {
 public:
  CleanupOnSignal() = default;
  CleanupOnSignal(std::string path, CleanupKind kind);
  /// Starts a child process with `spawn` (returning its pid, or -1 if none started) and
  /// registers it in one step, so no signal falls between the two: the child is killed with
  /// SIGKILL and reaped before any file is removed.
  static CleanupOnSignal Spawn(const std::function<pid_t()>& spawn);
  ~CleanupOnSignal() { Release(); }
  CleanupOnSignal(CleanupOnSignal&& other) noexcept : id_(other.id_) { other.id_ = 0; }
  CleanupOnSignal& operator=(CleanupOnSignal&& other) noexcept;
  CleanupOnSignal(const CleanupOnSignal&) = delete;
  CleanupOnSignal& operator=(const CleanupOnSignal&) = delete;

  void Release();

 private:
  std::uint64_t id_ = 0;
};

/// While one lives, a signal's cleanup waits (then runs on what is registered once it ends): for a
/// step that must not be cut in half. Its own thread may register and release meanwhile.
class SignalCleanupHold {
 public:
  SignalCleanupHold();
  ~SignalCleanupHold();
  SignalCleanupHold(const SignalCleanupHold&) = delete;
  SignalCleanupHold& operator=(const SignalCleanupHold&) = delete;
};

}  // namespace prt
