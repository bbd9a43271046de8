// dilatant-solve-step: solves the contact problem of dumped steps again
// (dilatant run --dump-steps, drivers/step_dumps.hpp) with the solver settings
// given, and prints each method's work against the residual of the contact
// problem after every pass. The benchmark set of the contact-solve plan
// (docs/contact-solve-plan.md, "Step problems on disk").
//
//   dilatant-solve-step DUMP_DIR [--set solver.relaxation=1.0 ...] [--step FILE ...]
//                       [--targets 1e-2,1e-3] [--csv OUT.csv]
//
// Work is counted in sweep-equivalents: local solves over the contacts the
// step detected. The residual is solver/contact_residual.hpp's, computed after
// every pass by the observer (not counted as work). One line per step: the
// passes and work of the solve, the residual it ended with, the loaded
// contacts' RMS impulse in the residual's unit (P_ref), the halvings a redo
// took (solver.redo_unconverged), and the work at which the residual of the
// attempt that was kept first fell to each target (- if never).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/shear_cell.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace {

using namespace dilatant;

struct PassRow {
  int pass = 0;
  double work = 0.0;  // sweep-equivalents so far
  ContactResidual residual;
};

std::vector<std::filesystem::path> steps_of(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::istringstream index(read_input_file(dir / "index.csv", "dump index"));
  std::string line;
  std::getline(index, line);  // header
  while (std::getline(index, line))
    if (!trim(line).empty())
      files.push_back(dir / std::string(trim(line.substr(0, line.find(',')))));
  return files;
}

std::vector<double> targets_of(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  for (std::string t; std::getline(in, t, ',');) {
    try {
      out.push_back(std::stod(t));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--targets: '{}' is not a number", t));
    }
  }
  return out;
}

int run(const std::filesystem::path& dir, const std::vector<std::string>& overrides,
        std::vector<std::filesystem::path> files, const std::vector<double>& targets,
        const std::string& csv_path) {
  const Config config = load_config(dir / "config.toml", overrides);
  if (files.empty()) files = steps_of(dir);
  std::string csv =
      "file,pass,sweep_equivalents,residual_max,residual_normal_rms,residual_tangential_rms\n";
  std::cout << "file  passes  sweep_equivalents  residual_max  typical_impulse  converged  redos";
  for (double t : targets) std::cout << fmt::format("  SE_to_{:g}", t);
  std::cout << "\n";
  for (const auto& file : files) {
    ShearCell cell = ShearCell::resumed(config, file);
    std::vector<PassRow> rows;
    double contacts = 0.0;
    cell.set_pass_observer([&](const ContactProblem& problem, int passes, double visits) {
      contacts = static_cast<double>(problem.contacts.size());
      rows.push_back({passes, contacts > 0.0 ? visits / contacts : 0.0, contact_residual(problem)});
    });
    // With solver.redo_unconverged a step that fails even at 1/64 of its
    // length throws: reported as such, and the next file is solved.
    StepReport report;
    try {
      report = cell.step();
    } catch (const SolveFailure& e) {
      std::cout << file.filename().string() << "  failed: " << e.what() << "\n";
      continue;
    }
    // The work of undone attempts (solver.redo_unconverged) is counted too.
    std::string line = fmt::format(
        "{}  {}  {:.1f}  {:.3g}  {:.3g}  {}  {}", file.filename().string(), report.solve.iterations,
        (rows.empty() ? 0.0 : rows.back().work) + report.redone_sweep_equivalents,
        report.contact_residual.max(), report.contact_residual.typical_impulse,
        report.solve.converged, report.redos);
    for (double t : targets) {
      std::string reached = "-";
      for (const PassRow& r : rows)
        if (r.residual.max() <= t) {
          reached = fmt::format("{:.1f}", r.work);
          break;
        }
      line += "  " + reached;
    }
    std::cout << line << "\n";
    for (const PassRow& r : rows)
      csv += fmt::format("{},{},{},{},{},{}\n", file.filename().string(), r.pass, r.work,
                         r.residual.max(), r.residual.normal_rms, r.residual.tangential_rms);
  }
  if (!csv_path.empty()) write_file_atomically(csv_path, csv);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Solve dumped step problems again and print work against residual"};
  std::string dir, csv, targets = "1e-2,1e-3";
  std::vector<std::string> overrides, steps;
  app.add_option("dump_dir", dir, "A folder written by dilatant run --dump-steps")
      ->required()
      ->check(CLI::ExistingDirectory);
  app.add_option("-s,--set", overrides, "Override a config key (solver.*), as dilatant run");
  app.add_option("--step", steps, "Only these step files (default: every one in index.csv)");
  app.add_option("--targets", targets, "Residuals to report the work to reach (comma-separated)");
  app.add_option("--csv", csv, "Write every pass's work and residual here");
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<std::filesystem::path> files(steps.begin(), steps.end());
    return run(dir, overrides, files, targets_of(targets), csv);
  } catch (const InputError& e) {
    std::cerr << "dilatant-solve-step: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "dilatant-solve-step: " << e.what() << "\n";
    return 1;
  }
}
