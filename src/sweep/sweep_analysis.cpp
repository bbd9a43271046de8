#include "sweep/sweep_analysis.hpp"

#include "analysis/analysis.hpp"
#include "analysis/analysis_input.hpp"
#include "analysis/report_files.hpp"
#include "io/input_error.hpp"

namespace dilatant::sweep {

std::string analyse_sweep(const std::filesystem::path& dir,
                          const analysis::AnalysisSettings& settings) {
  try {
    const auto report =
        analysis::analyse(analysis::read_sweep_table(dir / "flowcurves.csv"), settings);
    analysis::write_report_files(report, dir / "analysis");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dilatant::sweep
