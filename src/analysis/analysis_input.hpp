#pragma once
// What `dilatant analyze` reads: either a manifest (TOML) that labels rheometer
// files with sample and phi, or a simulation sweep's flowcurves.csv. Both give
// a list of labelled flow curves in one unit system.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "analysis/flow_curve.hpp"

namespace dilatant::analysis {

enum class InputKind { Manifest, SweepTable };

struct AnalysisInput {
  std::string source;  // the manifest or flowcurves.csv, as given
  InputKind kind = InputKind::Manifest;
  UnitSystem units = UnitSystem::SI;
  std::vector<FlowCurve> curves;
  std::vector<std::string> samples;       // in order of first appearance
  std::map<std::string, double> phi_max;  // measured values, per sample (manifest only)
  // Rows dropped for a missing, zero or negative value (io/table_rows.hpp):
  // their count, and per file that had any, "<file>: <which lines and why>".
  std::size_t dropped_rows = 0;
  std::vector<std::string> dropped;

  // Steps of rheometer files that are not flow curves, per file that had any:
  // "<file>: step 1 'Pre Shear Initial' (hold), ..." (rheometer_file.hpp).
  std::vector<std::string> skipped_steps;

  void note_dropped(const std::string& file, std::size_t rows, const std::string& summary) {
    if (rows == 0) return;
    dropped_rows += rows;
    dropped.push_back(file + ": " + summary);
  }
};

// A path ending in .toml is a manifest; a CSV whose header names phi, mu0,
// shear_stress and gamma_dot is a sweep table; anything else is an InputError.
AnalysisInput load_analysis_input(const std::filesystem::path& path);

// Manifest:
//   [[curve]]                 one per flow-curve file
//   file = "A_0537.csv"       relative to the manifest
//   step = "Flow Curve Up"    optional: the file's step, by name or number
//                             (step = 2); without it every flow-curve step
//                             of the file is a curve (rheometer_file.hpp)
//   sample = "A"              the coating (any name without ',' or '"')
//   phi = 0.537               volume fraction, in (0, 0.74)
//   window_stress = [5.0, 300.0]   optional: fit window in Pa (replaces the automatic one)
//   [samples.A]
//   phi_max = 0.578           optional: measured; fitted when absent
// Unknown keys, wrong types, out-of-range values, a missing file and a
// [samples.X] without curves are InputErrors naming the manifest's line.
AnalysisInput read_manifest(const std::filesystem::path& manifest);

// Sweep table (flowcurves.csv of `dilatant sweep`): a header with at least
// phi, mu0, shear_stress, gamma_dot, valid, jammed (optionally gamma_dot_err;
// other columns are ignored); one row per simulation, in the paper's units.
// Rows are grouped into curves by (phi, mu0), sample "mu0=<value>", or by
// (phi, sample) when a `sample` column names the curve (a sweep over more than
// mu0: "mu0=0.1 law=coulomb"); valid and jammed are true/false; a jammed row
// may have gamma_dot 0 and an empty eta. With a `status` column, only rows
// whose status is `done` are read (failed and pending points have no result).
AnalysisInput read_sweep_table(const std::filesystem::path& table);

}  // namespace dilatant::analysis
