#pragma once
// Drawing plots with a Python script (Debian's /usr/bin/python3 with
// matplotlib): the numbers come from the library, the scripts only draw them.
#include <filesystem>
#include <string>

namespace dilatant {

// Runs `python script dir` without a shell, its output captured so that a
// failure is reported in one line. Returns "" on success, else why it failed
// (script missing, python missing, or the script's last line of output, e.g.
// "matplotlib/numpy not available").
std::string run_plot_script(const std::string& python, const std::string& script,
                            const std::filesystem::path& dir);

}  // namespace dilatant
