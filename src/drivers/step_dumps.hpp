#pragma once
// A shear cell's step problems on disk: the state a chosen step starts from,
// written as a checkpoint (drivers/shear_cell_state.hpp) into a folder with
// the run's resolved config.toml and an index.csv. Loading one
// (ShearCell::resumed) and stepping once solves exactly that step's contact
// problem again — same prediction, detection, warm start, boundary and fluid
// forces, bit for bit — so a solver method can be measured on the problems a
// run met (bench/tools/solve_step.cpp: its work against its residual) without
// a second format to keep in step with the solve. Chosen steps:
//   regular      every `every`-th step once the strain reaches `from_strain`,
//                at most `max_regular` of them;
//   unconverged  the first `max_unconverged` steps whose solve ended at the
//                pass cap (the state of every step is then kept in memory
//                until the step is known: about a millisecond a step for the
//                paper's cell).
//
//   DIR/config.toml   the run's resolved configuration
//   DIR/step-0001234.bin   the state before step 1234 (a checkpoint)
//   DIR/index.csv     file,step,strain (at the step's
//   start),reason,converged,passes,sweep_equivalents,
//                     contacts,residual_change,contact_residual_max
#include <filesystem>
#include <string>

#include "io/config.hpp"
#include "solver/time_stepper.hpp"

namespace dilatant {

class ShearCell;

struct StepDumpSettings {
  std::filesystem::path dir;  // empty: no dumps
  double from_strain = 0.0;
  long every = 0;  // 0: no regular dumps
  int max_regular = 10;
  int max_unconverged = 0;
  bool any() const {
    return !dir.empty() && ((every > 0 && max_regular > 0) || max_unconverged > 0);
  }
};

class StepDumper {
 public:
  // Creates the folder and writes config.toml (throws if it cannot).
  StepDumper(StepDumpSettings settings, const Config& config);

  // Before a step: keeps the state it starts from if the step may be dumped.
  void before_step(ShearCell& cell);
  // After it: writes the kept state if the step was chosen.
  void after_step(const ShearCell& cell, const StepReport& report);

  int written() const { return regular_ + unconverged_; }

 private:
  StepDumpSettings settings_;
  std::string index_;         // index.csv so far
  std::string kept_;          // the state before the current step, if kept
  double kept_strain_ = 0.0;  // its strain
  bool regular_due_ = false;
  long eligible_steps_ = 0;  // steps started at or past from_strain
  int regular_ = 0, unconverged_ = 0;
};

}  // namespace dilatant
