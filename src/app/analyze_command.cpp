#include "app/analyze_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "analysis/analysis.hpp"
#include "analysis/analysis_input.hpp"
#include "analysis/report_files.hpp"
#include "analysis/rheometer_file.hpp"
#include "app/python_script.hpp"
#include "io/input_error.hpp"

namespace dilatant {

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
  const analysis::AnalysisReport report =
      analysis::analyse(analysis::load_analysis_input(input), args.settings);
  analysis::write_report_files(report, out);
  if (!args.no_plots) {
    const std::string script =
        args.plot_script.empty() ? plot_script("analysis.py") : args.plot_script;
    const std::string failure = run_plot_script(args.python, script, out);
    if (!failure.empty())
      std::cerr << fmt::format(
          "dilatant: plots skipped ({}); curves.csv, points.csv and fits.json are complete\n",
          failure);
  }
  if (!args.quiet) print_summary(report, out);
  return 0;
}

}  // namespace dilatant
