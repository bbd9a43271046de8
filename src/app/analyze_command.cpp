#include "app/analyze_command.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <utility>

#include "analysis/analysis.hpp"
#include "analysis/analysis_input.hpp"
#include "analysis/report_files.hpp"
#include "analysis/rheometer_file.hpp"
#include "analysis/wyart_cates_report.hpp"
#include "app/python_script.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace dilatant {

namespace {

// A choice's names (analysis::ChoiceName) as CLI::CheckedTransformer reads them.
template <class Choice, std::size_t N>
std::map<std::string, Choice> choice_map(const std::array<analysis::ChoiceName<Choice>, N>& names) {
  std::map<std::string, Choice> map;
  for (const analysis::ChoiceName<Choice>& c : names) map.emplace(c.name, c.value);
  return map;
}

}  // namespace

CLI::App* add_analyze_command(CLI::App& app, AnalyzeCommandArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "analyze",
      "Rheometer analysis (paper Fig. 3): per flow curve the Newtonian viscosity, the onset of "
      "thickening, the Ostwald-de Waele exponent n (eta ~ gamma_dot^n) with its confidence "
      "interval and the regime (newtonian, cst, dst, jammed); per sample the fit "
      "n - 1 = A x^-alpha, x = (phi_max - phi)/phi_max, phi_max given or fitted; the "
      "master-curve collapse of all samples. INPUT is a manifest (TOML: [[curve]] file, "
      "sample, phi; [samples.NAME] phi_max) or a sweep's flowcurves.csv (curves by phi and "
      "mu0, or by phi and its sample column). Writes curves.csv, points.csv, fits.json and "
      "plots (PNG, SVG) to --out. See docs/analysis.md.");
  cmd->add_option("input", args.input, "Manifest (.toml) or flowcurves.csv")
      ->check(CLI::ExistingFile);
  cmd->add_option("--list", args.list,
                  "Show the steps of a rheometer export (number, kind, rows, points, lines, "
                  "name) and exit; a manifest's step = N or \"name\" chooses among them")
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--out", args.out, "Output folder (default: out/analysis/<input name>)");
  cmd->add_flag("--no-plots", args.no_plots, "Write the tables only, no plots");
  cmd->add_flag("-q,--quiet", args.quiet, "No summary on stdout");
  cmd->add_option("--python", args.python, "Python with matplotlib that draws the plots")
      ->capture_default_str();
  cmd->add_option("--plot-script", args.plot_script,
                  "The plotting script (default: dilatant/plots/analysis.py of the installed "
                  "package, else of this source tree)");
  auto& s = args.settings;
  cmd->add_option("--onset-factor", s.onset_factor,
                  "Thickening starts where eta exceeds this x the Newtonian viscosity (> 1)")
      ->capture_default_str();
  cmd->add_option("--dst-n-cap", s.dst_n_cap, "A curve with n above this counts as DST (> 0)")
      ->capture_default_str();
  cmd->add_option("--min-window-points", s.min_window_points,
                  "Points the automatic thickening window starts from (>= 3)")
      ->capture_default_str();
  cmd->add_option("--confidence", s.confidence, "Level of the intervals n_low..n_high, in (0, 1)")
      ->capture_default_str();
  auto& wc = args.wyart_cates;
  auto* model = cmd->add_option("--model", args.model,
                                "Also fit a model of thickening to the flow curves of each "
                                "sample at several phi: wyart-cates (phi_0, phi_m, sigma*, A; "
                                "writes wyart_cates.json, the overlay and the flow-state map)")
                    ->check(CLI::IsMember({"wyart-cates"}));
  cmd->add_option("--alpha", wc.alpha,
                  "Wyart-Cates: exponent of eta = A (1 - phi/phi_J)^-alpha, held (or the start "
                  "with --fit-alpha; > 0)")
      ->capture_default_str()
      ->needs(model);
  cmd->add_option("--beta", wc.beta,
                  "Wyart-Cates: exponent of f = exp(-(sigma*/sigma)^beta), held (or the start "
                  "with --fit-beta; > 0)")
      ->capture_default_str()
      ->needs(model);
  cmd->add_option("--wc-phi", wc.phi,
                  "Wyart-Cates: the volume fraction fitted: bulk (each point's measured "
                  "phi_bulk, of a sweep table), nominal (the curve's phi), or auto (bulk when "
                  "every fitted point has one)")
      ->transform(CLI::CheckedTransformer(choice_map(analysis::kPhiBasisNames), CLI::ignore_case))
      ->default_str(analysis::phi_basis_name(wc.phi))
      ->needs(model);
  cmd->add_option("--wc-weights", wc.weights,
                  "Wyart-Cates: the residuals' weights: auto (the rate errors when every point "
                  "has one), uniform, or errors (each point's error of eta: gamma_dot_err, or "
                  "eta_err at an imposed rate)")
      ->transform(CLI::CheckedTransformer(choice_map(analysis::kWeightsNames), CLI::ignore_case))
      ->default_str(analysis::weights_name(wc.weights))
      ->needs(model);
  cmd->add_flag("--fit-alpha", wc.fit_alpha, "Wyart-Cates: fit alpha too")->needs(model);
  cmd->add_flag("--fit-beta", wc.fit_beta, "Wyart-Cates: fit beta too")->needs(model);
  return cmd;
}

namespace {

void check_settings(const analysis::AnalysisSettings& s) {
  auto fail = [](std::string_view option, double value, std::string_view what) {
    throw InputError(fmt::format("{} = {}: {}", option, value, what));
  };
  if (!(s.onset_factor > 1.0)) fail("--onset-factor", s.onset_factor, "must be > 1");
  if (!(s.dst_n_cap > 0.0)) fail("--dst-n-cap", s.dst_n_cap, "must be > 0");
  if (s.min_window_points < 3) fail("--min-window-points", s.min_window_points, "must be >= 3");
  if (!(s.confidence > 0.0 && s.confidence < 1.0))
    fail("--confidence", s.confidence, "must be in (0, 1)");
}

void check_model_settings(const analysis::WyartCatesSettings& s) {
  for (const auto& [option, value] : {std::pair{"--alpha", s.alpha}, std::pair{"--beta", s.beta}})
    if (!(value > 0.0 && value < 20.0))
      throw InputError(fmt::format("{} = {}: must be in (0, 20)", option, value));
}

std::string with_error(const analysis::Estimate& e, const char* format) {
  const std::string value = fmt::format(fmt::runtime(format), e.value);
  if (!std::isfinite(e.err)) return value;
  return value + " ± " + fmt::format("{:.2g}", e.err);
}

void print_summary(const analysis::AnalysisReport& r, const std::filesystem::path& out) {
  std::cout << fmt::format("dilatant: analysed {} flow curves of {} samples; results in {}\n",
                           r.curves.size(), r.samples.size(), out.string());
  // Dropped rows are said where the user looks, not only in fits.json.
  for (const auto& d : r.input.dropped) std::cout << "  " << d << "\n";
  for (const auto& d : r.input.skipped_steps) std::cout << "  skipped: " << d << "\n";
  std::cout << fmt::format("  {:<12} {:>6} {:>4} {:>4}  {:<22} {:<18} {:<16}\n", "sample", "curves",
                           "cst", "dst", "phi_max", "A", "alpha");
  for (const auto& s : r.samples) {
    std::string phi_max = "-", a = "-", alpha = "-";
    if (const auto& f = s.fit.fit) {
      phi_max = s.phi_max_given ? fmt::format("{} (given)", *s.phi_max_given)
                                : with_error(f->phi_max[0], "{:.4f}");
      a = with_error(f->A, "{:.3g}");
      alpha = with_error(f->alpha, "{:.3g}");
    } else if (s.phi_max_given) {
      phi_max = fmt::format("{} (given)", *s.phi_max_given);
    }
    std::cout << fmt::format("  {:<12} {:>6} {:>4} {:>4}  {:<22} {:<18} {:<16}\n", s.sample,
                             s.curves, s.cst_curves, s.dst_curves, phi_max, a, alpha);
  }
  if (const auto& f = r.collapse.fit.fit) {
    std::cout << fmt::format(
        "  collapse of {} samples: A = {}, alpha = {}, chi2/dof = {:.3g}, rms deviation "
        "{:.3g} decades\n",
        r.collapse.samples.size(), with_error(f->A, "{:.3g}"), with_error(f->alpha, "{:.3g}"),
        f->chi2_per_dof(), f->rms_log10_deviation);
  } else {
    std::cout << fmt::format("  no collapse: {}\n", r.collapse.fit.why_not);
  }
}

// The seeds' own fits: mean +- standard error (n seeds with a value) per
// quantity; "-" where none had one.
std::string seed_spread_text(const std::vector<analysis::SeedSpread>& spreads) {
  std::string text;
  for (const auto& q : spreads) {
    text += text.empty() ? "" : ", ";
    if (q.n == 0) {
      text += q.name + " -";
    } else if (q.n == 1) {
      text += fmt::format("{} {:.4g} (n=1)", q.name, q.mean);
    } else {
      text += fmt::format("{} {} (n={})", q.name, with_error({q.mean, q.sem}, "{:.4g}"), q.n);
    }
  }
  return text + " (mean +- standard error)";
}

void print_model_summary(const analysis::WyartCatesReport& r) {
  const auto& st = r.settings;
  std::cout << fmt::format("  Wyart-Cates fit (alpha {}, beta {}):\n",
                           st.fit_alpha ? "fitted" : fmt::format("{:g} fixed", st.alpha),
                           st.fit_beta ? "fitted" : fmt::format("{:g} fixed", st.beta));
  for (const auto& s : r.samples) {
    const auto& f = s.outcome.fit;
    if (!f) {
      std::cout << fmt::format("    {}: no fit: {}\n", s.sample, s.outcome.why_not);
      if (!s.members.empty())
        std::cout << fmt::format("      its {} seeds' own fits: {}\n", s.members.size(),
                                 seed_spread_text(s.seed_spreads));
      continue;
    }
    std::string exponents;
    if (st.fit_alpha) exponents += ", alpha = " + with_error(f->alpha, "{:.3g}");
    if (st.fit_beta) exponents += ", beta = " + with_error(f->beta, "{:.3g}");
    std::cout << fmt::format(
        "    {}: phi_0 = {}, phi_m = {}, sigma* = {}, A = {}{}, chi2/dof = {:.3g}; DST from phi "
        "{}, shear jamming from phi_m; phi {}\n",
        s.sample, with_error(f->phi_0, "{:.4f}"), with_error(f->phi_m, "{:.4f}"),
        with_error(f->sigma_star, "{:.4g}"), with_error(f->A, "{:.4g}"), exponents,
        f->chi2_per_dof(), with_error({s.onset.phi, s.onset_phi_err}, "{:.4f}"),
        f->phi_bulk ? "is each point's measured phi_bulk" : "is each curve's nominal phi");
    if (s.members.empty()) continue;
    std::cout << fmt::format("      the {} seeds pooled; their own fits: {}\n", s.members.size(),
                             seed_spread_text(s.seed_spreads));
  }
}

// Why the fit was asked for and none came out: every sample's reason, in one line.
std::string no_fit_reason(const analysis::WyartCatesReport& r) {
  std::string why;
  for (const auto& s : r.samples)
    why += fmt::format("{}{}: {}", why.empty() ? "" : "; ", s.sample, s.outcome.why_not);
  return "--model wyart-cates: no sample could be fitted (" + why + ")";
}

}  // namespace

int execute_analyze_command(const AnalyzeCommandArgs& args) {
  if (!args.list.empty()) {
    if (!args.input.empty())
      throw InputError("dilatant analyze: give either INPUT or --list FILE, not both");
    std::cout << analysis::step_listing(analysis::read_rheometer_file(args.list));
    return 0;
  }
  if (args.input.empty())
    throw InputError("dilatant analyze: INPUT is required (a manifest or a flowcurves.csv)");
  check_settings(args.settings);
  const std::filesystem::path input(args.input);
  const std::filesystem::path out = args.out.empty()
                                        ? std::filesystem::path("out") / "analysis" / input.stem()
                                        : std::filesystem::path(args.out);
  analysis::AnalysisInput data = analysis::load_analysis_input(input);
  // The model is fitted before anything is written: a fit that was asked for
  // and is impossible is bad input, and leaves no half-finished folder.
  std::optional<analysis::WyartCatesReport> model;
  if (!args.model.empty()) {
    check_model_settings(args.wyart_cates);
    model = analysis::wyart_cates_report(data, args.wyart_cates);
    if (!model->any_fit()) throw InputError(no_fit_reason(*model));
  }
  const analysis::AnalysisReport report = analysis::analyse(std::move(data), args.settings);
  analysis::write_report_files(report, out);
  if (model)
    analysis::write_wyart_cates_files(*model, out);
  else
    analysis::remove_wyart_cates_files(out);
  if (!args.no_plots) {
    const std::string script =
        args.plot_script.empty() ? plot_script("analysis.py") : args.plot_script;
    const std::string failure = run_plot_script(args.python, script, out);
    if (!failure.empty())
      std::cerr << fmt::format(
          "dilatant: plots skipped ({}); curves.csv, points.csv and fits.json are complete\n",
          failure);
  }
  if (!args.quiet) {
    print_summary(report, out);
    if (model) print_model_summary(*model);
  }
  return 0;
}

}  // namespace dilatant
