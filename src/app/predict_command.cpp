#include "app/predict_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "analysis/jamming_table.hpp"
#include "dilatant/version.hpp"
#include "io/input_error.hpp"

namespace dilatant {

CLI::App* add_predict_command(CLI::App& app, PredictCommandArgs& args) {
  CLI::App* p = app.add_subcommand(
      "predict",
      "The flow regime of spheres with boundary friction mu0 at volume fraction phi, from "
      "the measured jamming fractions (docs/jamming.md): cst when phi <= phi_max_BL(mu0), "
      "dst up to phi_RCP (the frictionless jamming fraction), no_flow above.");
  p->add_option("--mu0", args.mu0, "boundary-lubricated friction coefficient (>= 0)")->required();
  p->add_option("--phi", args.phi, "solid volume fraction, in (0, 0.74)")->required();
  p->add_flag("--json", args.json, "print the prediction as JSON");
  p->add_option("--table", args.table,
                "CSV with columns mu0, phi_max, phi_max_err (default: the built-in table, "
                "data/jamming/phi_max_bl.csv)")
      ->check(CLI::ExistingFile);
  return p;
}

int execute_predict_command(const PredictCommandArgs& args) {
  if (!(args.mu0 >= 0.0) || !std::isfinite(args.mu0))
    throw InputError(fmt::format("--mu0 {}: must be a finite number >= 0", args.mu0));
  if (!(args.phi > 0.0 && args.phi < 0.74))
    throw InputError(fmt::format("--phi {}: must be in (0, 0.74)", args.phi));
  const auto table = args.table.empty() ? analysis::JammingTable::builtin()
                                        : analysis::JammingTable::read(args.table);
  const auto p = analysis::predict_regime(table, args.mu0, args.phi);
  const double mu_max = table.points().back().mu0;
  if (args.json) {
    nlohmann::json j;
    j["mu0"] = args.mu0;
    j["phi"] = args.phi;
    j["regime"] = analysis::flow_regime_name(p.regime);
    j["phi_max_bl"] = p.phi_max_bl.value;
    j["phi_max_bl_err"] = p.phi_max_bl.error;
    j["phi_rcp"] = p.phi_rcp.value;
    j["phi_rcp_err"] = p.phi_rcp.error;
    j["margin_sigma"] =
        std::isfinite(p.margin_sigma) ? nlohmann::json(p.margin_sigma) : nlohmann::json(nullptr);
    j["uncertain"] = p.uncertain;
    j["mu0_beyond_table"] = args.mu0 > mu_max;
    j["table"] = args.table.empty() ? "built-in" : args.table;
    j["version"] = kVersion;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << fmt::format(
      "{} (phi {} against phi_max_BL({}) = {:.4f} +- {:.4f} and phi_RCP = {:.4f} +- {:.4f}{})\n",
      analysis::flow_regime_name(p.regime), args.phi, args.mu0, p.phi_max_bl.value,
      p.phi_max_bl.error, p.phi_rcp.value, p.phi_rcp.error,
      p.uncertain ? fmt::format("; within {:.1f} sigma of a boundary: uncertain", p.margin_sigma)
                  : "");
  if (args.mu0 > mu_max)
    std::cout << fmt::format(
        "note: mu0 {} is beyond the table's last point ({}); its value is "
        "used\n",
        args.mu0, mu_max);
  return 0;
}

}  // namespace dilatant
