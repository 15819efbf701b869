#pragma once
/// \file
/// An output folder that never mixes two runs and never loses a file prt did not make
/// (docs/CLI.md, "Conventions": Outputs, and Output folders):
///
/// - One run at a time. The folder's lock file `.prt-lock` is held with flock(2) for the whole
///   run; a second run into the same folder is refused at once (FolderBusy, exit 75). The
///   kernel releases the lock when its process ends however it ends, so a crashed or killed run
///   leaves nothing stuck.
/// - All of a run's outputs or none. Output() names a file in the hidden staging folder
///   `.prt-staging/`; Finish() moves them all into place (a rename each, on one file system)
///   once the run has succeeded. A failed run discards its staged files, so the folder keeps the
///   earlier run's outputs exactly as they were; a killed run leaves only its staging folder,
///   which the next run removes. (Files that are valid on their own whatever the run does, the
///   transport cache, are written in place through OutputInPlace().) A re-run therefore needs
///   room for both its outputs and the earlier ones until it finishes.
/// - No trace of a failed run. A run that fails, or that SIGINT, SIGTERM or SIGHUP stops
///   (core/signal_cleanup.h), removes its staging folder and lock file, writes the list only if
///   it wrote a file in place, and removes the folders it created if they are empty again.
/// - Never a file prt did not make. `.prt-outputs` lists the files prt wrote there, each with
///   the command that wrote it. An output name that exists in the folder and is not listed is
///   someone else's file: the run is refused before any work, unless the plan
///   allows replacing, and then Finish() keeps the old file as `NAME.orig`.
/// - Only its own command's leftovers. After a successful run, the files an earlier run of the
///   same command listed and this run did not write are removed (fewer frames than last time);
///   files other commands wrote (precompute's light.txt beside render's frames) are kept and stay
///   listed; no file or folder this run reads is ever removed (KeepInput).
///
/// - Parts of one folder at once. A run that writes only a part of its command's outputs
///   (OutputPlan::part: `render --frame-range`'s frames, `prt video`'s video, a farm's tasks)
///   shares the lock with the other parts: any number run at once, on one machine or many over
///   a shared file system, while a whole run is refused (FolderBusy) as long as one part holds
///   the folder, and a part as long as a whole run does. Each part stages in a staging folder of
///   its own (`.prt-staging.XXXXXX`), moves its outputs into place and adds them to the list
///   under the list's own short lock (`.prt-list-lock`), and removes nothing an earlier run
///   wrote. Two parts writing the same file write the same bytes, each by a rename: harmless.
///   The last part to end removes the lock files; a whole run removes the staging folders that
///   killed parts left.
///
/// The commands name every file they write through Output() or OutputInPlace() before writing
/// it, and name them all in the plan beforehand where they know them, so that a refusal comes
/// before any work.

#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/signal_cleanup.h"

namespace prt {

/// The output folder is held by another run of prt: try again later (exit code 75, sysexits'
/// EX_TEMPFAIL, so that a CI wrapper can retry).
class FolderBusy : public Error {
 public:
  using Error::Error;
};
constexpr int kExitFolderBusy = 75;

/// Creates `dir` and its missing parents. Throws Error naming `dir` and the cause (a file in
/// the way, permission denied, ...) when it cannot.
void CreateFolder(const std::string& dir);

/// The folders a run created for its outputs: made by Create(), removed again (deepest first,
/// and only while empty) when the object is destroyed before Keep(), or when a signal stops
/// the run. So a run that fails leaves no empty folders behind.
class CreatedFolders {
 public:
  CreatedFolders() = default;
  ~CreatedFolders();
  CreatedFolders(const CreatedFolders&) = delete;
  CreatedFolders& operator=(const CreatedFolders&) = delete;

  /// CreateFolder(dir), remembering each folder it had to make.
  void Create(const std::string& dir);
  /// The folders of `path`, a file to be written (see Create).
  void CreateParentOf(const std::string& path);
  /// The run succeeded: the folders stay.
  void Keep();

 private:
  std::vector<std::string> made_;  ///< outermost first
  std::vector<CleanupOnSignal> cleanup_;
};

/// A file named on its own, outside any output folder (`--video` or `--vertex-radiance`
/// elsewhere, `diff --out`, `basis --out`): its missing folders are made (and removed again if
/// the run fails), the temporaries a killed run left beside it swept, and it is written under
/// a temporary name (AtomicFile) that Commit() renames into place once the run has succeeded.
class SingleFileOutput {
 public:
  explicit SingleFileOutput(const std::string& path);
  /// Where to write the content before Commit() (or Write() it).
  const std::string& temp_path() const { return file_->temp_path(); }
  /// Writes `bytes` as the whole content of the temporary file.
  void Write(std::string_view bytes) { file_->Write({bytes}); }
  void Commit();

 private:
  CreatedFolders created_;          ///< first made, last removed
  std::optional<AtomicFile> file_;  ///< after the folders it lies in
};

/// `path` made absolute, its symbolic links resolved as far as it exists, normalised: two paths
/// name the same file exactly when their resolved paths are equal (neither need exist yet).
std::filesystem::path ResolvedPath(const std::string& path);

/// True if `a` and `b` name the same file: the same resolved path, or (both existing) the same
/// file by device and inode (another spelling on a case-insensitive mount, a hard link).
bool SameFile(const std::string& a, const std::string& b);

/// True if the file `path` lies directly in the folder `dir` (neither need exist yet; the
/// folders are resolved, the file itself is not: a link named there is written there).
bool LiesIn(const std::string& path, const std::string& dir);

/// What a run is about to write into its folder.
struct OutputPlan {
  /// The command whose outputs these are (`render` for render and demo): a run removes only
  /// what earlier runs of its command wrote.
  std::string command;
  /// The files it will write, as far as known before any work (Plan() adds more later).
  std::vector<std::string> names;
  /// --replace: a file prt did not write is replaced, and kept as NAME.orig, instead of
  /// refusing the run.
  bool replace = false;
  /// A part of the command's outputs, written beside other parts (see "Parts of one folder at
  /// once" above): the lock shared, a staging folder of its own, nothing removed.
  bool part = false;
};

class OutputFolder {
 public:
  /// Creates `dir` if missing, takes its lock, reads the list, checks the plan's names (Plan())
  /// and makes an empty staging folder (removing one a killed run left). Throws FolderBusy if
  /// another run holds it, Error if a planned name is someone else's file (see Plan()) or
  /// if the folders cannot be made; the folder is then left as it was.
  OutputFolder(std::string dir, OutputPlan plan);
  /// Releases the lock; without Finish(), discards the staged files, removes nothing else, adds
  /// the files written in place to the list, and removes the folders it created if empty.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& dir() const { return dir_; }

  /// Checks `names` before they are written: each one that exists in the folder and that prt
  /// did not write is refused (Error naming the file and the ways out) unless the plan allows
  /// replacing it, and then its NAME.orig must not exist yet.
  void Plan(const std::vector<std::string>& names);

  /// Where to write the output file `name` (a plain file name): in the staging folder until
  /// Finish() moves it into place. Recorded as an output of this run; checked as Plan() does.
  std::string Output(const std::string& name);

  /// Where to write the output file `name` directly in the folder, for a file that is valid on
  /// its own however the run ends (a checked cache). Listed as this run's output only if the run
  /// writes it (a cache reused as it is stays its writer's). Not checked: the caller replaces
  /// only a file it recognises as its own (the cache's header).
  std::string OutputInPlace(const std::string& name);

  /// True if this run named `name` as an output.
  bool Wrote(const std::string& name);

  /// True if `name` exists in the folder and prt has no record of writing it (a staged output
  /// of this run does not count until Finish() moves it there).
  bool IsForeign(const std::string& name);

  /// Records that this run reads `path` (a file, or a folder and everything in it): Finish()
  /// never removes it, even when an earlier prt run wrote it into this folder.
  void KeepInput(const std::string& path);

  struct Finished {
    std::vector<std::string> removed;  ///< earlier outputs of this command that this run did not write
    std::vector<std::string> kept_as_orig;  ///< files prt did not write, now NAME.orig (--replace)
  };
  /// After a successful run: keeps the files prt did not write that the outputs replace as
  /// NAME.orig, moves the staged outputs into place, removes the files an earlier run of this
  /// command wrote that this run did not (but no input of this run) and the temporary files of
  /// killed runs (core/atomic_file.h), and records this run's outputs beside the other commands'.
  /// Throws Error if a staged file cannot be moved into place (the files moved before it stay:
  /// they are this run's, complete, and listed).
  Finished Finish();

  /// Names of the lock and list files and of the staging folder (hidden, owned by prt).
  static constexpr const char* kLockName = ".prt-lock";
  static constexpr const char* kListName = ".prt-outputs";
  static constexpr const char* kStagingName = ".prt-staging";
  /// The list's own lock, which parts hold while they add to it.
  static constexpr const char* kListLockName = ".prt-list-lock";
  /// What a replaced file prt did not write is renamed to: NAME + kOrigSuffix.
  static constexpr const char* kOrigSuffix = ".orig";

 private:
  void CheckLocked(const std::string& name);
  /// The files this run put in the folder: the staged ones moved there, and those named in
  /// place that are new or were rewritten since (a cache reused as it was is not).
  std::set<std::string> Written() const;
  void WriteList(const std::map<std::string, std::string>& entries) const;
  bool IsForeignLocked(const std::string& name) const;
  bool IsInput(const std::string& name) const;
  void Abandon();

  std::string dir_;
  std::string staging_;  ///< where Output() stages: `.prt-staging`, or a part's own
  OutputPlan plan_;
  CreatedFolders created_;
  int lock_fd_ = -1;
  CleanupOnSignal lock_cleanup_, staging_cleanup_;
  std::map<std::string, std::string> earlier_;  ///< name -> command, as the list said when the run started
  std::set<std::string> staged_;    ///< this run's outputs written to the staging folder
  std::map<std::string, std::string> before_;  ///< outputs written in place: the file's signature when named
  std::set<std::string> moved_;  ///< staged outputs Finish() has moved into the folder
  std::set<std::string> replaced_;  ///< names whose file prt did not write (to keep as NAME.orig)
  std::vector<std::string> inputs_;  ///< absolute, normalised paths this run reads
  bool finished_ = false;
  mutable std::mutex mutex_;
};

}  // namespace prt
