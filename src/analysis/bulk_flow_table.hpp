#pragma once
// The flow states measured in bulk: stress ramps in the Lees–Edwards box (no
// walls), one row per ramp (data/jamming/bulk_flow_states.csv, made by
// dilatant.plots.bulk_flow_states from the committed flow curves). `dilatant
// predict` answers from it before the sediment table (jamming_table.hpp)
// where it decides, because the sediment's phi_max_BL is a static packing's
// fraction and our bulk flow curves part from it at high friction (at mu0 1
// they flow at phi_bulk 0.58, 0.02 above the sediment's 0.559:
// docs/jamming.md "Shear jamming in the cell").
//
// When a row decides a query (mu0, phi). Rows count only at the query's mu0
// (equal within kBulkMu0Tolerance: friction is not interpolated, since the
// bulk boundary's dependence on mu0 is what is not measured). The regime is
// taken as monotone in phi at fixed mu0 (denser suspensions jam first, the
// premise of the paper's phase diagram), so:
//   * a `cst` row at phi_bulk p (flowed to max_lambda without a jam) decides
//     `cst` for every phi <= p + kBulkPhiTolerance;
//   * a `jammed` row (no flow at its lowest stress) decides `no_flow` for
//     phi >= p - kBulkPhiTolerance;
//   * a `dst` row decides `dst` only within kBulkPhiTolerance of p: above it
//     the suspension may not flow at all, below it the jam may move to higher
//     stress. Its evidence (column dst_evidence, the flow-curve analysis's
//     word, docs/analysis.md rule 6) is `jammed` (flowed, then jammed at
//     jam_lambda, confirmed from a cold start) or, for a ramp that flowed at
//     every stress, `rate_falls` (its rate fell at fall_lambda as the stress
//     rose: a step across an S-shaped flow curve's turning point),
//     `rate_not_increasing` or `n_above_cap`. A table without the column is
//     read as written before these: its dst rows are jams. Of several dst
//     rows within reach, the nearest in phi answers, then the one whose
//     worst point had the smallest share of steps at the solver's iteration
//     cap (column max_frac_unconverged: a run of the same ramp at a higher cap
//     measures it without the cap's bias).
// Anything else (another mu0; phi between the densest cst row and the
// loosest dst or jammed one, where the bulk boundary lies but is not
// located; phi beyond a dst row) is not decided, and the caller falls back
// to the sediment table. A table whose rows contradict that order (a cst row
// at or above a dst or jammed row of the same mu0) is bad input.
// A `cst` answer holds up to the row's max_lambda: a ramp that stops there
// says nothing of higher stresses.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/curve_analysis.hpp"
#include "analysis/jamming_table.hpp"
#include "analysis/numeric_csv.hpp"

namespace dilatant::analysis {

// phi_bulk is written with four decimals in the table and quoted with three
// (0.5797 is "0.580"): half a unit of the third decimal.
inline constexpr double kBulkPhiTolerance = 0.0005;
inline constexpr double kBulkMu0Tolerance = 1e-9;

enum class BulkState { Cst, Dst, Jammed };

struct BulkFlowState {
  double mu0 = 0.0;
  double phi_bulk = 0.0;
  BulkState state = BulkState::Cst;
  double max_lambda = 0.0;  // largest lambda at which the ramp flowed (0: none)
  double jam_lambda = 0.0;  // lambda of the jam (0: none)
  std::string cell;         // "25x10x27"
  std::string source;       // the flow-curve file it was read from
  std::string sample;       // the curve's label there
  std::size_t line = 0;     // line of the row in the table
  DstEvidence dst_evidence = DstEvidence::None;  // None: not a dst row
  double fall_lambda = 0.0;  // where the rate fell: lambda of the first point on the lower branch
  // Largest share of a point's steps that stopped at solver.max_iterations
  // (optional column; 0 when absent).
  double max_frac_unconverged = 0.0;
};

class BulkFlowTable {
 public:
  // Columns mu0, phi_bulk, regime (cst, dst, jammed), max_lambda, jam_lambda,
  // cell, source, sample, and optionally dst_evidence (empty unless dst),
  // fall_lambda and max_frac_unconverged (in [0, 1]); checked as the header
  // comment says.
  // Throws InputError naming the file and line.
  static BulkFlowTable parse(const NumericCsv& csv);
  static BulkFlowTable read(const std::filesystem::path& file);
  // data/jamming/bulk_flow_states.csv of this version.
  static BulkFlowTable builtin();
  const std::vector<BulkFlowState>& rows() const { return rows_; }
  const std::string& name() const { return name_; }  // the file, as messages name it

 private:
  std::vector<BulkFlowState> rows_;
  std::string name_;
};

struct BulkDecision {
  std::optional<FlowRegime> regime;  // empty: the table does not decide
  BulkFlowState row;                 // the row that decides (when it does)
  std::string reason;  // what the row measured, or why none decides: one clause for the answer
};

BulkDecision decide_from_bulk(const BulkFlowTable& table, double mu0, double phi);

std::string_view bulk_state_name(BulkState s);  // "cst", "dst", "jammed"

}  // namespace dilatant::analysis
