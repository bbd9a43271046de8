#pragma once
// Running the real `dilatant` executable from a test: a private temporary
// directory (tests/io/io_test_files.hpp) that can also run the executable inside
// it, capturing its exit code, stdout and stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/io_test_files.hpp"

namespace dilatant::test {

// Single-quoted for /bin/sh.
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') {
      q.append("'\\''");
    } else {
      q.push_back(c);
    }
  }
  q.push_back('\'');
  return q;
}

// Whether /usr/bin/python3 can draw the figures. scripts/test.sh installs
// matplotlib and sets DILATANT_REQUIRE_PLOTS=1, so in CI its absence is a test
// failure (the figures must be drawn); elsewhere a machine without it checks
// the one-line "plots skipped" path instead.
inline bool matplotlib_available() {
  const bool available =
      std::system("/usr/bin/python3 -c 'import matplotlib, numpy' >/dev/null 2>&1") == 0;
  const char* required = std::getenv("DILATANT_REQUIRE_PLOTS");
  if (required != nullptr && std::string(required) == "1") {
    EXPECT_TRUE(available) << "DILATANT_REQUIRE_PLOTS=1 but python3 cannot import matplotlib";
  }
  return available;
}

struct RunResult {
  int exit_code = -1;  // -1: killed by a signal
  std::string out;
  std::string err;
};

class CliDir : public TempDir {
 public:
  // Runs the dilatant executable with `args`; stdout and stderr are captured.
  // `shell_setup` runs in the same shell first (e.g. limits: "ulimit -f 8;");
  // `launcher` goes in front of the executable (e.g. "setpriv ... --"), and
  // `executable` replaces DILATANT_EXECUTABLE.
  RunResult run(const std::vector<std::string>& args, const std::string& shell_setup = "",
                const std::string& launcher = "",
                const std::string& executable = DILATANT_EXECUTABLE) const {
    const std::filesystem::path out = path() / "stdout.txt";
    const std::filesystem::path err = path() / "stderr.txt";
    std::string command = shell_setup + " exec " + launcher + " " + shell_quote(executable);
    for (const auto& a : args) command.append(" ").append(shell_quote(a));
    command.append(" >").append(shell_quote(out.string()));
    command.append(" 2>").append(shell_quote(err.string()));
    command.append(" </dev/null");
    const int status = std::system(command.c_str());
    RunResult r;
    if (status != -1 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    r.out = read_text(out);
    r.err = read_text(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
  }
};

// `dilatant run` of a small cell for 0.03 strain without snapshots: about a
// second. Later --set options override these.
inline std::vector<std::string> small_cell_run() {
  return {"run",
          "--set",
          "cell.size=[6.0, 5.0, 7.0]",
          "--set",
          "run.transient_strain=0.01",
          "--set",
          "run.strain=0.03",
          "--set",
          "run.snapshot_interval=0",
          "-q"};
}

}  // namespace dilatant::test
