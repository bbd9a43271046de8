#pragma once
// Drawing plots with a Python script (Debian's /usr/bin/python3 with
// matplotlib, or the Python that installed dilatant): the numbers come from the
// library, the scripts only draw them.
#include <filesystem>
#include <string>
#include <string_view>

namespace dilatant {

// The Python that draws the plots unless --python says otherwise: the
// environment's DILATANT_PYTHON (set by the launcher that `pip install` puts on
// PATH, python/dilatant/_cli.py: the interpreter of that environment), else
// Debian's /usr/bin/python3.
std::string default_python();

// The plot script NAME (e.g. "analysis.py"): in an installed package the
// executable is dilatant/_bin/dilatant and the scripts are dilatant/plots/ beside
// it; in a build tree, python/dilatant/plots/ of the source tree it was built from.
std::string plot_script(std::string_view name);

// Runs `python script dir` without a shell, its output captured so that a
// failure is reported in one line. Returns "" on success, else why it failed
// (script missing, python missing, or the script's last line of output, e.g.
// "matplotlib/numpy not available").
std::string run_plot_script(const std::string& python, const std::string& script,
                            const std::filesystem::path& dir);

}  // namespace dilatant
