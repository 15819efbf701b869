#pragma once
/// \file
/// An output folder that never mixes two runs (CLI.md, "Exit codes and messages"):
///
/// - One run at a time. The folder's lock file `.prt-lock` is held with flock(2) for the whole
///   run; a second run into the same folder is refused at once. The kernel releases the lock
///   when its process ends however it ends, so a crashed or killed run leaves nothing stuck.
/// - Exactly this run's outputs. `.prt-outputs` lists the files prt wrote there. After a
///   successful run, the files an earlier run listed and this run did not write are removed and
///   the list is replaced by this run's; files prt did not write are never touched. A failed run
///   removes nothing (its new files join the list, so the next successful run can clean them).
///
/// The commands name every file they write through Output() before writing it.

#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace prt {

/// Creates `dir` and its missing parents. Throws Error naming `dir` and the cause (a file in
/// the way, permission denied, ...) when it cannot.
void CreateFolder(const std::string& dir);

/// Creates the folder a file `path` is to be written into, if missing (see CreateFolder).
void CreateParentFolder(const std::string& path);

class OutputFolder {
 public:
  /// Creates `dir` if missing and takes its lock. Throws Error if the folder cannot be made or
  /// another run holds it.
  explicit OutputFolder(std::string dir);
  /// Releases the lock; without Finish(), removes nothing and adds the files this run wrote to
  /// the list.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& dir() const { return dir_; }

  /// The path of file `name` in the folder, recorded as an output of this run.
  std::string Output(const std::string& name);

  /// True if this run named `name` as an output.
  bool Wrote(const std::string& name);

  /// After a successful run: removes the files an earlier prt run wrote that this run did not
  /// and the temporary files of killed runs (core/atomic_file.h), and records this run's
  /// outputs. Returns the names removed.
  std::vector<std::string> Finish();

  /// Names of the lock and list files (hidden, owned by prt).
  static constexpr const char* kLockName = ".prt-lock";
  static constexpr const char* kListName = ".prt-outputs";

 private:
  void WriteList(const std::set<std::string>& names) const;

  std::string dir_;
  int lock_fd_ = -1;
  std::set<std::string> earlier_;  ///< what the list said when the run started
  std::set<std::string> written_;  ///< this run's outputs
  bool finished_ = false;
  std::mutex mutex_;
};

}  // namespace prt
