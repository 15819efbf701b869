#pragma once
/// \file
/// Outputs are never half-written: a file is written under a temporary name in the same folder
/// and renamed over the destination only once complete (rename is atomic on POSIX file systems).
/// A failed or interrupted run leaves the previous file, if any, untouched.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/signal_cleanup.h"

namespace prt {

/// A temporary file beside `path`, renamed to `path` by Commit() and removed if never committed
/// (also when SIGINT, SIGTERM or SIGHUP stops the run: core/signal_cleanup.h).
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Where to write the content before Commit().
  const std::string& temp_path() const { return temp_; }

  /// The mark of prt's temporary names, `.<name>.prt-tmp<pid>_<n>`: distinct enough that no
  /// one else's file is taken for one.
  static constexpr const char* kTemporaryTag = ".prt-tmp";
  /// True if `name` (a file name without folder) is one of these temporary files,
  /// `.<name>.prt-tmp<pid>_<n>`; `pid` then receives the process that made it.
  static bool IsTemporaryName(const std::string& name, long* pid = nullptr);
  /// Removes the temporary files in `folder` whose process is gone (what runs killed by SIGKILL
  /// left), all of them or those of the file `name` only. Returns the names removed.
  static std::vector<std::string> RemoveStaleIn(const std::string& folder, const std::string& name = "");
  /// RemoveStaleIn for the file `path`: what a killed run left while writing it.
  static void RemoveStale(const std::string& path);
  /// True if process `pid` no longer exists (and is not this one).
  static bool ProcessGone(long pid);
  /// Writes `parts`, one after the other, as the whole content of the temporary file. Throws
  /// Error naming the destination and the cause (WriteProblem) on failure.
  void Write(const std::vector<std::string_view>& parts);
  /// Renames the temporary file over the destination. Throws Error on failure.
  void Commit();

 private:
  std::string path_;
  std::string temp_;
  CleanupOnSignal cleanup_;  ///< the temporary file, removed if a signal stops the run
  bool committed_ = false;
};

/// Writes `bytes` to `path` through an AtomicFile. Throws Error naming `path` and the cause
/// (WriteProblem) on failure; the previous file at `path`, if any, is then left as it was.
void WriteFileAtomic(const std::string& path, const std::string& bytes);

/// The same for content in pieces, written one after the other: large outputs (the transport
/// cache, transfer matrices) are never copied into one buffer first.
void WriteFileAtomic(const std::string& path, const std::vector<std::string_view>& parts);

/// Writes all of `bytes` to the file descriptor `fd`, retrying short writes and EINTR. Returns 0,
/// or the errno of the write that failed (EIO for a write that wrote nothing).
int WriteAll(int fd, std::string_view bytes);

/// Why writing into `path` failed with `error` (an errno value), in the user's terms: the
/// folder does not exist (or is a file), exists but takes no new files (ENOENT from /proc and
/// the like), is not writable (permission denied, read-only file system), the disk is full, or
/// the system's own words for anything else.
std::string WriteProblem(const std::string& path, int error);

/// Reads a whole file. Throws Error naming `path` if it is missing, a directory or unreadable.
std::string ReadFile(const std::string& path);

/// True if the file at `path` starts with the `size` bytes at `magic`; false for a shorter file
/// and for a path that cannot be read.
bool FileStartsWith(const std::string& path, const char* magic, std::size_t size);

}  // namespace prt
