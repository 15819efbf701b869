#include "core/output_folder.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/atomic_file.h"

namespace prt {
namespace fs = std::filesystem;

void CreateFolder(const std::string& dir) {
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  // The first existing ancestor tells why: a file in the way, or a folder we may not write.
  fs::path existing = fs::path(dir);
  while (!existing.empty() && !fs::exists(existing, ec)) existing = existing.parent_path();
  if (!existing.empty() && !fs::is_directory(existing, ec))
    throw Error(dir + ": cannot create the folder ('" + existing.string() + "' is a file, expected a folder)");
  fs::create_directories(dir, ec);
  // The folder that refused is the deepest one that exists: name it, not the one to be made.
  if (ec || !fs::is_directory(dir))
    throw Error(dir + ": cannot create the folder (" +
                WriteProblem((existing.empty() ? fs::path(".") : existing).string() + "/x", ec.value() ? ec.value() : EIO) +
                ")");
}

CreatedFolders::~CreatedFolders() {
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) ::rmdir(it->c_str());  // only if empty
}

void CreatedFolders::Create(const std::string& dir) {
  std::error_code ec;
  if (dir.empty() || fs::is_directory(dir, ec)) return;
  // The missing folders, outermost first, registered before they exist.
  std::vector<std::string> missing;
  for (fs::path p = fs::path(dir).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    if (p.filename().empty()) continue;  // a trailing separator
    missing.insert(missing.begin(), p.string());
  }
  const std::size_t registered = cleanup_.size();
  for (const std::string& m : missing) cleanup_.emplace_back(m, CleanupKind::kEmptyFolder);
  try {
    CreateFolder(dir);
  } catch (const Error&) {
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) ::rmdir(it->c_str());
    cleanup_.resize(registered);  // this call's registrations only
    throw;
  }
  made_.insert(made_.end(), missing.begin(), missing.end());
}

void CreatedFolders::CreateParentOf(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) Create(parent.string());
}

void CreatedFolders::Keep() {
  made_.clear();
  cleanup_.clear();
}

SingleFileOutput::SingleFileOutput(const std::string& path) {
  created_.CreateParentOf(path);
  AtomicFile::RemoveStale(path);
  file_.emplace(path);
}

void SingleFileOutput::Commit() {
  file_->Commit();
  created_.Keep();
}

namespace {

/// What tells whether a file was written since: its inode, size and modification time ("" when
/// there is no such file). A rename over it gives another inode.
std::string FileSignature(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return "";
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" +
         std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
}

/// The list's lines: `command<TAB>name`; a line without a tab (a prt older than the commands'
/// names in the list) is a file prt wrote for no known command, which no run removes.
std::map<std::string, std::string> ReadList(const std::string& path) {
  std::map<std::string, std::string> entries;
  std::error_code ec;
  if (!fs::exists(path, ec)) return entries;
  std::istringstream list(ReadFile(path));
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    const std::string command = tab == std::string::npos ? "" : line.substr(0, tab);
    const std::string name = tab == std::string::npos ? line : line.substr(tab + 1);
    if (!name.empty() && name.find('/') == std::string::npos) entries[name] = command;
  }
  return entries;
}

/// A part waits this long at most for the lock the last part holds alone while it ends.
constexpr int kPartLockTries = 100;
constexpr useconds_t kPartLockWaitUs = 20000;

/// Takes `fd`'s flock in `mode` without waiting. A part (LOCK_SH) tries again for a moment: the
/// last part of a folder to end holds the lock alone while it removes the lock files.
bool TryLock(int fd, int mode) {
  for (int tries = 0;; ++tries) {
    if (::flock(fd, mode | LOCK_NB) == 0) return true;
    if (mode != LOCK_SH || tries == kPartLockTries) return false;
    ::usleep(kPartLockWaitUs);
  }
}

/// The list's own lock, `.prt-list-lock`, held while a part reads, adds to and writes the list
/// (and moves its outputs into place): waited for, as the parts' list updates are short.
class ListLock {
 public:
  explicit ListLock(const std::string& dir) : path_(dir + "/" + OutputFolder::kListLockName) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) throw Error(dir + ": cannot use the output folder (" + WriteProblem(path_, errno) + ")");
    if (::flock(fd_, LOCK_EX) != 0) {
      const int error = errno;
      ::close(fd_);
      throw Error(path_ + ": cannot lock (" + std::string(std::strerror(error)) + ")");
    }
  }
  ~ListLock() { ::close(fd_); }
  ListLock(const ListLock&) = delete;
  ListLock& operator=(const ListLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace

OutputFolder::OutputFolder(std::string dir, OutputPlan plan) : dir_(std::move(dir)), plan_(std::move(plan)) {
  created_.Create(dir_);
  const std::string lock = dir_ + "/" + kLockName;
  // The lock is the file that has the name now: a run that opened a lock file its holder then
  // unlinked (at its end) holds a lock on nothing and tries again with the fresh one.
  for (;;) {
    lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (lock_fd_ < 0 && errno == ELOOP)
      throw Error(lock + ": is a symbolic link (expected prt's lock file, or none: remove it)");
    if (lock_fd_ < 0) throw Error(dir_ + ": cannot use the output folder (" + WriteProblem(lock, errno) + ")");
    if (!TryLock(lock_fd_, plan_.part ? LOCK_SH : LOCK_EX)) {
      char holder[32] = {0};
      const ssize_t n = ::pread(lock_fd_, holder, sizeof holder - 1, 0);
      ::close(lock_fd_);
      lock_fd_ = -1;
      throw FolderBusy(dir_ + ": in use by another prt run" + (n > 0 ? " (process " + std::string(holder) + ")" : "") +
                       (plan_.part ? " that writes the whole folder" : "") +
                       " (expected one run per output folder, or runs that each write a part of it, such as "
                       "--frame-range: wait for it to finish, or choose another --out; exit code 75 means try again)");
    }
    struct stat held {}, named {};
    if (::fstat(lock_fd_, &held) == 0 && ::stat(lock.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino)
      break;
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
  // A part shares the lock file: the last part to end removes it (Abandon), never a signal.
  if (!plan_.part) {
    lock_cleanup_ = CleanupOnSignal(lock, CleanupKind::kFile);
    const std::string pid = std::to_string(::getpid());
    if (::ftruncate(lock_fd_, 0) == 0 && ::pwrite(lock_fd_, pid.data(), pid.size(), 0) < 0) {
      // The holder's pid only improves the message of a refused run; nothing depends on it.
    }
  }
  try {
    earlier_ = ReadList(dir_ + "/" + kListName);
    Plan(plan_.names);
    std::error_code ec;
    if (plan_.part) {
      // A staging folder of its own, beside the other parts' (on a shared file system too).
      std::string name = dir_ + "/" + kStagingName + ".XXXXXX";
      if (::mkdtemp(name.data()) == nullptr)
        throw Error(dir_ + ": cannot use the output folder (" + WriteProblem(name, errno) + ")");
      staging_ = name;
      staging_cleanup_ = CleanupOnSignal(staging_, CleanupKind::kTree);
    } else {
      // A staging folder here is a killed run's (this run holds the lock): its files never
      // counted. So are the parts' staging folders: no part holds the folder now.
      staging_ = dir_ + "/" + kStagingName;
      staging_cleanup_ = CleanupOnSignal(staging_, CleanupKind::kTree);
      for (const auto& entry : fs::directory_iterator(dir_, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(std::string(kStagingName) + ".", 0) == 0) fs::remove_all(entry.path(), ec);
      }
      fs::remove_all(staging_, ec);
      if (!fs::create_directory(staging_, ec) && !fs::is_directory(staging_))
        throw Error(dir_ + ": cannot use the output folder (" +
                    WriteProblem(staging_ + "/x", ec.value() ? ec.value() : EIO) + ")");
    }
  } catch (...) {
    Abandon();
    throw;
  }
}

OutputFolder::~OutputFolder() { Abandon(); }

void OutputFolder::Abandon() {
  if (lock_fd_ < 0) return;
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);  // a failed run's staged outputs, never moved into place
  staging_cleanup_.Release();
  if (!finished_) {
    // Files written in place are valid on their own: listed, so that the next run knows them.
    try {
      std::optional<ListLock> list_lock;
      if (plan_.part) list_lock.emplace(dir_);
      std::map<std::string, std::string> all = plan_.part ? ReadList(dir_ + "/" + kListName) : earlier_;
      bool added = false;
      for (const std::string& name : Written()) {
        if (all.count(name) && all.at(name) == plan_.command) continue;
        all[name] = plan_.command;
        added = true;
      }
      if (added) WriteList(all);
    } catch (const std::exception&) {
      // The run is failing already; its error is the one to report.
    }
  }
  if (plan_.part) {
    // The last part to end removes the lock files: holding the list's lock, it takes the
    // folder's alone, which it gets only when no other run holds it.
    try {
      const ListLock list_lock(dir_);
      if (::flock(lock_fd_, LOCK_EX | LOCK_NB) == 0) {
        ::unlink((dir_ + "/" + kLockName).c_str());
        ::unlink((dir_ + "/" + kListLockName).c_str());
      }
    } catch (const std::exception&) {
      // The lock files stay: the next run uses them.
    }
  } else {
    // Unlinked before it is released: a run that opened the old file meanwhile finds it locked
    // and is refused, or, locking it once released, sees that it is no longer the folder's lock
    // and takes a fresh one; one that starts later creates a fresh lock. The parts' list lock
    // is no part's now.
    ::unlink((dir_ + "/" + kListLockName).c_str());
    ::unlink((dir_ + "/" + kLockName).c_str());
  }
  lock_cleanup_.Release();
  ::close(lock_fd_);
  lock_fd_ = -1;
  // created_ removes the folders this run made, if it left them empty (a failed run).
}

bool OutputFolder::IsForeignLocked(const std::string& name) const {
  // A staged output is not in the folder until it is moved: what is there under its name is
  // still foreign.
  std::error_code ec;
  if (earlier_.count(name) || before_.count(name) || moved_.count(name)) return false;
  return fs::exists(fs::symlink_status(fs::path(dir_) / name, ec));
}

bool OutputFolder::IsForeign(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  return IsForeignLocked(name);
}

void OutputFolder::CheckLocked(const std::string& name) {
  if (replaced_.count(name) || !IsForeignLocked(name)) return;
  const std::string path = dir_ + "/" + name;
  const std::string orig = name + kOrigSuffix;
  if (!plan_.replace)
    throw Error(path + ": exists and prt did not write it: this run would replace it (expected another --out, or "
                "--replace to replace it and keep the old file as " + orig + ")");
  std::error_code ec;
  if (fs::exists(fs::symlink_status(fs::path(dir_) / orig, ec)))
    throw Error(path + ": --replace would keep it as " + orig + ", which exists already (expected " + orig +
                " moved away first)");
  if (fs::is_directory(fs::symlink_status(path, ec)))
    throw Error(path + ": is a folder, and an output of this run has its name (expected another --out)");
  replaced_.insert(name);
}

void OutputFolder::Plan(const std::vector<std::string>& names) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const std::string& name : names) CheckLocked(name);
}

std::string OutputFolder::Output(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  CheckLocked(name);
  staged_.insert(name);
  return staging_ + "/" + name;
}

std::string OutputFolder::OutputInPlace(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  before_.emplace(name, FileSignature(dir_ + "/" + name));
  return dir_ + "/" + name;
}

std::set<std::string> OutputFolder::Written() const {
  std::set<std::string> written = moved_;
  for (const auto& [name, before] : before_) {
    const std::string now = FileSignature(dir_ + "/" + name);
    if (!now.empty() && now != before) written.insert(name);
  }
  return written;
}

bool OutputFolder::Wrote(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  return staged_.count(name) != 0 || before_.count(name) != 0;
}

fs::path ResolvedPath(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return p.lexically_normal();
}

bool SameFile(const std::string& a, const std::string& b) {
  if (ResolvedPath(a) == ResolvedPath(b)) return true;
  std::error_code ec;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

bool LiesIn(const std::string& path, const std::string& dir) {
  const auto folder_of = [](const std::string& file) {
    return ResolvedPath((fs::path(file).parent_path() / "x").string()).parent_path();
  };
  return folder_of(path) == folder_of(dir + "/x");
}

void OutputFolder::KeepInput(const std::string& path) {
  std::lock_guard<std::mutex> lock(mutex_);
  inputs_.push_back(ResolvedPath(path).string());
}

bool OutputFolder::IsInput(const std::string& name) const {
  const std::string p = ResolvedPath(dir_ + "/" + name).string();
  for (const std::string& input : inputs_)
    if (p == input || (p.size() > input.size() && p.compare(0, input.size(), input) == 0 && p[input.size()] == '/'))
      return true;
  return false;
}

OutputFolder::Finished OutputFolder::Finish() {
  // Not cut in half by a signal: its cleanup waits until the outputs are in place and listed.
  const SignalCleanupHold hold;
  std::lock_guard<std::mutex> lock(mutex_);
  // A part: the other parts' outputs listed since this run began are theirs, not foreign.
  std::optional<ListLock> list_lock;
  if (plan_.part) {
    list_lock.emplace(dir_);
    earlier_ = ReadList(dir_ + "/" + kListName);
  }
  Finished result;
  std::error_code ec;
  // Every staged output checked before any is moved: a file that appeared during the run and
  // that prt did not write stops the run here, with nothing replaced.
  std::vector<std::string> to_move;
  for (const auto& name : staged_) {
    if (!fs::exists(fs::symlink_status(staging_ + "/" + name, ec))) continue;  // named, then never written
    CheckLocked(name);
    to_move.push_back(name);
  }
  // This run's outputs into place. A file prt did not write that one replaces (--replace) first
  // becomes NAME.orig, never over an existing file, and comes back if the move fails. Each
  // output moved is listed from then on, even if a later one fails (the destructor lists it).
  for (const auto& name : to_move) {
    const std::string from = staging_ + "/" + name, to = dir_ + "/" + name, orig = to + kOrigSuffix;
    const bool keep = replaced_.count(name) && IsForeignLocked(name);
    if (keep && ::renameat2(AT_FDCWD, to.c_str(), AT_FDCWD, orig.c_str(), RENAME_NOREPLACE) != 0)
      throw Error(to + ": cannot keep it as " + name + kOrigSuffix + " (" +
                  (errno == EEXIST ? std::string("which exists already") : WriteProblem(orig, errno)) + ")");
    if (std::rename(from.c_str(), to.c_str()) != 0) {
      const int error = errno;
      if (keep) std::rename(orig.c_str(), to.c_str());
      throw Error(to + ": cannot write (" + WriteProblem(to, error) + ")");
    }
    if (keep) result.kept_as_orig.push_back(name + kOrigSuffix);
    moved_.insert(name);
  }
  // The new list: this run's outputs, the other commands' files, and a file this run named but
  // did not rewrite (a reused cache) under the command that wrote it. This command's earlier
  // outputs that it did not write again are removed, but only once the list no longer names them.
  const std::set<std::string> written = Written();
  std::map<std::string, std::string> list;
  std::vector<std::string> leftovers;
  for (const auto& [name, command] : earlier_) {
    if (written.count(name) || !fs::exists(fs::symlink_status(fs::path(dir_) / name, ec))) continue;  // listed below, or gone
    if (before_.count(name) || command != plan_.command || plan_.part) {
      // Not rewritten, another command's (an unknown command's) deliverable, or the other parts': kept.
      list[name] = command;
      continue;
    }
    if (IsInput(name)) continue;  // read by this run: kept, and no longer listed as prt's
    leftovers.push_back(name);
  }
  for (const auto& name : written) list[name] = plan_.command;
  WriteList(list);
  finished_ = true;
  created_.Keep();
  for (const auto& name : leftovers) {
    const fs::path p = fs::path(dir_) / name;
    if (fs::is_regular_file(fs::symlink_status(p, ec)) && fs::remove(p, ec)) result.removed.push_back(name);
  }
  // Temporary files of prt runs that were killed mid-write: removed once their process is gone.
  // This run holds the folder, so no live run of prt can be writing them here (a part does not).
  if (!plan_.part)
    for (const std::string& name : AtomicFile::RemoveStaleIn(dir_)) result.removed.push_back(name);
  return result;
}

void OutputFolder::WriteList(const std::map<std::string, std::string>& entries) const {
  std::string text =
      "# files prt wrote in this folder: the command that wrote it, a tab, the file name. A run removes what its\n"
      "# command wrote earlier and did not write again; files of other commands, and files not listed, stay.\n";
  for (const auto& [name, command] : entries) text += command + "\t" + name + "\n";
  WriteFileAtomic(dir_ + "/" + kListName, text);
}

}  // namespace prt
