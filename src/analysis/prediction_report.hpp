#pragma once
// `dilatant predict`'s answer as one record, shared by the CLI (--json and
// its text) and the Python module (dilatant.predict): the regime against the
// jamming table (jamming_table.hpp) and, where the suspension flows, the
// onset scale of thickening (onset_table.hpp).
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/jamming_table.hpp"
#include "analysis/onset_table.hpp"

namespace dilatant::analysis {

struct PredictionReport {
  double mu0 = 0.0;
  double phi = 0.0;
  double s_c = 0.0;
  Prediction regime;
  OnsetPrediction onset;  // not available when the regime is no_flow
  double mu0_table_max = 0.0;
  bool mu0_beyond_table() const { return mu0 > mu0_table_max; }
};

// Why no onset is given when the nearest measured one is too far in phi.
std::string onset_withheld(const OnsetPrediction& o, double phi);

// How the caller spells the inputs in messages: the CLI's flags, or Python's
// argument names.
struct PredictArgumentNames {
  std::string mu0 = "--mu0", phi = "--phi", s_c = "--s-c";
};
// InputError naming the first bad input (s_c, mu0, phi), before any table is read.
void check_prediction_input(double mu0, double phi, double s_c,
                            const PredictArgumentNames& names = {});
// Checks the input and predicts.
PredictionReport predict(const JammingTable& table, double mu0, double phi, double s_c,
                         const PredictArgumentNames& names = {});

// The --json document; `table_name` is "built-in" or the table's file.
nlohmann::json prediction_json(const PredictionReport& r, const std::string& table_name);

}  // namespace dilatant::analysis
