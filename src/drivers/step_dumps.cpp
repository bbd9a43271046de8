#include "drivers/step_dumps.hpp"

#include <fmt/format.h>

#include "drivers/shear_cell.hpp"
#include "io/atomic_file.hpp"

namespace dilatant {

StepDumper::StepDumper(StepDumpSettings settings, const Config& config)
    : settings_(std::move(settings)),
      index_(
          "file,step,strain,reason,converged,passes,sweep_equivalents,contacts,residual_change,"
          "contact_residual_max\n") {
  std::filesystem::create_directories(settings_.dir);
  write_file_atomically(settings_.dir / "config.toml", resolved_toml(config));
  write_file_atomically(settings_.dir / "index.csv", index_);
}

void StepDumper::before_step(ShearCell& cell) {
  kept_.clear();
  regular_due_ = false;
  if (cell.state().strain >= settings_.from_strain) {
    regular_due_ = settings_.every > 0 && regular_ < settings_.max_regular &&
                   eligible_steps_ % settings_.every == 0;
    ++eligible_steps_;
  }
  if (regular_due_ || unconverged_ < settings_.max_unconverged) {
    kept_ = cell.checkpoint_bytes();
    kept_strain_ = cell.state().strain;
  }
}

void StepDumper::after_step(const ShearCell& cell, const StepReport& report) {
  if (kept_.empty()) return;
  const bool unconverged = !report.solve.converged && unconverged_ < settings_.max_unconverged;
  if (!regular_due_ && !unconverged) return;
  // The step just run is state().steps; its state before is what was kept.
  const long step = cell.state().steps;
  const auto file = fmt::format("step-{:07d}.bin", step);
  write_file_atomically(settings_.dir / file, kept_);
  regular_ += regular_due_ ? 1 : 0;
  unconverged_ += !regular_due_ && unconverged ? 1 : 0;
  const double contacts = static_cast<double>(report.contacts_detected);
  index_ += fmt::format(
      "{},{},{},{},{},{},{},{},{},{}\n", file, step, kept_strain_,
      regular_due_ ? "regular" : "unconverged", report.solve.converged, report.solve.iterations,
      contacts > 0.0 ? report.solve.contact_visits / contacts : 0.0, report.contacts_detected,
      report.solve.residual, report.contact_residual.max());
  write_file_atomically(settings_.dir / "index.csv", index_);
}

}  // namespace dilatant
