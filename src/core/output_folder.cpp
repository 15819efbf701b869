#include "core/output_folder.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <csignal>
#include <sys/file.h>
#include <unistd.h>

#include "core/atomic_file.h"
#include "core/error.h"

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

void CreateParentFolder(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty()) CreateFolder(parent.string());
}

OutputFolder::OutputFolder(std::string dir) : dir_(std::move(dir)) {
  CreateFolder(dir_);
  const std::string lock = dir_ + "/" + kLockName;
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) throw Error(dir_ + ": cannot use the output folder (" + WriteProblem(lock, errno) + ")");
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    char holder[32] = {0};
    const ssize_t n = ::pread(lock_fd_, holder, sizeof holder - 1, 0);
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw Error(dir_ + ": in use by another prt run" + (n > 0 ? " (process " + std::string(holder) + ")" : "") +
                " (expected one run per output folder: wait for it to finish, or choose another --out)");
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(lock_fd_, 0) == 0 && ::pwrite(lock_fd_, pid.data(), pid.size(), 0) < 0) {
    // The holder's pid only improves the message of a refused run; nothing depends on it.
  }
  std::error_code ec;
  if (fs::exists(dir_ + "/" + kListName, ec)) {
    std::istringstream list(ReadFile(dir_ + "/" + kListName));
    for (std::string line; std::getline(list, line);)
      if (!line.empty() && line[0] != '#' && line.find('/') == std::string::npos) earlier_.insert(line);
  }
  // A staging folder here is a killed run's (this run holds the lock): its files never counted.
  fs::remove_all(staging(), ec);
  if (!fs::create_directory(staging(), ec) && !fs::is_directory(staging()))
    throw Error(dir_ + ": cannot use the output folder (" +
                WriteProblem(staging() + "/x", ec.value() ? ec.value() : EIO) + ")");
}

OutputFolder::~OutputFolder() {
  if (lock_fd_ < 0) return;
  std::error_code ec;
  fs::remove_all(staging(), ec);  // a failed run's staged outputs, never moved into place
  if (!finished_) {
    std::set<std::string> all = earlier_;
    all.insert(in_place_.begin(), in_place_.end());
    try {
      WriteList(all);
    } catch (const std::exception&) {
      // The run is failing already; its error is the one to report.
    }
  }
  // Unlinked before it is released: a run that opened the old file meanwhile finds it locked
  // and is refused; one that starts later creates a fresh lock.
  ::unlink((dir_ + "/" + kLockName).c_str());
  ::close(lock_fd_);
}

std::string OutputFolder::staging() const { return dir_ + "/" + kStagingName; }

std::string OutputFolder::Output(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  staged_.insert(name);
  return staging() + "/" + name;
}

std::string OutputFolder::OutputInPlace(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  in_place_.insert(name);
  return dir_ + "/" + name;
}

bool OutputFolder::Wrote(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  return staged_.count(name) != 0 || in_place_.count(name) != 0;
}

fs::path ResolvedPath(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return p.lexically_normal();
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

std::vector<std::string> OutputFolder::Finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  // This run's outputs into place. Each one moved is listed from then on, even if a later one
  // fails (the destructor writes the list).
  std::error_code ec;
  for (const auto& name : staged_) {
    const std::string from = staging() + "/" + name, to = dir_ + "/" + name;
    if (!fs::exists(fs::symlink_status(from, ec))) continue;  // named, then never written
    if (std::rename(from.c_str(), to.c_str()) != 0) throw Error(to + ": cannot write (" + WriteProblem(to, errno) + ")");
    in_place_.insert(name);
  }
  std::vector<std::string> removed;
  for (const auto& name : earlier_) {
    if (in_place_.count(name) || IsInput(name)) continue;
    const fs::path p = fs::path(dir_) / name;
    if (fs::is_regular_file(fs::symlink_status(p, ec)) && fs::remove(p, ec)) removed.push_back(name);
  }
  // Temporary files of prt runs that were killed mid-write (core/atomic_file.h names them
  // `.<name>.tmp<pid>_<n>`): removed once their process is gone. This run holds the folder, so
  // no live run of prt can be writing them here.
  for (const auto& entry : fs::directory_iterator(dir_, ec)) {
    long maker = 0;
    const std::string name = entry.path().filename().string();
    if (!AtomicFile::IsTemporaryName(name, &maker)) continue;
    const auto pid = static_cast<pid_t>(maker);
    const bool gone = pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH;
    if (gone && fs::remove(entry.path(), ec)) removed.push_back(name);
  }
  WriteList(in_place_);
  finished_ = true;
  return removed;
}

void OutputFolder::WriteList(const std::set<std::string>& names) const {
  std::string text = "# files the last prt runs wrote in this folder; the next run removes those it does not rewrite\n";
  for (const auto& n : names) text += n + "\n";
  WriteFileAtomic(dir_ + "/" + kListName, text);
}

}  // namespace prt
