// Step problems on disk (drivers/step_dumps.hpp) and the solve's pass
// observer (solver/contact_problem.hpp): a dumped step, loaded and stepped
// once, is exactly the run's step; the observer sees every pass.
#include "drivers/step_dumps.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/cell_run_helpers.hpp"
#include "drivers/shear_cell.hpp"
#include "io/text.hpp"

namespace dilatant::drivers::step_dumps_test {
namespace {

// A small cell, no snapshots and no checkpoint within the run, so that
// nothing but the steps themselves changes the state between two dumps.
const std::vector<std::string> kCell = {
    "solver.threads=1",         "cell.size=[8.0, 5.0, 9.0]", "run.strain=0.02",
    "run.transient_strain=0.0", "run.snapshot_interval=0.0", "run.checkpoint_interval=100.0",
    "run.output_interval=0.005"};

std::string bytes_of(const std::filesystem::path& file) {
  return read_input_file(file, "test file");
}

// Loading the state dumped before step 2 and stepping once gives, byte for
// byte, the state the run dumped before step 3: the dump holds everything the
// step reads (prediction, detection, warm start, drive, measurements).
TEST(StepDumps, ADumpedStepSteppedOnceIsTheRunsNextState) {
  const auto dir = test::cell_run_dir("step_dumps");
  std::filesystem::remove_all(dir);
  const Config config = default_cell_config(kCell);
  CellRunOptions options{RunOptions{dir / "run", true}, false, nullptr};
  options.dumps = {.dir = dir / "dumps", .from_strain = 0.0, .every = 1, .max_regular = 3};
  run_shear_cell(config, options);
  for (const char* f : {"step-0000001.bin", "step-0000002.bin", "step-0000003.bin"})
    ASSERT_TRUE(std::filesystem::is_regular_file(dir / "dumps" / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(dir / "dumps" / "step-0000004.bin"));  // --dump-max 3
  ShearCell cell = ShearCell::resumed(config, dir / "dumps" / "step-0000002.bin");
  EXPECT_EQ(cell.state().steps, 1);
  cell.step();
  EXPECT_EQ(cell.checkpoint_bytes(), bytes_of(dir / "dumps" / "step-0000003.bin"));
  // The index names each file once, with its reason, and the config loads.
  std::istringstream index(bytes_of(dir / "dumps" / "index.csv"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(index, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[1].rfind("step-0000001.bin,1,0,regular,", 0), 0u) << lines[1];
  EXPECT_NO_THROW(load_config(dir / "dumps" / "config.toml", {}));
  std::filesystem::remove_all(dir);
}

// The observer is called after every pass, by one thread, with the passes
// and visits so far: its last call is the solve's report, and the residual it
// computes then is the one the step reports. Two threads share the passes.
TEST(PassObserver, SeesEveryPassAndTheSolvesLastState) {
  for (const char* threads : {"solver.threads=1", "solver.threads=2"}) {
    std::vector<std::string> overrides = kCell;
    overrides.emplace_back(threads);
    ShearCell cell(default_cell_config(overrides));
    for (int k = 0; k < 20; ++k) cell.step();  // contacts formed
    int calls = 0, last_passes = 0;
    double last_visits = 0.0;
    ContactResidual last;
    cell.set_pass_observer([&](const ContactProblem& problem, int passes, double visits) {
      ++calls;
      EXPECT_EQ(passes, calls);
      last_passes = passes;
      last_visits = visits;
      last = contact_residual(problem);
    });
    const StepReport report = cell.step();
    ASSERT_GT(report.contacts_detected, 0u);
    EXPECT_EQ(calls, report.solve.iterations) << threads;
    EXPECT_EQ(last_passes, report.solve.iterations);
    EXPECT_EQ(last_visits, report.solve.contact_visits);
    EXPECT_EQ(last.max(), report.contact_residual.max());
    EXPECT_EQ(last.normal_rms, report.contact_residual.normal_rms);
  }
}

}  // namespace
}  // namespace dilatant::drivers::step_dumps_test
