#include "tests/test_process.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/atomic_file.h"

namespace prt::test {
namespace fs = std::filesystem;

std::string PrtBinary() {
  const char* binary = std::getenv("PRT_BINARY");
  return binary && *binary ? binary : PRT_BINARY_PATH;
}

int StartLongRender(const std::string& out, const std::string& size, const std::vector<std::string>& extra) {
  // Everything the child needs is made before fork: after it, the child (of a process with
  // threads) may only make async-signal-safe calls.
  const std::string binary = PrtBinary(), mesh = Fixture("obj/tetra_no_normals.obj");
  std::vector<std::string> args = {binary, "render", "--mesh", mesh, "--env", "furnace", "--transport", "unshadowed",
                                   "--frames", "9999", "--size", size, "--threads", "1", "--quiet", "--out", out};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, 2);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

int SignalWhenFileAppears(int pid, const std::string& path, int sig) {
  bool appeared = false;
  for (int tries = 0; tries < 60000 && !appeared; ++tries) {
    appeared = fs::exists(path);
    int status = 0;
    if (!appeared && ::waitpid(pid, &status, WNOHANG) == pid) return -1;  // exited (and reaped)
    if (!appeared) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(pid, sig);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return appeared ? status : -1;
}

bool KillWhenFileAppears(int pid, const std::string& path) {
  const int status = SignalWhenFileAppears(pid, path, SIGKILL);
  return status != -1 && WIFSIGNALED(status);
}

std::string QuickRender(const std::string& out, int frames, const std::string& size) {
  return "render " + QuickScene() + " --size " + size + " --frames " + std::to_string(frames) + " --out " + Q(out);
}

RunResult RunPrt(const std::string& arguments) { return RunCommand(ShellQuote(PrtBinary()) + " " + arguments); }

RunResult RunCommand(const std::string& command) {
  const std::string dir = ScratchDir("run");
  const std::string cmd = command + " >'" + dir + "/out' 2>'" + dir + "/err' </dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = ReadFile(dir + "/out");
  r.err = ReadFile(dir + "/err");
  fs::remove_all(dir);
  return r;
}

}  // namespace prt::test
