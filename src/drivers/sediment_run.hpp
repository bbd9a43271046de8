#pragma once
// `dilatant jam`: the sedimentation of a [sediment] config (drivers/sediment.hpp),
// sample after sample, into OUT: config.toml (resolved), samples.csv (one row
// per packing) and summary.json (phi_max, its error from the samples' scatter,
// the fraction's sensitivity to the exclusion), each written whole or not at all,
// and checkpoint.bin (drivers/sediment_checkpoint.hpp). samples.csv and the
// checkpoint are written after every sample: a stopped run (Ctrl-C) keeps the
// samples it finished, and resumed, runs the rest; a finished run resumed
// with a larger sediment.samples adds samples.
#include <atomic>
#include <string>

#include "drivers/run_options.hpp"
#include "drivers/sediment.hpp"
#include "io/config.hpp"

namespace dilatant {

// The driver's settings for sample `index` (seed + index) of a [sediment] config.
SedimentSettings sediment_settings(const Config& config, int index);

struct SedimentOutcome {
  double phi_max = 0.0;
  double phi_max_err = 0.0;  // standard error over the samples; 0 with one sample
  bool settled = false;      // every sample
  long steps = 0;
  long unconverged_steps = 0;
  bool interrupted = false;  // stopped before its last sample settled
};

struct SedimentRunOptions {
  RunOptions run;
  // Continue the run in run.out_dir from its checkpoint (none there: start
  // anew; the CLI refuses that case first).
  bool resume = false;
  // Once set (Ctrl-C, Python), the running sample is abandoned and the run
  // returns interrupted with the samples it finished.
  const std::atomic<bool>* stop_requested = nullptr;
  // If set, gets the fraction of sediment.samples finished after every sample.
  std::atomic<double>* progress = nullptr;
};

SedimentOutcome run_sediment(const Config& config, const SedimentRunOptions& options);

// "phi_max = 0.5612 +- 0.0040" over several samples; over one, which has no
// error bar (summary.json has none), "phi_max = 0.5612 (one sample: no error
// bar)" rather than a "+- 0.0000" that reads as an exact result.
std::string phi_max_text(const SedimentOutcome& outcome, int samples);

}  // namespace dilatant
