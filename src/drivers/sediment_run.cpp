#include "drivers/sediment_run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "dilatant/version.hpp"
#include "drivers/model_setup.hpp"
#include "io/atomic_file.hpp"
#include "io/output_folder.hpp"
#include "measure/run_cost.hpp"
#include "measure/sample_mean.hpp"

namespace dilatant {

namespace {

// Exclusions (R) the fraction is also reported at, to show how much it depends
// on the choice.
constexpr double kExclusions[] = {2.0, 3.0, 4.0, 6.0};

struct Sample {
  std::int64_t seed = 0;
  std::size_t spheres = 0;
  bool settled = false;
  double time = 0.0;
  long steps = 0, unconverged = 0;
  double max_overlap = 0.0;
  SedimentFraction fraction;
  std::vector<double> phi_at;  // at kExclusions
};

// The sediment's fraction over its samples; with one sample the error is
// unknown: 0 here, null in summary.json.
struct MeanError {
  double mean = 0.0, error = 0.0;
};

MeanError mean_error(const std::vector<double>& x) {
  const SampleMean m = sample_mean(x);
  return {x.empty() ? 0.0 : m.mean, x.size() < 2 ? 0.0 : m.sem};
}

Sample run_sample(const Config& config, int index, bool progress) {
  Sediment sediment(sediment_settings(config, index));
  Sample s;
  s.seed = config.sediment()->seed + index;
  s.spheres = sediment.world().bodies.size();
  auto last = std::chrono::steady_clock::now();
  while (!sediment.settled() && !sediment.timed_out()) {
    const StepReport& r = sediment.step();
    if (!r.solve.converged) ++s.unconverged;
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

}  // namespace

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

SedimentOutcome run_sediment(const Config& config, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SedimentConfig& c = *config.sediment();
  prepare_output_folder(options.out_dir);
  write_file_atomically(options.out_dir / "config.toml", resolved_toml(config));

  std::vector<Sample> samples;
  for (int i = 0; i < c.samples; ++i) {
    samples.push_back(run_sample(config, i, !options.quiet && isatty(STDERR_FILENO)));
    const Sample& s = samples.back();
    if (!options.quiet)
      std::cout << fmt::format(
          "dilatant: sample {}/{} (seed {}): phi {:.4f}, surface {:.2f} R, {} after {} steps\n",
          i + 1, c.samples, s.seed, s.fraction.phi, s.fraction.surface,
          s.settled ? "settled" : "NOT settled", s.steps);
  }

  std::string csv = "seed,spheres,settled,time,steps,unconverged_steps,max_overlap,surface,top,phi";
  for (double e : kExclusions) csv += fmt::format(",phi_exclusion_{:g}", e);
  csv += "\n";
  std::vector<double> phi;
  SedimentOutcome out{.settled = true};
  double max_overlap = 0.0;
  for (const Sample& s : samples) {
    csv += fmt::format("{},{},{},{:.10g},{},{},{:.3e},{:.6g},{:.6g},{:.6f}", s.seed, s.spheres,
                       s.settled, s.time, s.steps, s.unconverged, s.max_overlap, s.fraction.surface,
                       s.fraction.top, s.fraction.phi);
    for (double p : s.phi_at) csv += fmt::format(",{:.6f}", p);
    csv += "\n";
    phi.push_back(s.fraction.phi);
    out.settled = out.settled && s.settled;
    out.steps += s.steps;
    out.unconverged_steps += s.unconverged;
    max_overlap = std::max(max_overlap, s.max_overlap);
  }
  write_file_atomically(options.out_dir / "samples.csv", csv);

  const MeanError m = mean_error(phi);
  out.phi_max = m.mean;
  out.phi_max_err = m.error;
  nlohmann::json j;
  j["version"] = kVersion;
  j["mode"] = "sediment";
  j["mu0"] = config.friction.mu0;
  j["phi_max"] = m.mean;
  j["phi_max_err"] = samples.size() > 1 ? nlohmann::json(m.error) : nlohmann::json(nullptr);
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
  j["wall_time_s"] = seconds_since(start);
  write_file_atomically(options.out_dir / "summary.json", j.dump(2) + "\n");
  return out;
}

std::string phi_max_text(const SedimentOutcome& outcome, int samples) {
  if (samples > 1)
    return fmt::format("phi_max = {:.4f} +- {:.4f}", outcome.phi_max, outcome.phi_max_err);
  return fmt::format("phi_max = {:.4f} (one sample: no error bar)", outcome.phi_max);
}

}  // namespace dilatant
