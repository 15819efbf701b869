#include "core/atomic_file.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <unistd.h>

#include "core/error.h"
#include "core/text.h"

namespace prt {
namespace fs = std::filesystem;

namespace {

/// Where this process's temporary numbers start: random, so that two processes of one pid on
/// two machines writing one shared folder (a farm's tasks, core/output_folder.h's parts) never
/// share a temporary name. Only the name depends on it, never a file's bytes.
std::uint64_t FirstTemporaryNumber() {
  std::uint32_t bits = 0;
  if (::getrandom(&bits, sizeof bits, 0) != sizeof bits)
    bits = static_cast<std::uint32_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  return std::uint64_t(bits) << 16;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  static std::atomic<std::uint64_t> counter{FirstTemporaryNumber()};
  const fs::path p(path_);
  const std::string name = "." + p.filename().string() + kTemporaryTag + std::to_string(::getpid()) + "_" +
                           std::to_string(counter++);
  temp_ = (p.parent_path() / name).string();
  cleanup_ = CleanupOnSignal(temp_, CleanupKind::kFile);  // before anything creates the file
}

namespace {

/// What follows kTemporaryTag in a temporary name: `<pid>_<n>`, the pid of 1 to 9 digits, n of at
/// least one; the pid into `pid`.
bool IsTemporarySuffix(const std::string& suffix, long* pid) {
  const std::size_t bar = suffix.find('_');
  if (bar == std::string::npos || bar > 9) return false;
  const std::string digits = suffix.substr(0, bar);
  if (!AllDigits(digits) || !AllDigits(suffix.substr(bar + 1))) return false;
  if (pid) *pid = std::stol(digits);
  return true;
}

}  // namespace

bool AtomicFile::IsTemporaryName(const std::string& name, long* pid) {
  const std::size_t tag = name.rfind(kTemporaryTag);
  return name.size() > 1 && name[0] == '.' && tag != std::string::npos && tag > 1 &&
         IsTemporarySuffix(name.substr(tag + std::string(kTemporaryTag).size()), pid);
}

bool AtomicFile::ProcessGone(long pid) {
  return pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

std::vector<std::string> AtomicFile::RemoveStaleIn(const std::string& folder, const std::string& name) {
  const std::string prefix = name.empty() ? "" : "." + name + kTemporaryTag;
  std::vector<std::string> removed;
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder.empty() ? "." : folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    const std::string file = it->path().filename().string();
    long maker = 0;
    const bool stale = name.empty() ? IsTemporaryName(file, &maker)
                                    : file.compare(0, prefix.size(), prefix) == 0 &&
                                          IsTemporarySuffix(file.substr(prefix.size()), &maker);
    std::error_code removing;
    if (stale && ProcessGone(maker) && fs::remove(it->path(), removing)) removed.push_back(file);
  }
  return removed;
}

void AtomicFile::RemoveStale(const std::string& path) {
  const fs::path p(path);
  RemoveStaleIn(p.parent_path().string(), p.filename().string());
}

void AtomicFile::Write(const std::vector<std::string_view>& parts) {
  const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw Error(path_ + ": cannot write (" + WriteProblem(path_, errno) + ")");
  int error = 0;
  for (std::size_t p = 0; p < parts.size() && error == 0; ++p) error = WriteAll(fd, parts[p]);
  // close() reports delayed write errors (full disks on network file systems among them).
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) throw Error(path_ + ": cannot write (" + WriteProblem(path_, error) + ")");
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::Commit() {
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) throw Error(path_ + ": cannot write (" + WriteProblem(path_, errno) + ")");
  committed_ = true;
  cleanup_.Release();
}

std::string WriteProblem(const std::string& path, int error) {
  std::string folder = fs::path(path).parent_path().string();
  if (folder.empty()) folder = ".";
  switch (error) {
    case ENOENT:
    case ENOTDIR: {
      // Some file systems (/proc, /sys) answer ENOENT for a new name in a folder that exists.
      std::error_code ec;
      if (fs::is_directory(folder, ec)) return "folder '" + folder + "' does not accept new files";
      if (fs::exists(folder, ec)) return "'" + folder + "' is a file, not a folder";
      return "folder '" + folder + "' does not exist";
    }
    case EACCES:
    case EPERM: return "folder '" + folder + "' is not writable: permission denied";
    case EROFS: return "folder '" + folder + "' is on a read-only file system";
    case ENOSPC:
    case EDQUOT: return "disk full: no space left on the device of '" + folder + "'";
    case EISDIR: return "is a directory (expected a file name)";
    default: return std::strerror(error);
  }
}

int WriteAll(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

void WriteFileAtomic(const std::string& path, const std::string& bytes) {
  WriteFileAtomic(path, std::vector<std::string_view>{bytes});
}

void WriteFileAtomic(const std::string& path, const std::vector<std::string_view>& parts) {
  AtomicFile file(path);
  file.Write(parts);
  file.Commit();
}

std::string ReadFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path + ": no such file");
  if (fs::is_directory(path, ec)) throw Error(path + ": is a directory (expected a file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw Error(path + ": read failed");
  return ss.str();
}

bool FileStartsWith(const std::string& path, const char* magic, std::size_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string head(size, '\0');
  return in.read(head.data(), static_cast<std::streamsize>(size)) && std::memcmp(head.data(), magic, size) == 0;
}

}  // namespace prt
