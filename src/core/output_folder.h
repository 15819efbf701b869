#pragma once
/// \file
/// An output folder that never mixes two runs (docs/CLI.md, "Conventions": Outputs, and Output
/// folders serve one run at a time):
///
/// - One run at a time. The folder's lock file `.prt-lock` is held with flock(2) for the whole
///   run; a second run into the same folder is refused at once. The kernel releases the lock
///   when its process ends however it ends, so a crashed or killed run leaves nothing stuck.
/// - All of a run's outputs or none. Output() names a file in the hidden staging folder
///   `.prt-staging/`; Finish() moves them all into place (a rename each, on one file system)
///   once the run has succeeded. A failed run discards its staged files, so the folder keeps the
///   earlier run's outputs exactly as they were; a killed run leaves only its staging folder,
///   which the next run removes. (Files that are valid on their own whatever the run does, the
///   transport cache, are written in place through OutputInPlace().) A re-run therefore needs
///   room for both its outputs and the earlier ones until it finishes.
/// - Exactly this run's outputs. `.prt-outputs` lists the files prt wrote there. After a
///   successful run, the files an earlier run listed and this run did not write are removed and
///   the list is replaced by this run's; files prt did not write are never touched, nor is any
///   file or folder this run read (KeepInput: a mesh, a material library or a sky that an
///   earlier prt run wrote into the folder).
///
/// The commands name every file they write through Output() or OutputInPlace() before writing
/// it.

#include <filesystem>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace prt {

/// Creates `dir` and its missing parents. Throws Error naming `dir` and the cause (a file in
/// the way, permission denied, ...) when it cannot.
void CreateFolder(const std::string& dir);

/// `path` made absolute, its symbolic links resolved as far as it exists, normalised: two paths
/// name the same file exactly when their resolved paths are equal (neither need exist yet).
std::filesystem::path ResolvedPath(const std::string& path);

/// Creates the folder a file `path` is to be written into, if missing (see CreateFolder).
void CreateParentFolder(const std::string& path);

class OutputFolder {
 public:
  /// Creates `dir` if missing, takes its lock and makes an empty staging folder (removing one
  /// a killed run left). Throws Error if the folders cannot be made or another run holds it.
  explicit OutputFolder(std::string dir);
  /// Releases the lock; without Finish(), discards the staged files, removes nothing else and
  /// adds the files written in place to the list.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& dir() const { return dir_; }

  /// Where to write the output file `name` (a plain file name): in the staging folder until
  /// Finish() moves it into place. Recorded as an output of this run.
  std::string Output(const std::string& name);

  /// Where to write the output file `name` directly in the folder, for a file that is valid on
  /// its own however the run ends (a checked cache). Recorded as an output of this run.
  std::string OutputInPlace(const std::string& name);

  /// True if this run named `name` as an output.
  bool Wrote(const std::string& name);

  /// Records that this run reads `path` (a file, or a folder and everything in it): Finish()
  /// never removes it, even when an earlier prt run wrote it into this folder.
  void KeepInput(const std::string& path);

  /// After a successful run: moves the staged outputs into place, removes the files an earlier
  /// prt run wrote that this run did not (but no input of this run) and the temporary files of
  /// killed runs (core/atomic_file.h), and records this run's outputs. Returns the names
  /// removed. Throws Error if a staged file cannot be moved into place (the files moved before
  /// it stay: they are this run's, complete, and listed).
  std::vector<std::string> Finish();

  /// Names of the lock and list files and of the staging folder (hidden, owned by prt).
  static constexpr const char* kLockName = ".prt-lock";
  static constexpr const char* kListName = ".prt-outputs";
  static constexpr const char* kStagingName = ".prt-staging";

 private:
  void WriteList(const std::set<std::string>& names) const;
  bool IsInput(const std::string& name) const;
  std::string staging() const;

  std::string dir_;
  int lock_fd_ = -1;
  std::set<std::string> earlier_;   ///< what the list said when the run started
  std::set<std::string> staged_;    ///< this run's outputs written to the staging folder
  std::set<std::string> in_place_;  ///< this run's outputs written directly
  std::vector<std::string> inputs_;  ///< absolute, normalised paths this run reads
  bool finished_ = false;
  mutable std::mutex mutex_;
};

}  // namespace prt
