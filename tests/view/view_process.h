#pragma once
/// \file
/// `prt view` as the tests run it: a child process serving the small scene, its address read
/// from its stdout; the tests talk to it with tests/view/http_client.h.

#include <string>
#include <vector>

#include "tests/view/http_client.h"

namespace prt::test {

class ViewProcess {
 public:
  /// Starts `prt view ARGS...` (stderr into `log`, stdout read for the address line); waits for
  /// the address, then for its scene to be ready (/state no longer "starting"), for up to five
  /// minutes in all. FAILs the test when either does not come.
  ViewProcess(const std::vector<std::string>& args, const std::string& log);
  /// Starts `prt view ARGS...` and waits for its address only: its scene may still be starting.
  static ViewProcess Starting(const std::vector<std::string>& args, const std::string& log);
  /// Runs `command` with bash in folder `dir` instead (a README command, as a user types it).
  static ViewProcess Shell(const std::string& command, const std::string& dir, const std::string& log);
  ~ViewProcess();  ///< SIGKILL if still running
  ViewProcess(const ViewProcess&) = delete;
  ViewProcess& operator=(const ViewProcess&) = delete;
  ViewProcess(ViewProcess&& other) noexcept
      : pid_(other.pid_), port_(other.port_), address_(std::move(other.address_)) {
    other.pid_ = -1;
  }

  int port() const { return port_; }
  int pid() const { return pid_; }
  const std::string& address() const { return address_; }
  /// Sends `signal` and waits: the raw wait status.
  int Stop(int signal);

 private:
  ViewProcess() = default;
  void Start(std::vector<std::string> argv, const std::string& log, const std::string& dir, bool wait_ready = true);

  int pid_ = -1;
  int port_ = 0;
  std::string address_;
};

/// Waits (up to five minutes) until /state says the transport `key` ("basis mode") is ready;
/// FAILs when it failed or never is.
void WaitReady(int port, const std::string& key);

/// The small scene's view arguments the tests share: WriteSmallScene in `dir`, lmax 3, 256
/// directions a vertex, 160x120 frames, one thread per process kept free.
std::vector<std::string> SmallViewArgs(const std::string& dir);

}  // namespace prt::test
