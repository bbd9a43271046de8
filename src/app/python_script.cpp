#include "app/python_script.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace dilatant {
namespace {

std::string last_line(const std::string& text) {
  auto end = text.find_last_not_of(" \n\r\t");
  if (end == std::string::npos) return "";
  const auto start = text.rfind('\n', end);
  return text.substr(start == std::string::npos ? 0 : start + 1,
                     end - (start == std::string::npos ? 0 : start + 1) + 1);
}

}  // namespace

std::string default_python() {
  const char* python = std::getenv("DILATANT_PYTHON");
  return python != nullptr && *python != '\0' ? python : "/usr/bin/python3";
}

std::string plot_script(std::string_view name) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    const fs::path installed = self.parent_path().parent_path() / "plots" / name;
    if (fs::is_regular_file(installed, error)) return installed.string();
  }
  return (fs::path(DILATANT_PLOTS_DIR) / name).string();
}

std::string run_plot_script(const std::string& python, const std::string& script,
                            const std::filesystem::path& dir) {
  if (!std::filesystem::is_regular_file(script))
    return fmt::format("plot script {} not found", script);
  int fds[2];
  if (pipe(fds) != 0) return fmt::format("pipe: {}", std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  std::string dir_arg = dir.string(), python_arg = python, script_arg = script;
  char* argv[] = {python_arg.data(), script_arg.data(), dir_arg.data(), nullptr};
  pid_t pid = 0;
  // posix_spawnp: a bare name such as --python python3 is looked up in PATH.
  const int spawned = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (spawned != 0) {
    close(fds[0]);
    return fmt::format("cannot run {}: {}", python, std::strerror(spawned));
  }
  std::string output;
  char buffer[4096];
  for (ssize_t got; (got = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) break;
    output.append(buffer, static_cast<std::size_t>(got));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  const std::string why = last_line(output);
  return fmt::format("{} {} failed{}{}", python, script, why.empty() ? "" : ": ", why);
}

}  // namespace dilatant
