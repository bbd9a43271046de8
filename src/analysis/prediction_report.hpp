#pragma once
// `dilatant predict`'s answer as one record, shared by the CLI (--json and
// its text) and the Python module (dilatant.predict): the regime from the
// bulk flow curves where they decide (bulk_flow_table.hpp), else from the
// sediment's jamming table (jamming_table.hpp), with the source named; and,
// where the suspension flows, the frictional onset (onset_table.hpp).
// (A user's Wyart–Cates fit, `predict --model`, comes before both:
// wyart_cates_prediction.hpp.)
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "analysis/bulk_flow_table.hpp"
#include "analysis/jamming_table.hpp"
#include "analysis/onset_table.hpp"

namespace dilatant::analysis {

enum class RegimeSource { BulkFlowCurves, SedimentTable };

struct PredictionReport {
  double mu0 = 0.0;
  double phi = 0.0;
  double s_c = 0.0;
  Prediction regime;       // the sediment table's answer, always computed (phi_max_bl, phi_rcp)
  BulkDecision bulk;       // bulk.regime empty: the bulk table did not decide (or none was used)
  std::string bulk_table;  // its name; empty when predict used none
  // The answer: the bulk table's where it decides, else the sediment table's.
  RegimeSource source() const {
    return bulk.regime ? RegimeSource::BulkFlowCurves : RegimeSource::SedimentTable;
  }
  FlowRegime answer() const { return bulk.regime ? *bulk.regime : regime.regime; }
  OnsetPrediction onset;  // not available when the answer is no_flow
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
// Checks the input and predicts: from `bulk` where it decides (nullptr: no
// bulk table), else from `table`.
PredictionReport predict(const JammingTable& table, const BulkFlowTable* bulk, double mu0,
                         double phi, double s_c, const PredictArgumentNames& names = {});

// "bulk flow curves" or "sediment table": the --json `source`.
std::string_view regime_source_name(RegimeSource s);
// The answer's source in a sentence: "bulk flow curves (TABLE, line N: mu0 1,
// phi_bulk 0.5797, ...: CST to lambda 30000 (...))", or "sediment table
// (TABLE); bulk flow curves: <why they do not decide>".
std::string source_detail(const PredictionReport& r, const std::string& table_name);

// The --json document; `table_name` is "built-in" or the sediment table's file.
nlohmann::json prediction_json(const PredictionReport& r, const std::string& table_name);

}  // namespace dilatant::analysis
