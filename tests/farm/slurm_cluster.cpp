#include "tests/farm/slurm_cluster.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "tests/test_process.h"

namespace prt::test {
namespace {

namespace fs = std::filesystem;

/// A TCP port free on this machine now (bound to port 0, read back, released).
int FreePort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_ANY);
  socklen_t len = sizeof addr;
  REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  REQUIRE(::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0);
  ::close(fd);
  return ntohs(addr.sin_port);
}

std::string Read(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The process id in the pid file `path`, or 0.
long PidIn(const std::string& path) { return std::atol(Read(path).c_str()); }

}  // namespace

OneNodeSlurm::OneNodeSlurm(const std::string& dir) : dir_(fs::absolute(dir).string()) {
  fs::create_directories(dir_ + "/state");
  fs::create_directories(dir_ + "/spool");
  // munged with a fresh key, its socket here (not the system's).
  {
    std::random_device random;
    std::string key(1024, '\0');
    for (char& c : key) c = static_cast<char>(random());
    std::ofstream(dir_ + "/munge.key", std::ios::binary) << key;
    fs::permissions(dir_ + "/munge.key", fs::perms::owner_read);
  }
  RunResult r = RunCommand("munged --force --key-file=" + Q(dir_ + "/munge.key") + " --socket=" + Q(dir_ + "/munge.socket") +
                           " --pid-file=" + Q(dir_ + "/munged.pid") + " --log-file=" + Q(dir_ + "/munged.log") +
                           " --seed-file=" + Q(dir_ + "/munge.seed"));
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const std::string name = RunCommand("hostname -s").out;
  const std::string host = name.substr(0, name.find('\n'));
  const int cpus = static_cast<int>(std::thread::hardware_concurrency());
  std::ofstream(dir_ + "/slurm.conf")
      << "ClusterName=prt\nSlurmctldHost=" << host << "\nSlurmUser=root\nSlurmdUser=root\n"
      << "SlurmctldPort=" << FreePort() << "\nSlurmdPort=" << FreePort() << "\n"
      << "AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket=" << dir_ << "/munge.socket\n"
      << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\nMpiDefault=none\n"
      << "StateSaveLocation=" << dir_ << "/state\nSlurmdSpoolDir=" << dir_ << "/spool\n"
      << "SlurmctldPidFile=" << dir_ << "/slurmctld.pid\nSlurmdPidFile=" << dir_ << "/slurmd.pid\n"
      << "SlurmctldLogFile=" << dir_ << "/slurmctld.log\nSlurmdLogFile=" << dir_ << "/slurmd.log\n"
      << "SchedulerType=sched/builtin\nSelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\n"
      // Jobs start as soon as they can (the defaults delay batch jobs up to 3 s a round).
      << "SchedulerParameters=batch_sched_delay=0,sched_min_interval=0\n"
      << "ReturnToService=2\nJobCompType=jobcomp/none\nAccountingStorageType=accounting_storage/none\n"
      << "NodeName=" << host << " CPUs=" << cpus << " State=UNKNOWN\n"
      << "PartitionName=prt Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n";
  for (const char* daemon : {"slurmctld", "slurmd"}) {
    r = RunCommand(Env() + " " + daemon + " -f " + Q(dir_ + "/slurm.conf"));
    REQUIRE_MESSAGE(r.exit_code == 0, daemon << ": " << r.err << Logs());
  }
  // The node takes jobs once sinfo says it is idle.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (RunCommand(Env() + " sinfo -h -o %t").out.find("idle") == std::string::npos) {
    REQUIRE_MESSAGE(std::chrono::steady_clock::now() < give_up, "the node never became idle" << Logs());
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
}

OneNodeSlurm::~OneNodeSlurm() {
  for (const char* pid_file : {"slurmd.pid", "slurmctld.pid", "munged.pid"}) {
    const long pid = PidIn(dir_ + "/" + pid_file);
    if (pid <= 0 || ::kill(static_cast<pid_t>(pid), SIGTERM) != 0) continue;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (::kill(static_cast<pid_t>(pid), 0) == 0 && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (::kill(static_cast<pid_t>(pid), 0) == 0) ::kill(static_cast<pid_t>(pid), SIGKILL);
  }
}

std::string OneNodeSlurm::Logs() const {
  std::string logs;
  for (const char* log : {"slurmctld.log", "slurmd.log", "munged.log"}) {
    const std::string text = Read(dir_ + "/" + log);
    logs += std::string("\n--- ") + log + " (last lines)\n" + text.substr(text.size() > 2000 ? text.size() - 2000 : 0);
  }
  return logs;
}

}  // namespace prt::test
