#include "drivers/sediment_run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "dilatant/version.hpp"
#include "drivers/model_setup.hpp"
#include "drivers/sediment_checkpoint.hpp"
#include "io/atomic_file.hpp"
#include "io/config_compare.hpp"
#include "io/folder_lock.hpp"
#include "io/input_error.hpp"
#include "io/output_folder.hpp"
#include "measure/run_cost.hpp"
#include "measure/sample_mean.hpp"

namespace dilatant {

namespace {

// Exclusions (R) the fraction is also reported at, to show how much it depends
// on the choice.
constexpr double kExclusions[] = {2.0, 3.0, 4.0, 6.0};

using Sample = SedimentSample;

// The sediment's fraction over its samples; with one sample the error is
// unknown: 0 here, null in summary.json.
struct MeanError {
  double mean = 0.0, error = 0.0;
};

MeanError mean_error(const std::vector<double>& x) {
  const SampleMean m = sample_mean(x);
  return {x.empty() ? 0.0 : m.mean, x.size() < 2 ? 0.0 : m.sem};
}

// The sample, or nothing if `stop` was set before it settled.
std::optional<Sample> run_sample(const Config& config, int index, bool progress,
                                 const std::atomic<bool>* stop) {
  Sediment sediment(sediment_settings(config, index));
  Sample s;
  s.seed = config.sediment()->seed + index;
  s.spheres = sediment.world().bodies.size();
  auto last = std::chrono::steady_clock::now();
  while (!sediment.settled() && !sediment.timed_out()) {
    const StepReport& r = sediment.step();
    if (!r.solve.converged) ++s.unconverged;
    if (stop != nullptr && stop->load()) {
      if (progress) std::cerr << "\n";
      return std::nullopt;
    }
    if (progress && std::chrono::steady_clock::now() - last > std::chrono::milliseconds(500)) {
      // The mean height falls from H/2 towards the sediment's; settling ends
      // when it stops changing.
      std::cerr << fmt::format("\rsample {}/{}: step {}, time {:.0f}, mean height {:.3f} R   ",
                               index + 1, config.sediment()->samples, sediment.steps(),
                               sediment.world().time, sediment.mean_height())
                << std::flush;
      last = std::chrono::steady_clock::now();
    }
  }
  if (progress) std::cerr << "\n";
  s.settled = sediment.settled();
  s.time = sediment.world().time;
  s.steps = sediment.steps();
  s.max_overlap = sediment.max_overlap();
  s.fraction = sediment.measure(config.sediment()->exclusion);
  for (double e : kExclusions) s.phi_at.push_back(sediment.measure(e).phi);
  return s;
}

// The outcome over the finished samples.
SedimentOutcome outcome_of(const std::vector<Sample>& samples) {
  SedimentOutcome out{.settled = true};
  std::vector<double> phi;
  for (const Sample& s : samples) {
    phi.push_back(s.fraction.phi);
    out.settled = out.settled && s.settled;
    out.steps += s.steps;
    out.unconverged_steps += s.unconverged;
  }
  const MeanError m = mean_error(phi);
  out.phi_max = m.mean;
  out.phi_max_err = m.error;
  return out;
}

void write_summary(const Config& config, const std::vector<Sample>& samples,
                   const SedimentOutcome& out, const std::filesystem::path& folder,
                   double wall_time_s) {
  const SedimentConfig& c = *config.sediment();
  double max_overlap = 0.0;
  for (const Sample& s : samples) max_overlap = std::max(max_overlap, s.max_overlap);
  nlohmann::json j;
  j["version"] = kVersion;
  j["mode"] = "sediment";
  j["mu0"] = config.friction.mu0;
  j["phi_max"] = out.phi_max;
  j["phi_max_err"] = samples.size() > 1 ? nlohmann::json(out.phi_max_err) : nlohmann::json(nullptr);
  std::vector<std::int64_t> seeds;
  for (const Sample& s : samples) seeds.push_back(s.seed);
  j["seeds"] = seeds;
  j["settled"] = out.settled;
  j["exclusion"] = c.exclusion;
  nlohmann::json by_exclusion = nlohmann::json::object();
  for (std::size_t k = 0; k < std::size(kExclusions); ++k) {
    std::vector<double> at;
    for (const Sample& s : samples) at.push_back(s.phi_at[k]);
    const MeanError e = mean_error(at);
    by_exclusion[fmt::format("{:g}", kExclusions[k])] = {
        {"phi", e.mean},
        {"err", samples.size() > 1 ? nlohmann::json(e.error) : nlohmann::json(nullptr)}};
  }
  j["phi_by_exclusion"] = by_exclusion;
  j["phi_initial"] = c.phi;
  j["stokes_number"] = c.stokes_number;
  j["size"] = {c.size[0], c.size[1], c.size[2]};
  j["spheres"] = samples.empty() ? 0 : samples.front().spheres;
  j["max_overlap"] = max_overlap;
  j["steps"] = out.steps;
  j["frac_steps_unconverged"] =
      out.steps > 0 ? double(out.unconverged_steps) / double(out.steps) : 0.0;
  j["wall_time_s"] = wall_time_s;
  write_file_atomically(folder / "summary.json", j.dump(2) + "\n");
}

std::string samples_csv(const std::vector<Sample>& samples) {
  std::string csv = "seed,spheres,settled,time,steps,unconverged_steps,max_overlap,surface,top,phi";
  for (double e : kExclusions) csv += fmt::format(",phi_exclusion_{:g}", e);
  csv += "\n";
  for (const Sample& s : samples) {
    csv += fmt::format("{},{},{},{:.10g},{},{},{:.3e},{:.6g},{:.6g},{:.6f}", s.seed, s.spheres,
                       s.settled, s.time, s.steps, s.unconverged, s.max_overlap, s.fraction.surface,
                       s.fraction.top, s.fraction.phi);
    for (double p : s.phi_at) csv += fmt::format(",{:.6f}", p);
    csv += "\n";
  }
  return csv;
}

// The samples a run in `out` finished, checked against this run: the
// configuration it ran with (its config.toml; only sediment.samples may grow).
// Anything that does not fit is bad input naming its file.
std::vector<Sample> resumable_samples(const Config& config, const std::filesystem::path& out) {
  static constexpr std::string_view kExtensible[] = {"sediment.samples"};
  resumable_run_config(out, config, kExtensible, "only sediment.samples may grow");
  std::vector<Sample> samples = load_sediment_checkpoint(out / "checkpoint.bin");
  if (samples.size() > static_cast<std::size_t>(config.sediment()->samples))
    throw InputError(fmt::format(
        "{}: sediment.samples = {} is below the {} samples the run there finished: --resume "
        "adds samples, it cannot remove any",
        (out / "config.toml").string(), config.sediment()->samples, samples.size()));
  return samples;
}

}  // namespace

SedimentOutcome run_sediment(const Config& config, const SedimentRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SedimentConfig& c = *config.sediment();
  const auto& out_dir = options.run.out_dir;
  const auto checkpoint = out_dir / "checkpoint.bin";
  prepare_output_folder(out_dir);
  // Held to the end of the run: a second run on this folder would resume from
  // the same checkpoint and overwrite this one's (io/folder_lock.hpp).
  const FolderLock lock(out_dir, "a sediment run");
  const bool resuming = options.resume && std::filesystem::exists(checkpoint);
  std::vector<Sample> samples;
  if (resuming) {
    samples = resumable_samples(config, out_dir);
    // Nothing left to run: keep the finished run's files as they are.
    if (samples.size() == static_cast<std::size_t>(c.samples) &&
        std::filesystem::exists(out_dir / "summary.json"))
      return outcome_of(samples);
    remove_earlier_results(out_dir, {"summary.json"});
  } else {
    remove_earlier_results(out_dir, {"checkpoint.bin", "samples.csv", "summary.json"});
  }
  write_file_atomically(out_dir / "config.toml", resolved_toml(config));

  const bool quiet = options.run.quiet;
  for (int i = static_cast<int>(samples.size()); i < c.samples; ++i) {
    std::optional<Sample> sample =
        run_sample(config, i, !quiet && isatty(STDERR_FILENO), options.stop_requested);
    if (!sample) {
      SedimentOutcome stopped = outcome_of(samples);
      stopped.interrupted = true;
      return stopped;
    }
    samples.push_back(std::move(*sample));
    // Each finished sample is kept: a stop loses at most the one running.
    save_sediment_checkpoint(checkpoint, samples);
    write_file_atomically(out_dir / "samples.csv", samples_csv(samples));
    if (options.progress != nullptr)
      options.progress->store(static_cast<double>(samples.size()) / c.samples);
    const Sample& s = samples.back();
    if (!quiet)
      std::cout << fmt::format(
          "dilatant: sample {}/{} (seed {}): phi {:.4f}, surface {:.2f} R, {} after {} steps\n",
          i + 1, c.samples, s.seed, s.fraction.phi, s.fraction.surface,
          s.settled ? "settled" : "NOT settled", s.steps);
  }
  const SedimentOutcome out = outcome_of(samples);
  write_summary(config, samples, out, out_dir, seconds_since(start));
  return out;
}

SedimentSettings sediment_settings(const Config& config, int index) {
  const SedimentConfig& c = *config.sediment();
  SedimentSettings s;
  s.lx = c.size[0];
  s.ly = c.size[1];
  s.height = c.size[2];
  s.phi_initial = c.phi;
  s.radius_min = c.radius_min;
  s.radius_max = 1.0;
  s.seed = c.seed + index;
  s.mu0 = config.friction.mu0;
  s.stokes_number = c.stokes_number;
  s.solver = make_solver_settings(config.solver);
  s.dt = config.solver.dt;
  return s;
}

std::string phi_max_text(const SedimentOutcome& outcome, int samples) {
  if (samples > 1)
    return fmt::format("phi_max = {:.4f} +- {:.4f}", outcome.phi_max, outcome.phi_max_err);
  return fmt::format("phi_max = {:.4f} (one sample: no error bar)", outcome.phi_max);
}

}  // namespace dilatant
