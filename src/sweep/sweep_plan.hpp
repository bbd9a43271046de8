#pragma once
// A sweep: many shear-cell runs that differ in a few keys, e.g. the points of
// the flow curves eta(gamma_dot) for several mu0 (docs/sweeps.md).
//
// A sweep file is a run configuration ([cell], [friction], ...) in which any
// key may hold a list of values instead of one:
//
//   [cell]
//   phi = 0.58
//   [friction]
//   mu0 = [0.1, 0.3]                  # swept
//   [fluid]
//   lambda = [1.0, 10.0, 100.0]       # swept
//   [sweep]                           # optional: sweep-only settings
//   jobs = 0                          # points run side by side; 0 = all cores
//   continuation = false              # see below
//
// The points are the full grid over all lists: the key listed first in the
// file varies slowest, the last fastest (here mu0 0.1 with lambda 1, 10, 100,
// then mu0 0.3 with the same). A key whose value is an array anyway
// (cell.size) is swept only when given a list of arrays:
// size = [[6.0, 5.0, 7.0], [8.0, 6.0, 9.0]].
//
// Instead of the grid of the whole file, `[[points]]` tables list points: each
// holds a partial set of keys (dotted, `friction.mu0 = 0.3`, or nested tables)
// that replace the file's values for that point; a list inside one of them
// makes it a small grid of its own (with the file's lists):
//
//   [fluid]
//   lambda = [1.0, 10.0, 100.0]
//   [[points]]
//   cell.phi = 0.58
//   friction.mu0 = [0.1, 0.3]
//   [[points]]
//   cell.phi = 0.59
//   friction.mu0 = 0.3
//
// gives 2 x 3 + 3 points. The swept keys are those holding a list anywhere or
// set in any [[points]] table; they name the points and head the table
// (flowcurves.csv).
//
// Continuation (`continuation = true`): the points of one flow curve (equal in
// every swept key but fluid.lambda) run one after the other in increasing
// lambda, each starting from the final state of the previous one (a rheometer
// ramp) instead of a new packing. `continuation_strain` and
// `continuation_transient_strain` then replace run.strain and
// run.transient_strain for every point but the first of its curve, which is
// where the time is saved.
//
// A ramp that jams (issue 15, docs/sweeps.md "Ramps to the jam"): with
// `stop_at_jam = true` (the default) the points above a jammed one are not
// run (status `skipped`): a packing jammed at one stress stays jammed at a
// higher one. With `confirm_jams = true` (the default) a continued point that
// jams is run again from a cold start of the same configuration (with the
// first point's run.strain and run.transient_strain), in its folder's
// `cold-start/`; the table's `jam_cold_start` says whether that jammed too.
//
// Refinement (`refines = "DIR"`, with `continuation = true`): the points are
// extra stresses of the ramps of another (continuation) sweep, whose folder is
// DIR (relative to this file's folder), e.g. stress steps of 2 where a ramp of
// steps of 10 bends (sweep_refinement.cpp). The extra points between two of a
// ramp's points are a short ramp of their own: the lowest starts from the
// final state of the ramp's point below it, each next one from the previous
// extra point's; the segments run side by side. A point's configuration must
// equal its ramp's but for fluid.lambda; a point above the ramp's jam is
// skipped, one whose starting point has not finished yet waits (stays
// pending); the continuation settings apply to every point.
//
// Every point's resolved configuration is validated like a run's; an error
// names the sweep file, line and key, and the point. Sweeps run the shear cell
// only ([scene] is an error). Each point gets solver.threads as configured
// (default 1: points run side by side instead).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/config.hpp"

namespace dilatant::sweep {

struct SweepSettings {
  int jobs = 0;  // 0: one per core
  bool continuation = false;
  std::optional<double> continuation_strain;
  std::optional<double> continuation_transient_strain;
  bool stop_at_jam = true;
  bool confirm_jams = true;
  // The nominal phi of a jam's cold start (docs/sweeps.md "Ramps to the jam";
  // cold_start_choice.hpp): the ramp's own (nominal), shifted by the ramp's
  // change of the bulk before the jam (matched), or the one whose packing
  // begins at the bulk fraction the jammed point began from (bulk).
  enum class ColdStartPhi { Nominal, Matched, Bulk };
  ColdStartPhi cold_start_phi = ColdStartPhi::Nominal;
  // The folder of the sweep whose ramps this one refines (absolute), or empty.
  std::filesystem::path refines;
  // A point that ends not steady runs on, one averaging window at a time, up
  // to this run.strain (sweep/unsteady_extension.hpp); unset: never.
  std::optional<double> extend_unsteady_to;
};

// Where the lowest extra point of a refinement's segment starts
// (sweep.refines): the refined ramp's points up to the nearest lower lambda, in
// order of lambda (absolute folders). The last is the state it starts from;
// the first is the ramp's cold start.
struct RampStart {
  std::vector<std::filesystem::path> ramp;
};

struct SweepPoint {
  std::size_t index = 0;
  std::string label;   // "mu0=0.1_lambda=10", from the swept keys
  std::string folder;  // "points/001-mu0=0.1_lambda=10", relative to the sweep's folder
  std::vector<std::string> values;            // per swept key, its value as TOML text
  Config config;                              // resolved and validated
  std::optional<std::size_t> continues_from;  // index of the point whose final state it starts from
  std::optional<RampStart> refines;  // or, a refinement segment's lowest point, the other sweep's
  // A continued point's configuration as a cold start (run.strain and
  // run.transient_strain of a cold point): the run that confirms its jam.
  std::optional<Config> cold_start;
};

// The point starts from another run's final state (continuation or refinement).
inline bool is_continued(const SweepPoint& p) { return p.continues_from || p.refines; }

struct SweepPlan {
  std::string source;  // the sweep file, as given
  SweepSettings settings;
  std::vector<std::string> keys;  // the swept keys, dotted ("friction.mu0"), in file order
  std::vector<SweepPoint> points;
};

// Reads and expands a sweep file; `overrides` are `--set key=value` as for
// `dilatant run` (a list value sweeps the key; sweep.* keys set [sweep]
// settings); an override replaces the key in the file and in every [[points]]
// table. Throws InputError naming file, line, key and point.
SweepPlan load_sweep(const std::filesystem::path& file, const std::vector<std::string>& overrides);

// The same from text; `source` names it in messages, relative paths resolve
// against `base_dir`.
SweepPlan parse_sweep(std::string_view text, std::string source,
                      const std::filesystem::path& base_dir,
                      const std::vector<std::string>& overrides);

// The plan's continuation chains (ramps), in order of their first point: each
// the indices of its points from the one that continues from none, each next
// the point that continues from the one before (in order of lambda). Without
// continuation every point is a chain of its own.
std::vector<std::vector<std::size_t>> continuation_chains(const SweepPlan& plan);

// The resolved sweep as a sweep file (DIR/sweep.toml): [sweep] settings, every
// other key at the value shared by all points, and one [[points]] table per
// point with its swept keys. Loading it gives the same points, folders and
// configurations.
std::string resolved_sweep_toml(const SweepPlan& plan);

// The value of dotted `key` ("friction.mu0") in a resolved configuration.
const toml::node* find_key(const toml::table& resolved, std::string_view key);

// A value as short text for labels and table cells: numbers as the shortest
// exact decimal (0.1, 10), strings bare, arrays joined by 'x' (6x5x7).
std::string plain_text(const toml::node& value);

}  // namespace dilatant::sweep
