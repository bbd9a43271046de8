// dilatant: the command-line front end. A thin layer: it parses arguments with
// CLI11 and calls the library; it owns the exit codes (README "Using it"):
//   0 success, 2 bad input (one line naming file, key and problem), 1 other failure.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <exception>
#include <iostream>
#include <string_view>

#include "app/analyze_command.hpp"
#include "app/jam_command.hpp"
#include "app/plot_command.hpp"
#include "app/predict_command.hpp"
#include "app/run_command.hpp"
#include "app/sweep_command.hpp"
#include "dilatant/version.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "dilatant: Contact Dynamics simulation of dense non-Brownian suspensions that "
      "shear-thicken (Fernandez et al., PRL 111, 108301, 2013)."};
  app.set_version_flag("--version", dilatant::kVersion);
  app.require_subcommand(1);
  dilatant::RunCommandArgs run_args;
  CLI::App* run = dilatant::add_run_command(app, run_args);
  dilatant::SweepCommandArgs sweep_args;
  CLI::App* sweep = dilatant::add_sweep_command(app, sweep_args);
  dilatant::AnalyzeCommandArgs analyze_args;
  CLI::App* analyze = dilatant::add_analyze_command(app, analyze_args);
  dilatant::PlotCommandArgs plot_args;
  CLI::App* plot = dilatant::add_plot_command(app, plot_args);
  dilatant::JamCommandArgs jam_args;
  CLI::App* jam = dilatant::add_jam_command(app, jam_args);
  dilatant::PredictCommandArgs predict_args;
  CLI::App* predict = dilatant::add_predict_command(app, predict_args);

  // A mistyped command is named, with the one meant: CLI11 alone says "A
  // subcommand is required", which misleads when one was given.
  if (argc >= 2 && argv[1][0] != '-') {
    static constexpr std::array<std::string_view, 6> kCommands = {"run",  "sweep", "analyze",
                                                                  "plot", "jam",   "predict"};
    const std::string_view given = argv[1];
    if (std::find(kCommands.begin(), kCommands.end(), given) == kCommands.end()) {
      std::cerr << "dilatant: error: '" << given << "' is not a command"
                << dilatant::did_you_mean(given, kCommands)
                << "; the commands are run, sweep, analyze, plot, jam and predict (see dilatant "
                   "--help)\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "dilatant: error: " << e.what() << " (see dilatant --help)\n";
    return 2;
  }
  try {
    if (run->parsed()) return dilatant::execute_run_command(run_args);
    if (sweep->parsed()) return dilatant::execute_sweep_command(sweep_args);
    if (analyze->parsed()) return dilatant::execute_analyze_command(analyze_args);
    if (plot->parsed()) return dilatant::execute_plot_command(plot_args);
    if (jam->parsed()) return dilatant::execute_jam_command(jam_args);
    if (predict->parsed()) return dilatant::execute_predict_command(predict_args);
  } catch (const dilatant::InputError& e) {
    std::cerr << "dilatant: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "dilatant: failed: " << e.what() << "\n";
    return 1;
  }
  return 1;
}
