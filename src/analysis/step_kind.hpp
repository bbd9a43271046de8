#pragma once
// What kind of measurement a step of a rheometer procedure is: only a flow
// curve (a ramp of stress or rate through the steady states) is analysed; the
// steps around it are recognised, named and skipped (docs/analysis.md,
// "Rheometer exports").
//
//   flow curve    a flow sweep or ramp: stress and rate both vary
//   oscillation   amplitude, frequency or other oscillatory sweeps (moduli,
//                 not a steady viscosity)
//   hold          a step at one rate or stress: pre-shear, peak hold,
//                 conditioning, rest, creep, recovery
//   other         a table without shear stress, rate or viscosity columns
//
// The name decides first, as the vendor's software wrote it, in English,
// German or French; then the columns (moduli, phase angle); then the data: a
// step whose rate or stress stays within kHoldSpread of one value is a hold.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dilatant::analysis {

enum class StepKind { FlowCurve, Oscillation, Hold, Other };

// "flow curve", "oscillation", "hold", "other".
std::string_view step_kind_name(StepKind kind);

// What a step's name says it is; nullopt when it does not tell. A flow curve's
// name ("Flow sweep", "Flow Curve Up", "Fließkurve") returns FlowCurve; its
// data may still show a hold.
std::optional<StepKind> kind_from_name(std::string_view name);

// A table with oscillation columns (storage or loss modulus, phase angle).
bool has_oscillation_columns(const std::vector<std::string>& headings);

// Rate or stress within this factor of one value over a step: a hold. A flow
// curve spans a decade or more; an instrument holds its set point to well
// under 1%, and a step at one rate still lets the stress creep by a few %.
inline constexpr double kHoldSpread = 1.05;

}  // namespace dilatant::analysis
