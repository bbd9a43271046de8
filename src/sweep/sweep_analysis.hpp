#pragma once
// The flow-curve analysis of a sweep: src/analysis (the rheometer analysis of
// `dilatant analyze`) run on DIR/flowcurves.csv, one curve per (phi, sample),
// its files written to DIR/analysis/ (curves.csv with the regime of every
// curve, points.csv with the local slopes, fits.json; see
// analysis/report_files.hpp and docs/sweeps.md "Classification").
#include <filesystem>
#include <string>

#include "analysis/analysis_settings.hpp"

namespace dilatant::sweep {

// Returns "" when the files were written, else why not (no finished point yet,
// or a table the analysis cannot read, e.g. two runs of one curve at the same
// stress when cell.seed is swept): the sweep's results stand without it.
std::string analyse_sweep(const std::filesystem::path& dir,
                          const analysis::AnalysisSettings& settings = {});

}  // namespace dilatant::sweep
