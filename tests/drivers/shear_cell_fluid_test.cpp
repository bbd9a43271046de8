// The shear cell with the fluid forces on (fluid.lubrication = "normal",
// fluid.drag = "stokes"): the energy budget still closes to round-off with the
// films' and the drag's powers in it, both are real losses here, and the
// volume fraction can be counted against the whole box (cell.phi_definition).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/cli_runner.hpp"
#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_run.hpp"
#include "io/config.hpp"

namespace dilatant::shear_cell_fluid_test {
namespace {

const std::vector<std::string> kCell = {
    "cell.size=[8.0, 5.0, 9.0]", "fluid.lambda=1.0",         "run.strain=3.0",
    "run.transient_strain=1.0",  "run.output_interval=0.02", "run.snapshot_interval=0.0",
    "fluid.lubrication=normal",  "fluid.drag=stokes"};

TEST(ShearCellFluid, EnergyBudgetClosesWithFilmsAndDrag) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("dilatant_fluid_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  run_shear_cell(default_cell_config(kCell), CellRunOptions{RunOptions{dir, true}, false, nullptr});
  std::ifstream in(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(j["lubrication"], "normal");
  EXPECT_EQ(j["drag"], "stokes");
  EXPECT_FALSE(j["jammed"].get<bool>());
  const double injected = j["power_injected"];
  const double losses = j["power_impacts"].get<double>() + j["power_friction_bl"].get<double>() +
                        j["power_friction_hd"].get<double>() +
                        j["power_lubrication"].get<double>() + j["power_drag"].get<double>() +
                        j["power_kinetic"].get<double>();
  // Exact step by step (solver/contact_work.hpp, fluid/implicit_drag.hpp).
  EXPECT_NEAR(injected, losses, 1e-9 * injected);
  // The films dissipate in every step (tests/fluid/squeeze_film_test.cpp); the
  // drag, relative to the flow's own mean profile, takes power from the
  // particles' fluctuations on balance.
  EXPECT_GT(j["power_lubrication"].get<double>(), 0.0);
  EXPECT_GT(j["power_drag"].get<double>(), 0.0);
}

// The fluid forces on two threads: the films enter each contact's local
// problem in the parallel solve (solver/local_problem.hpp), the drag acts
// against the cell's mean flow, set each step; two threads must give the bits
// of one.
// The size is ShearCellRun.TwoThreadsGiveTheSameBitsAsOne's, which checks that
// it makes at least 4 slabs, so both threads have work in each colour. Short,
// so that ThreadSanitizer and the sanitizer stage run the fluid code on
// threads without the long energy-budget run above (tests/tsan/release-only.txt);
// rows every 0.002 strain, so that the steady window's 50 rows are enough for
// the block error bars and the steadiness check (measure/steadiness.hpp) to run.
TEST(ShearCellFluid, TwoThreadsGiveTheSameBitsAsOne) {
  test::TempDir dir;
  std::vector<std::string> cell = kCell;
  cell.insert(cell.end(), {"cell.size=[6.0, 5.0, 11.0]", "run.strain=0.2",
                           "run.transient_strain=0.1", "run.output_interval=0.002"});
  const auto run = [&](const char* threads, const char* name) {
    std::vector<std::string> c = cell;
    c.push_back(threads);
    run_shear_cell(default_cell_config(c),
                   CellRunOptions{RunOptions{dir.path() / name, true}, false, nullptr});
    return dir.path() / name;
  };
  const auto one = run("solver.threads=1", "one");
  const auto two = run("solver.threads=2", "two");
  for (const char* f : {"timeseries.csv", "contacts.csv", "checkpoint.bin"})
    EXPECT_EQ(test::read_text(one / f), test::read_text(two / f)) << f;
}

// phi_definition = "box" fills Lx Ly Lz to cell.phi, and both counts are
// reported: the box's is below the requested phi by less than one sphere.
TEST(ShearCellFluid, BoxVolumeFractionCountsTheWholeHeight) {
  const Config box =
      default_cell_config({"cell.size=[8.0, 5.0, 9.0]", "cell.phi=0.45", "cell.phi_definition=box",
                           "run.strain=0.01", "run.transient_strain=0.0"});
  const ShearCell cell(box);
  const ShearCellGeometry& g = cell.state().geometry;
  const double one_sphere = 4.0 / 3.0 * M_PI / (8.0 * 5.0 * 9.0);  // radius <= 1
  EXPECT_LE(g.phi_box, 0.45);
  EXPECT_GT(g.phi_box, 0.45 - one_sphere);
  EXPECT_NEAR(g.phi * g.gap_height, g.phi_box * 9.0, 1e-12);
}

}  // namespace
}  // namespace dilatant::shear_cell_fluid_test
