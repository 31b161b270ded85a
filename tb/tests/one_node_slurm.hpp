// A one-node Slurm for a test (slurmctld and slurmd started by the test as
// root, on ports of its own, configuration, state and logs in a folder of
// its own), for the tests of the Slurm job arrays (blocks, explorer).
#pragma once
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace cube4::test {

namespace fs = std::filesystem;

// A one-node Slurm of the test's own (configuration, state, logs and ports
// in the test's folder; no authentication: auth/none), or the reason it
// cannot run here.
class OneNodeSlurm {
 public:
  explicit OneNodeSlurm(const fs::path& dir) : dir_(dir) {
    for (const char* tool : {"slurmctld", "slurmd", "sbatch", "sinfo"})
      if (std::system((std::string("command -v ") + tool + " >/dev/null 2>&1").c_str()) != 0) {
        why_ = std::string(tool) + " is not installed (Debian: slurm-wlm)";
        return;
      }
    if (::geteuid() != 0) {
      why_ = "slurmd must run as root to start jobs, and the test is not root";
      return;
    }
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    const int port = 20000 + static_cast<int>(::getpid() % 20000);
    fs::create_directories(dir_ / "state");
    fs::create_directories(dir_ / "spool");
    const std::string d = dir_.string();
    std::ofstream(dir_ / "slurm.conf")
        << "ClusterName=cube4test\nSlurmctldHost=" << host << "\nSlurmctldPort=" << port << "\nSlurmdPort="
        << port + 1 << "\nAuthType=auth/none\nCredType=cred/none\nProctrackType=proctrack/pgid\n"
        << "TaskPlugin=task/none\nSchedulerType=sched/builtin\nSelectType=select/cons_tres\n"
        << "SelectTypeParameters=CR_CPU\nSlurmUser=root\nReturnToService=2\nMpiDefault=none\n"
        << "StateSaveLocation=" << d << "/state\nSlurmdSpoolDir=" << d << "/spool\n"
        << "SlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d << "/slurmd.pid\n"
        << "SlurmctldLogFile=" << d << "/slurmctld.log\nSlurmdLogFile=" << d << "/slurmd.log\n"
        << "NodeName=" << host << " CPUs=2 State=UNKNOWN\n"
        << "PartitionName=cube4 Nodes=" << host << " Default=YES MaxTime=INFINITE State=UP\n";
    ::setenv("SLURM_CONF", (dir_ / "slurm.conf").c_str(), 1);
    if (std::system("slurmctld -c >/dev/null 2>&1") != 0 || std::system("slurmd >/dev/null 2>&1") != 0) {
      why_ = "slurmctld or slurmd did not start (see " + d + "/*.log)";
      return;
    }
    for (int i = 0; i < 100; ++i) {
      if (std::system("sinfo -h -o %t 2>/dev/null | grep -q idle") == 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    why_ = "the node did not come up idle within 20 s (see " + d + "/slurmctld.log)";
  }
  ~OneNodeSlurm() {
    for (const char* pid : {"slurmd.pid", "slurmctld.pid"}) {
      std::ifstream f(dir_ / pid);
      long p = 0;
      if (f >> p && p > 0) ::kill(static_cast<pid_t>(p), SIGTERM);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ::unsetenv("SLURM_CONF");
  }
  const std::string& why_not() const { return why_; }

 private:
  fs::path dir_;
  std::string why_;
};

}  // namespace cube4::test
