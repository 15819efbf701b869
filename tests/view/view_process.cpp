#include "tests/view/view_process.h"

#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <doctest/doctest.h>

#include "tests/test_process.h"

namespace prt::test {

ViewProcess::ViewProcess(const std::vector<std::string>& args, const std::string& log) {
  std::vector<std::string> all = {PrtBinary(), "view"};
  all.insert(all.end(), args.begin(), args.end());
  Start(all, log, "");
}

ViewProcess ViewProcess::Starting(const std::vector<std::string>& args, const std::string& log) {
  ViewProcess p;
  std::vector<std::string> all = {PrtBinary(), "view"};
  all.insert(all.end(), args.begin(), args.end());
  p.Start(all, log, "", false);
  return p;
}

ViewProcess ViewProcess::Shell(const std::string& command, const std::string& dir, const std::string& log) {
  ViewProcess p;
  p.Start({"/bin/bash", "-c", "exec " + command}, log, dir);
  return p;
}

void ViewProcess::Start(std::vector<std::string> all, const std::string& log, const std::string& dir, bool wait_ready) {
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  int out[2];
  REQUIRE(::pipe(out) == 0);
  const std::string binary = all[0];
  pid_ = ::fork();
  if (pid_ == 0) {
    ::dup2(out[1], 1);
    const int err = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err >= 0) ::dup2(err, 2);
    ::close(out[0]);
    if (!dir.empty() && ::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(out[1]);
  // The address line: read byte by byte until the newline, for up to five minutes.
  std::string line;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{out[0], POLLIN, 0};
    if (::poll(&p, 1, 1000) <= 0) continue;
    char c = 0;
    if (::read(out[0], &c, 1) != 1) break;
    if (c == '\n') break;
    line += c;
  }
  ::close(out[0]);
  address_ = line;
  // http://HOST:PORT/ (HOST 127.0.0.1 unless --bind names another).
  const std::size_t colon = line.rfind(':');
  if (line.rfind("http://", 0) == 0 && colon != std::string::npos && line.back() == '/')
    port_ = std::atoi(line.c_str() + colon + 1);
  if (port_ <= 0) {
    int status = 0;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    FAIL("prt view printed no address (stdout '" << line << "'; its stderr is in " << log << ")");
  }
  FetchToken(port_);
  // It serves from then on, and its scene once the first transport is computed: /state says
  // "starting" until then (view/late_backend.h). The tests start from a ready scene.
  while (wait_ready && std::chrono::steady_clock::now() < deadline) {
    const HttpReply state = Request(port_, "/state");
    if (state.status == 200 && state.body.find("\"starting\":true") == std::string::npos) return;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      FAIL("prt view ended before its scene was ready (its stderr is in " << log << ")");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (wait_ready) FAIL("prt view's scene was not ready within five minutes (its stderr is in " << log << ")");
}

ViewProcess::~ViewProcess() {
  if (pid_ > 0) Stop(SIGKILL);
}

int ViewProcess::Stop(int signal) {
  int status = 0;
  ::kill(pid_, signal);
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
  return status;
}

void WaitReady(int port, const std::string& key) {
  for (int i = 0; i < 3000; ++i) {
    const HttpReply state = Request(port, "/state");
    REQUIRE(state.status == 200);
    if (state.body.find("{\"key\":\"" + key + "\",\"state\":\"ready\"") != std::string::npos) return;
    REQUIRE(state.body.find("{\"key\":\"" + key + "\",\"state\":\"failed\"") == std::string::npos);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  FAIL("transport " << key << " never ready");
}

std::vector<std::string> SmallViewArgs(const std::string& dir) {
  return {"--mesh", WriteSmallScene(dir), "--lmax", "3", "--samples", "256", "--size", "160x120", "--port", "0"};
}

}  // namespace prt::test
