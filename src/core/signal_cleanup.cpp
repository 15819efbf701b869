#include "core/signal_cleanup.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace prt {
namespace {

struct Entry {
  std::string path;
  CleanupKind kind = CleanupKind::kFile;
  pid_t child = -1;
};

struct Registry {
  std::recursive_mutex mutex;  ///< recursive: a SignalCleanupHold's thread registers meanwhile
  std::map<std::uint64_t, Entry> entries;  ///< by registration order: ids only grow
  std::uint64_t next = 1;
};

Registry& TheRegistry() {
  static Registry* registry = new Registry;  // never destroyed: the watcher may outlive main's statics
  return *registry;
}

/// How long the watcher waits before its second pass over the files.
constexpr std::chrono::milliseconds kSecondPassDelay{50};

sigset_t& OriginalMask() {
  static sigset_t mask;
  return mask;
}

sigset_t Watched() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
}

/// Kills and reaps the children (`children`), then removes the files and folders, newest first
/// (a folder is registered before what is made in it). Called with the registry locked, never
/// unlocked.
void CleanUp(const std::map<std::uint64_t, Entry>& entries, bool children) {
  for (const auto& [id, e] : entries) {
    if (e.child <= 0 || !children) continue;
    ::kill(e.child, SIGKILL);
    int status = 0;
    while (::waitpid(e.child, &status, 0) < 0 && errno == EINTR) {
    }
  }
  std::error_code ec;
  for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
    const Entry& e = it->second;
    if (e.child > 0) continue;
    switch (e.kind) {
      case CleanupKind::kFile: ::unlink(e.path.c_str()); break;
      case CleanupKind::kTree: std::filesystem::remove_all(e.path, ec); break;
      case CleanupKind::kEmptyFolder: ::rmdir(e.path.c_str()); break;
    }
  }
}

void Watch(sigset_t set) {
  int sig = 0;
  while (sigwait(&set, &sig) != 0) {
  }
  Registry& r = TheRegistry();
  r.mutex.lock();  // held until the process ends: nothing registers, so nothing new is created
  CleanUp(r.entries, true);
  // A thread that registered a name just before may create the file just after the first pass:
  // a second pass, once such a thread has had time to (creating a file takes microseconds).
  std::this_thread::sleep_for(kSecondPassDelay);
  CleanUp(r.entries, false);
  // End by the same signal, with its default action.
  std::signal(sig, SIG_DFL);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, sig);
  pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
  ::raise(sig);
  ::_exit(128 + sig);  // not reached: the default action of all three ends the process
}

/// Takes the registry's lock, makes the entry (a child is started then), registers it unless
/// it is a child that did not start, and returns its id (0 for none).
std::uint64_t Add(const std::function<Entry()>& make) {
  Registry& r = TheRegistry();
  std::lock_guard<std::recursive_mutex> lock(r.mutex);
  Entry e = make();
  if (e.path.empty() && e.child <= 0) return 0;
  const std::uint64_t id = r.next++;
  r.entries.emplace(id, std::move(e));
  return id;
}

}  // namespace

void InstallSignalCleanup() {
  const sigset_t set = Watched();
  pthread_sigmask(SIG_BLOCK, &set, &OriginalMask());
  std::thread(Watch, set).detach();
}

void ChildSignalMask(void* out) { *static_cast<sigset_t*>(out) = OriginalMask(); }

CleanupOnSignal::CleanupOnSignal(std::string path, CleanupKind kind)
    : id_(Add([&] { return Entry{std::move(path), kind, -1}; })) {}

CleanupOnSignal CleanupOnSignal::Spawn(const std::function<pid_t()>& spawn) {
  CleanupOnSignal c;
  c.id_ = Add([&] { return Entry{"", CleanupKind::kFile, spawn()}; });
  return c;
}

CleanupOnSignal& CleanupOnSignal::operator=(CleanupOnSignal&& other) noexcept {
  if (this != &other) {
    Release();
    id_ = other.id_;
    other.id_ = 0;
  }
  return *this;
}

void CleanupOnSignal::Release() {
  if (id_ == 0) return;
  Registry& r = TheRegistry();
  std::lock_guard<std::recursive_mutex> lock(r.mutex);
  r.entries.erase(id_);
  id_ = 0;
}

SignalCleanupHold::SignalCleanupHold() { TheRegistry().mutex.lock(); }
SignalCleanupHold::~SignalCleanupHold() { TheRegistry().mutex.unlock(); }

}  // namespace prt
