#pragma once
// `dilatant sweep` as a child process, alone or under mpirun, for the tests
// that kill it (sweep_kill_test.cpp) or run it on MPI ranks
// (mpi_sweep_test.cpp), and the comparison of the tables they leave.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"

namespace dilatant::test {

// Starts `program args...` in a session of its own (so that a test can kill
// it with everything it started: mpirun puts each rank in a process group of
// its own, but they stay in its session), stdin and stdout from/to /dev/null,
// stderr to `err` (/dev/null when empty).
inline pid_t start_child(const std::vector<std::string>& command, const std::string& err = {}) {
  const pid_t pid = fork();
  if (pid == 0) {
    setsid();
    const int null = open("/dev/null", O_RDWR);
    dup2(null, 0);
    dup2(null, 1);
    const int e = err.empty() ? null : open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(e, 2);
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

// The live processes (not zombies) of session `sid`.
inline std::vector<pid_t> session_processes(pid_t sid) {
  std::vector<pid_t> pids;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    // /proc/PID/stat: pid (comm) state ppid pgrp session ...; comm may hold spaces.
    const std::string stat = read_text(entry.path() / "stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 1));
    char state = 0;
    long ppid = 0, group = 0, session = 0;
    rest >> state >> ppid >> group >> session;
    if (session == sid && state != 'Z') pids.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return pids;
}

// SIGKILL to the child started by start_child and everything in its session,
// as a batch system ends a job: returns once none of them is left (the ranks
// of a killed mpirun would otherwise run on for a moment).
inline int kill_session(pid_t pid) {
  for (pid_t p : session_processes(pid)) kill(p, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  for (int tries = 0; tries < 1000; ++tries) {
    const auto left = session_processes(pid);
    if (left.empty()) break;
    for (pid_t p : left) kill(p, SIGKILL);
    usleep(10000);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// Waits for the child; its exit code, or -signal when a signal ended it.
inline int wait_for(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// The table with the wall-time column blanked (the only one that differs
// between two runs of the same points).
inline std::string table_without_timing(const std::filesystem::path& file) {
  std::istringstream in(read_text(file));
  std::string out, line;
  std::size_t timing = std::string::npos;
  while (std::getline(in, line)) {
    auto fields = analysis::split_fields(line, ',');
    if (timing == std::string::npos)
      for (std::size_t k = 0; k < fields.size(); ++k)
        if (fields[k] == "wall_time_s") timing = k;
    if (!out.empty() && timing < fields.size()) fields[timing] = "";
    for (const auto& f : fields) out += f + "|";
    out += "\n";
  }
  return out;
}

// How many points the table on disk calls done (0 when there is no table).
inline std::size_t done_points(const std::filesystem::path& table) {
  if (!std::filesystem::exists(table)) return 0;
  const std::string t = read_text(table);
  std::size_t done = 0;
  for (auto at = t.find(",done,"); at != std::string::npos; at = t.find(",done,", at + 1)) ++done;
  return done;
}

}  // namespace dilatant::test
