#include "core/child_process.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"  // WriteAll
#include "core/error.h"

extern char** environ;

namespace prt {
namespace {

/// argv as the NULL-terminated array posix_spawn takes (pointing into `argv`).
std::vector<char*> ArgvPointers(const std::vector<std::string>& argv) {
  std::vector<char*> p;
  for (const std::string& a : argv) p.push_back(const_cast<char*>(a.c_str()));
  p.push_back(nullptr);
  return p;
}

/// waitpid's status as an exit code, 128 + signal for a signal.
int ExitCode(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

/// The child starts with the signal mask the process had before prt blocked SIGINT, SIGTERM
/// and SIGHUP for its cleanup thread (core/signal_cleanup.h), so Ctrl-C reaches it too.
class SpawnAttributes {
 public:
  SpawnAttributes() {
    posix_spawnattr_init(&attr_);
    sigset_t mask;
    ChildSignalMask(&mask);
    posix_spawnattr_setsigmask(&attr_, &mask);
    posix_spawnattr_setflags(&attr_, POSIX_SPAWN_SETSIGMASK);
  }
  ~SpawnAttributes() { posix_spawnattr_destroy(&attr_); }
  const posix_spawnattr_t* get() const { return &attr_; }

 private:
  posix_spawnattr_t attr_;
};

int Reap(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return ExitCode(status);
}

/// SIGPIPE blocked on this thread for the object's life; a SIGPIPE raised meanwhile by a write
/// to a closed pipe is discarded before the old mask returns.
class SigpipeBlocked {
 public:
  SigpipeBlocked() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
  }
  ~SigpipeBlocked() {
    if (!sigismember(&old_, SIGPIPE)) {
      const timespec zero{0, 0};
      while (sigtimedwait(&pipe_, nullptr, &zero) > 0) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }

 private:
  sigset_t pipe_, old_;
};

}  // namespace

std::optional<std::string> FindProgram(const std::string& name) {
  if (name.empty()) return std::nullopt;
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    const std::string candidate = (folder.empty() ? "." : folder) + "/" + name;
    struct stat st {};
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return std::nullopt;
}

ProgramResult RunProgram(const std::vector<std::string>& argv) {
  ProgramResult result;
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) return result;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  auto args = ArgvPointers(argv);
  SpawnAttributes attributes;
  const int failed = posix_spawn(&pid, argv[0].c_str(), &actions, attributes.get(), args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  if (failed == 0) {
    char buf[4096];
    ssize_t n;
    while ((n = ::read(out[0], buf, sizeof buf)) != 0) {
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) break;
      result.out.append(buf, static_cast<std::size_t>(n));
    }
  }
  ::close(out[0]);
  if (failed == 0) result.status = Reap(pid);
  return result;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::string& log) {
  int in[2];
  if (::pipe2(in, O_CLOEXEC) != 0) throw Error(argv[0] + ": cannot start (" + std::strerror(errno) + ")");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  auto args = ArgvPointers(argv);
  SpawnAttributes attributes;
  // Started and registered in one step: a signal kills and reaps the child before the cleanup
  // removes the file it writes.
  int failed = 0;
  cleanup_ = CleanupOnSignal::Spawn([&] {
    failed = posix_spawn(&pid_, argv[0].c_str(), &actions, attributes.get(), args.data(), environ);
    return failed == 0 ? pid_ : pid_t(-1);
  });
  posix_spawn_file_actions_destroy(&actions);
  ::close(in[0]);
  if (failed != 0) {
    ::close(in[1]);
    pid_ = -1;
    throw Error(argv[0] + ": cannot start (" + std::strerror(failed) + ")");
  }
  input_ = in[1];
}

namespace {

/// Waits for the child to exit without reaping it, withdraws it from the signal cleanup, then
/// reaps it: its pid is never free for another process while the cleanup might still kill it.
int ReapRegistered(pid_t pid, CleanupOnSignal& cleanup) {
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) < 0)
    if (errno != EINTR) break;
  cleanup.Release();
  return Reap(pid);
}

}  // namespace

ChildProcess::~ChildProcess() {
  if (pid_ < 0) return;
  ::kill(pid_, SIGKILL);
  if (input_ >= 0) ::close(input_);
  ReapRegistered(pid_, cleanup_);
}

bool ChildProcess::Write(std::string_view bytes) {
  if (input_ < 0) return false;
  SigpipeBlocked blocked;
  return WriteAll(input_, bytes) == 0;
}

int ChildProcess::Wait() {
  if (pid_ < 0) return -1;
  if (input_ >= 0) ::close(input_);
  input_ = -1;
  const int code = ReapRegistered(pid_, cleanup_);
  pid_ = -1;
  return code;
}

std::string LastLine(const std::string& path, std::size_t limit) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) last = line;
  }
  if (last.size() > limit) last = last.substr(0, limit) + "...";
  return last;
}

}  // namespace prt
