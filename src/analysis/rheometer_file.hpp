#pragma once
// A rheometer export read whole: its steps, what kind each is, and the flow
// curves among them (docs/analysis.md, "Rheometer exports").
//
// The tables and steps are found by rheometer_layout.hpp, each step's kind by
// step_kind.hpp, a flow curve's numbers by flow_curve_csv.hpp. A flow-curve
// step whose data cannot be used (too few points, an unsorted ramp, a
// mislabelled unit) carries its problem, so that `dilatant analyze --list`
// shows every step; a malformed row (io/table_rows.hpp, rule 1) makes the
// whole file bad input.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/flow_curve_csv.hpp"
#include "analysis/step_kind.hpp"

namespace dilatant::analysis {

struct RheometerStep {
  std::size_t number = 0;  // 1-based, in file order
  std::string name;        // as the export names it; "" when it does not
  StepKind kind = StepKind::Other;
  std::size_t first_line = 0;  // its marker, header or first row
  std::size_t last_line = 0;   // its last row
  std::size_t rows = 0;        // data rows, dropped ones included
  FlowCurveFile curve;         // a usable flow curve: ascending stress, >= kMinCurvePoints
  // Why a flow-curve step gives no curve ("file:line: ..."); "" when it does.
  enum class Problem { None, TooFewPoints, BadData } problem = Problem::None;
  std::string why;

  // "3 'Flow Curve Down'", or "3" when the step has no name.
  std::string label() const;
};

struct RheometerFile {
  std::string source;
  std::vector<RheometerStep> steps;
};

// Reads and classifies every step. InputError for a file that cannot be read,
// has no table, or has a malformed row.
RheometerFile read_rheometer_file(const std::filesystem::path& file);

// Which steps of a file become curves: one by number or by name (the
// manifest's `step = 2` or `step = "Flow Curve Up"`), or, when neither is
// given, every flow-curve step.
struct StepChoice {
  std::optional<std::size_t> number;
  std::optional<std::string> name;
  std::string origin;  // where it was chosen, for messages: "manifest.toml:7: curve[2].step"
};

struct StepCurve {
  std::string step;  // RheometerStep::label(); "" when the file has one step
  FlowCurveFile curve;
};

struct ChosenCurves {
  std::vector<StepCurve> curves;
  // The steps left out and why: "step 1 'Pre Shear Initial' (hold), ..."; "" if none.
  std::string skipped;
};

// The curves of the chosen steps. InputError when a chosen step does not
// exist, is not a flow curve or cannot be used; without a choice, when a flow
// step's data are bad, or no flow step gives a curve (naming what was found).
// A flow step with too few points is then skipped and said in `skipped`.
ChosenCurves choose_flow_curves(const RheometerFile& file, const StepChoice& choice);

// The curve of a file whose steps give exactly one flow curve (InputError
// otherwise): a plain table, a one-step export.
FlowCurveFile read_flow_curve_file(const std::filesystem::path& file);

// `dilatant analyze --list FILE`: one line per step, its number, kind, rows,
// lines, name and problem.
std::string step_listing(const RheometerFile& file);

}  // namespace dilatant::analysis
