#include "app/predict_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include "analysis/bulk_flow_table.hpp"
#include "analysis/jamming_table.hpp"
#include "analysis/onset_table.hpp"
#include "analysis/phase_diagram.hpp"
#include "analysis/prediction_report.hpp"
#include "analysis/wyart_cates_prediction.hpp"
#include "app/python_script.hpp"
#include "friction/defaults.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace dilatant {

CLI::App* add_predict_command(CLI::App& app, PredictCommandArgs& args) {
  CLI::App* p = app.add_subcommand(
      "predict",
      "The flow regime of spheres with boundary friction mu0 at volume fraction phi, from the "
      "first source that decides it (docs/jamming.md \"The predictor's sources\"): a "
      "Wyart-Cates fit if given (--model); else the flow states measured in bulk, in the "
      "Lees-Edwards box (data/jamming/bulk_flow_states.csv), at the same mu0 and phi up to a "
      "ramp that flowed (+ 0.0005); else the sediment's jamming fractions: cst when phi <= "
      "phi_max_BL(mu0), dst up to phi_RCP (the frictionless jamming fraction), no_flow above. "
      "The answer names its source. And the frictional onset, where contacts leave the "
      "hydrodynamic branch, gamma_dot_c ~ C eta_f I_c^2/(s_c rho_p R^2), with I_c and C "
      "measured on our flow curves (data/jamming/onsets.csv). With --grid: the "
      "phase diagram over (mu0, phi).");
  args.s_c = friction_defaults::kSc;
  auto* mu0 = p->add_option_function<double>(
      "--mu0",
      [&args](double v) {
        args.mu0 = v;
        args.mu0_given = true;
      },
      "boundary-lubricated friction coefficient (>= 0)");
  auto* phi = p->add_option_function<double>(
      "--phi",
      [&args](double v) {
        args.phi = v;
        args.phi_given = true;
      },
      "solid volume fraction, in (0, 0.74)");
  p->add_option("--s-c", args.s_c,
                "critical Sommerfeld number of the Stribeck law, for the onset scale (> 0)")
      ->capture_default_str();
  p->add_flag("--json", args.json, "print the prediction as JSON");
  p->add_option("--table", args.table,
                "CSV with columns mu0, phi_max, phi_max_err (default: the built-in table, "
                "data/jamming/phi_max_bl.csv)")
      ->check(CLI::ExistingFile);
  p->add_option("--bulk-table", args.bulk_table,
                "CSV of flow states measured in bulk (columns mu0, phi_bulk, regime = "
                "cst|dst|jammed, max_lambda, jam_lambda, cell, source, sample; optional "
                "dst_evidence = jammed|rate_falls|rate_not_increasing|n_above_cap and "
                "fall_lambda), asked before the "
                "sediment table; 'none': the sediment table alone (default: the built-in "
                "data/jamming/bulk_flow_states.csv)");
  auto* grid = p->add_flag("--grid", args.grid,
                           "the regime over mu0 0-1 and phi 0.50-0.66: DIR/phase_diagram.csv "
                           "and its plot (PNG, SVG)");
  grid->excludes(mu0)->excludes(phi);
  auto* model = p->add_option("--model", args.model,
                              "answer from a Wyart-Cates fit (the wyart_cates.json of `dilatant "
                              "analyze --model wyart-cates`) instead of the table: the regime at "
                              "--phi (cst, dst, shear_jamming, no_flow) and, with --stress, the "
                              "state of the stress-controlled flow there")
                    ->check(CLI::ExistingFile);
  model->excludes(grid)->excludes(mu0)->excludes("--table")->excludes("--bulk-table");
  p->add_option("--sample", args.sample, "--model: the fitted sample (default: the only one)")
      ->needs(model);
  p->add_option_function<double>(
       "--stress",
       [&args](double v) {
         args.stress = v;
         args.stress_given = true;
       },
       "--model: the imposed shear stress, in the fit's units (> 0)")
      ->needs(model);
  p->add_option("-o,--out", args.out, "--grid's output folder (default: out/predict)");
  p->add_flag("--no-plots", args.no_plots, "--grid: write the table only, no plot");
  p->add_option("--python", args.python, "Python with matplotlib that draws the plot")
      ->capture_default_str();
  return p;
}

namespace {

analysis::JammingTable load_table(const std::string& file) {
  return file.empty() ? analysis::JammingTable::builtin() : analysis::JammingTable::read(file);
}

std::optional<analysis::BulkFlowTable> load_bulk_table(const std::string& file) {
  if (file == "none") return std::nullopt;
  return file.empty() ? analysis::BulkFlowTable::builtin() : analysis::BulkFlowTable::read(file);
}

const analysis::BulkFlowTable* bulk_or_null(const std::optional<analysis::BulkFlowTable>& t) {
  return t ? &*t : nullptr;
}

int draw_grid(const PredictCommandArgs& args) {
  const std::filesystem::path out = args.out.empty() ? "out/predict" : args.out;
  prepare_output_folder(out);
  const auto bulk = load_bulk_table(args.bulk_table);
  write_file_atomically(
      out / "phase_diagram.csv",
      analysis::phase_diagram_csv(load_table(args.table), bulk_or_null(bulk), {}));
  if (!args.no_plots) {
    const std::string failure = run_plot_script(args.python, plot_script("phase_diagram.py"), out);
    if (!failure.empty())
      std::cerr << fmt::format("dilatant: plot skipped ({}); phase_diagram.csv is complete\n",
                               failure);
  }
  std::cout << fmt::format("phase diagram: {}\n", (out / "phase_diagram.csv").string());
  return 0;
}

std::string or_none(const nlohmann::ordered_json& v, const char* format) {
  return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : std::string("-");
}

int predict_from_model(const PredictCommandArgs& args) {
  if (!args.phi_given) throw InputError("predict --model needs --phi");
  if (!(args.phi > 0.0 && args.phi < 1.0))
    throw InputError(fmt::format("--phi {}: must be in (0, 1)", args.phi));
  if (args.stress_given && !(args.stress > 0.0 && std::isfinite(args.stress)))
    throw InputError(fmt::format("--stress {}: must be a finite number > 0", args.stress));
  const auto fit = analysis::read_fitted_wyart_cates(args.model, args.sample);
  const auto j = analysis::wyart_cates_prediction(
      fit, args.phi, args.stress_given ? std::optional(args.stress) : std::nullopt);
  if (args.json) {
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << fmt::format(
      "{} ({}phi {} against phi_DST = {} +- {}, phi_m = {} +- {}, phi_0 = {} +- {}{}; source: "
      "Wyart-Cates fit {}, sample {})\n",
      j["regime"].get<std::string>(), fit.phi_basis == "bulk" ? "bulk " : "", args.phi,
      or_none(j["phi_dst"], "{:.4f}"), or_none(j["phi_dst_err"], "{:.2g}"),
      or_none(j["phi_m"], "{:.4f}"), or_none(j["phi_m_err"], "{:.2g}"),
      or_none(j["phi_0"], "{:.4f}"), or_none(j["phi_0_err"], "{:.2g}"),
      j["uncertain"].get<bool>() ? fmt::format("; within {:.1f} sigma of a boundary: uncertain",
                                               j["margin_sigma"].get<double>())
                                 : "",
      fit.file, fit.sample);
  if (j["turning_range"].is_array())
    std::cout << fmt::format(
        "the stress-controlled flow curve turns back (DST) between sigma {:.4g} "
        "and {:.4g}\n",
        j["turning_range"][0].get<double>(), j["turning_range"][1].get<double>());
  if (j["shear_jamming_stress"].is_number())
    std::cout << fmt::format("shear jamming above sigma {:.4g}\n",
                             j["shear_jamming_stress"].get<double>());
  if (args.stress_given)
    std::cout << fmt::format("at sigma {}: {} (eta {}, gamma_dot {}, f {:.3g}, phi_J {:.4f})\n",
                             args.stress, j["state"].get<std::string>(),
                             or_none(j["viscosity"], "{:.4g}"), or_none(j["shear_rate"], "{:.4g}"),
                             j["frictional_fraction"].get<double>(), j["phi_j"].get<double>());
  return 0;
}

}  // namespace

int execute_predict_command(const PredictCommandArgs& args) {
  if (!args.model.empty()) return predict_from_model(args);
  if (!(args.s_c > 0.0) || !std::isfinite(args.s_c))
    throw InputError(fmt::format("--s-c {}: must be a finite number > 0", args.s_c));
  if (args.grid) return draw_grid(args);
  if (!args.mu0_given || !args.phi_given)
    throw InputError(
        "predict needs --mu0 and --phi (or --grid for the whole diagram, or --model FILE and "
        "--phi)");
  analysis::check_prediction_input(args.mu0, args.phi, args.s_c);  // before the table is read
  const auto table = load_table(args.table);
  const auto bulk = load_bulk_table(args.bulk_table);
  const auto report = analysis::predict(table, bulk_or_null(bulk), args.mu0, args.phi, args.s_c);
  const std::string table_name = args.table.empty() ? "built-in" : args.table;
  if (args.json) {
    std::cout << analysis::prediction_json(report, table_name).dump(2) << "\n";
    return 0;
  }
  const auto& p = report.regime;
  const auto& onset = report.onset;
  const std::string sediment = fmt::format(
      "phi {} against phi_max_BL({}) = {:.4f} +- {:.4f} and phi_RCP = {:.4f} +- {:.4f}", args.phi,
      args.mu0, p.phi_max_bl.value, p.phi_max_bl.error, p.phi_rcp.value, p.phi_rcp.error);
  if (report.source() == analysis::RegimeSource::BulkFlowCurves)
    std::cout << fmt::format("{} (measured in bulk; the sediment table alone would say {}: {})\n",
                             analysis::flow_regime_name(report.answer()),
                             analysis::flow_regime_name(p.regime), sediment);
  else
    std::cout << fmt::format(
        "{} ({}{})\n", analysis::flow_regime_name(p.regime), sediment,
        p.uncertain ? fmt::format("; within {:.1f} sigma of a boundary: uncertain", p.margin_sigma)
                    : "");
  std::cout << fmt::format("source: {}\n", analysis::source_detail(report, table_name));
  if (onset.available && onset.too_far)
    std::cout << fmt::format("frictional onset: not given ({}; docs/jamming.md)\n",
                             analysis::onset_withheld(onset, args.phi));
  else if (onset.available)
    std::cout << fmt::format(
        "frictional onset (contacts leave the hydrodynamic branch): gamma_dot_c ~ C I_c^2/s_c = "
        "{:.3g} eta_f/(rho_p R^2) at s_c {:g}, {:.3g}-{:.3g} over {} curve(s) (I_c {:.3g} and C "
        "{:.3g} measured at mu0 {}, phi_bulk {:.3f}, s_c {:g}, {} model; I_c^2/s_c alone is "
        "{:.3g}; docs/jamming.md)\n",
        onset.rate, args.s_c, onset.rate_low, onset.rate_high, onset.measured.size(),
        onset.inertial_number, onset.prefactor, onset.mu0, onset.phi_bulk,
        onset.measured.front().s_c, onset.measured.front().model, onset.scale);
  if (report.mu0_beyond_table())
    std::cout << fmt::format(
        "note: mu0 {} is beyond the table's last point ({}); its value is "
        "used\n",
        args.mu0, report.mu0_table_max);
  return 0;
}

}  // namespace dilatant
