#include "app/jam_command.hpp"

#include <fmt/format.h>

#include <iostream>

#include "app/stop_request.hpp"
#include "drivers/model_setup.hpp"
#include "drivers/sediment_run.hpp"
#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"

namespace dilatant {

CLI::App* add_jam_command(CLI::App& app, JamCommandArgs& args) {
  CLI::App* jam = app.add_subcommand(
      "jam",
      "Simulated centrifugation: a suspension at phi 0.47 settles under gravity with Coulomb "
      "friction mu0 until it stops; the sediment's bulk fraction is the jamming fraction "
      "phi_max of that friction (docs/jamming.md). CONFIG is a TOML file with a [sediment] "
      "table; without it, the built-in one (mu0 from --set friction.mu0=...). Results go to "
      "--out: config.toml, samples.csv, summary.json, checkpoint.bin (after every sample: "
      "Ctrl-C keeps the samples finished, --resume runs the rest).");
  jam->add_option("config", args.config, "TOML configuration file with [sediment]")
      ->check(CLI::ExistingFile);
  jam->add_option("-o,--out", args.out, "Output folder (default: out/jam or out/<config name>)");
  jam->add_option("-s,--set", args.overrides,
                  "Override a config key, e.g. friction.mu0=0.4, sediment.samples=5 (repeatable)")
      ->allow_extra_args(false);
  jam->add_flag("-q,--quiet", args.quiet, "No progress or final messages");
  jam->add_flag("--resume", args.resume,
                "Continue the run in OUT from its checkpoint.bin (same config; a larger "
                "sediment.samples adds samples to a finished run): the samples it finished are "
                "kept, the rest run");
  return jam;
}

// The built-in [sediment]: every default (the solver's residual in units of a
// grain's weight impulse, drivers/model_setup.hpp weight_force()).
constexpr const char* kBuiltInSediment = "[sediment]\n";

int execute_jam_command(const JamCommandArgs& args) {
  const Config config = args.config.empty()
                            ? parse_config(kBuiltInSediment, "<built-in>",
                                           std::filesystem::current_path(), args.overrides)
                            : load_config(args.config, args.overrides);
  if (config.sediment() == nullptr)
    throw InputError(
        fmt::format("{}: dilatant jam needs a [sediment] table (a [cell] or "
                    "[scene] config is run by dilatant run)",
                    config.source));
  if (const std::string cap = thread_cap_warning(config.solver); !cap.empty())
    std::cerr << cap << "\n";
  RunOptions options;
  options.quiet = args.quiet;
  options.out_dir =
      args.out.empty()
          ? std::filesystem::path("out") /
                (args.config.empty() ? std::string("jam")
                                     : std::filesystem::path(args.config).stem().string())
          : std::filesystem::path(args.out);
  if (args.resume) require_checkpoint_to_resume(options.out_dir);
  // SIGINT/SIGTERM: abandon the running sample, keep the finished ones.
  const SedimentOutcome outcome = run_sediment(config, {options, args.resume, stop_on_interrupt()});
  if (outcome.interrupted) {
    std::cerr << fmt::format(
        "dilatant: interrupted; the samples finished are in {}; continue with --resume\n",
        (options.out_dir / "checkpoint.bin").string());
    return 1;
  }
  if (!args.quiet)
    std::cout << fmt::format("dilatant: {} (mu0 {}){}; results in {}\n",
                             phi_max_text(outcome, config.sediment()->samples), config.friction.mu0,
                             outcome.settled ? "" : ", NOT every sample settled",
                             options.out_dir.string());
  if (outcome.unconverged_steps > 0)
    std::cerr << fmt::format(
        "dilatant: warning: {} of {} steps did not converge within solver.max_iterations = {}\n",
        outcome.unconverged_steps, outcome.steps, config.solver.max_iterations);
  return 0;
}

}  // namespace dilatant
