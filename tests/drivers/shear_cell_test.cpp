// The shear cell's construction and its checkpoint/resume contract.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "detection/contact_detector.hpp"
#include "drivers/packing_growth.hpp"
#include "drivers/shear_cell_builder.hpp"
#include "drivers/shear_cell_run.hpp"
#include "io/config.hpp"
#include "io/input_error.hpp"
#include "solver/slab_partition.hpp"

namespace dilatant::shear_cell_test {
namespace {

Config small_cell(const std::vector<std::string>& extra = {}) {
  // A few dozen spheres over a little strain: enough steps to cross several
  // output rows and checkpoints, short enough for the sanitizer build.
  std::vector<std::string> overrides = {
      "cell.size=[6.0, 5.0, 7.0]",    "run.strain=0.04",
      "run.transient_strain=0.01",    "run.output_interval=0.005",
      "run.checkpoint_interval=0.01", "run.snapshot_interval=0.02",
      "solver.max_iterations=200"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return default_cell_config(overrides);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("dilatant_cell_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  return d;
}

TEST(ShearCellBuilder, PacksRequestedPhiWithoutOverlapBetweenWalls) {
  const Config config = default_cell_config({"cell.size=[10.0, 6.0, 12.0]", "cell.phi=0.59"});
  ShearCellGeometry g;
  RoughWalls walls;
  World world = build_shear_cell(config, g, walls);
  const double lx = 10.0, ly = 6.0, lz = 12.0;
  // phi is realised to within one sphere volume of the request.
  const double one_sphere = 4.0 / 3.0 * std::numbers::pi / (lx * ly * g.gap_height);
  EXPECT_LE(g.phi, 0.59);
  EXPECT_GT(g.phi, 0.59 - one_sphere);
  EXPECT_NEAR(g.gap_height, lz - 2.0 * g.wall_radius_mean, 1e-12);
  // Mobile volume recomputed from the bodies agrees with the reported phi.
  double volume = 0.0;
  for (std::size_t i = g.first_mobile; i < world.bodies.size(); ++i) {
    const double r = world.bodies.radius[i];
    volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    EXPECT_GE(r, 0.8);
    EXPECT_LE(r, 1.0);
    EXPECT_GE(world.bodies.position[i][2], r * (1.0 - 1e-6));  // above the bottom plane
    EXPECT_LE(world.bodies.position[i][2], lz - r * (1.0 - 1e-6));
  }
  EXPECT_NEAR(volume / (lx * ly * g.gap_height), g.phi, 1e-12);
  // No overlap beyond the growth protocol's final tolerance (1e-6 r_min).
  std::vector<Contact> contacts;
  ContactDetector detector;
  detector.detect(world, 0.0, contacts);
  for (const Contact& c : contacts) EXPECT_GE(c.gap, -kPackingOverlapTolerance * 0.8);
  // Walls: glued spheres centred on z = 0 and z = Lz; the top one slides.
  ASSERT_EQ(world.bodies.owner.size(), world.bodies.size());
  ASSERT_FALSE(walls.top().spheres.empty());
  for (std::int32_t s : walls.top().spheres) {
    EXPECT_EQ(world.bodies.owner[s], kTopWall);
    EXPECT_TRUE(world.bodies.is_driven(s));
    EXPECT_DOUBLE_EQ(world.bodies.position[s][2], lz);
    EXPECT_EQ(world.bodies.inv_mass[s], 0.0);
  }
  EXPECT_DOUBLE_EQ(walls.top().drive_force, 1.0 * lx * ly);
}

TEST(ShearCellBuilder, IsReproducibleFromTheSeed) {
  const Config config = default_cell_config({"cell.size=[8.0, 6.0, 9.0]"});
  ShearCellGeometry g1, g2;
  RoughWalls w1, w2;
  const World a = build_shear_cell(config, g1, w1);
  const World b = build_shear_cell(config, g2, w2);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies.position[i], b.bodies.position[i]);
  }
}

// Both boundaries: the wall cell, and the Lees–Edwards cell under stress
// control (its boundary speed and image offset are part of the state).
TEST(ShearCellRun, ResumeEqualsUninterruptedRunBitForBit) {
  for (const Config& config :
       {small_cell(), small_cell({"cell.boundary=\"lees-edwards\"", "fluid.lambda=1.0"})}) {
    SCOPED_TRACE(config.cell()->boundary == CellBoundary::Walls ? "walls" : "lees-edwards");
    const auto whole = fresh_dir("whole");
    const auto pieces = fresh_dir("pieces");
    run_shear_cell(config, CellRunOptions{RunOptions{whole, true}, false, nullptr});

    // Interrupt after the first step (as SIGINT would), then resume to the end.
    std::atomic<bool> stop{true};
    const CellOutcome first =
        run_shear_cell(config, CellRunOptions{RunOptions{pieces, true}, false, &stop});
    EXPECT_TRUE(first.interrupted);
    EXPECT_FALSE(std::filesystem::exists(pieces / "summary.json"));
    run_shear_cell(config, CellRunOptions{RunOptions{pieces, true}, true, nullptr});

    for (const char* f : {"timeseries.csv", "contacts.csv", "velocity_profile.csv",
                          "sommerfeld_hist.csv", "checkpoint.bin", "cell.pvd"}) {
      EXPECT_EQ(read(whole / f), read(pieces / f)) << f;
    }
    // Resuming a finished run changes nothing.
    const std::string contacts = read(pieces / "contacts.csv");
    run_shear_cell(config, CellRunOptions{RunOptions{pieces, true}, true, nullptr});
    EXPECT_EQ(read(pieces / "contacts.csv"), contacts);
    std::filesystem::remove_all(whole);
    std::filesystem::remove_all(pieces);
  }
}

// Extending a finished run (`dilatant run --resume` with a larger run.strain):
// the bits of a run made that long from the start, and only run.strain may
// differ (drivers/shear_cell_run.cpp).
void run_into(const Config& config, const std::filesystem::path& out, bool resume) {
  run_shear_cell(config, CellRunOptions{RunOptions{out, true}, resume, nullptr});
}

// The summary without the costs of the invocation that wrote it: what the
// clock measured, and the work per step and steps per strain of this
// invocation's steps (as after any resume).
nlohmann::json physics_of(const std::filesystem::path& summary) {
  nlohmann::json j = nlohmann::json::parse(read(summary));
  for (const char* timing :
       {"wall_time_s", "wall_time_per_strain_s", "ns_per_contact_update", "peak_memory_mib",
        "time_build_s", "time_detection_s", "time_measure_s", "time_other_s", "time_solve_s",
        "steps_per_strain", "sweep_equivalents_per_step"})
    j.erase(timing);
  return j;
}

TEST(ExtendRun, AFinishedRunExtendedGivesTheBitsOfTheLongerRun) {
  const auto whole = fresh_dir("extend_whole");
  const auto extended = fresh_dir("extended");
  run_into(small_cell(), whole, false);
  run_into(small_cell({"run.strain=0.025"}), extended,
           false);  // finished mid-row (rows every 0.005)
  ASSERT_TRUE(std::filesystem::exists(extended / "summary.json"));
  run_into(small_cell(), extended, true);
  for (const char* f : {"timeseries.csv", "contacts.csv", "velocity_profile.csv",
                        "sommerfeld_hist.csv", "checkpoint.bin", "config.toml"})
    EXPECT_EQ(read(whole / f), read(extended / f)) << f;
  EXPECT_EQ(physics_of(whole / "summary.json"), physics_of(extended / "summary.json"));
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(extended);
}

TEST(ExtendRun, AShorterStrainOrAnotherKeyIsRefused) {
  const auto out = fresh_dir("extend_refused");
  run_into(small_cell({"run.strain=0.02"}), out, false);
  const std::string series = read(out / "timeseries.csv");
  try {
    run_into(small_cell({"run.strain=0.015"}), out, true);
    ADD_FAILURE() << "a run.strain below the run's was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.strain = 0.015 is below the run's there (0.02)"),
              std::string::npos)
        << e.what();
  }
  try {
    run_into(small_cell({"friction.mu0=0.3"}), out, true);
    ADD_FAILURE() << "another friction.mu0 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("friction.mu0"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(out / "timeseries.csv"), series);  // neither touched the run
  std::filesystem::remove_all(out);
}

// A run resumed with its transient moved to the strain it had run (how a
// sweep runs on a point that is not steady, sweep/unsteady_extension.hpp):
// its rows are those of a run made with that transient from the start, and
// its velocity profile averages past the new transient only. The profile is
// added to per step once past the transient; the first run's last step
// crossed its run.strain, so it alone (a weight of at most one step, N dt)
// is in the run made whole and not in the resumed one. A transient moved into
// the strain already run is refused.
TEST(ExtendRun, AMovedTransientStartsTheAveragesAnewThere) {
  const auto whole = fresh_dir("moved_whole");
  const auto moved = fresh_dir("moved");
  // Total profile weight: the sum of dt x spheres over the bins.
  const auto weight = [&](const std::filesystem::path& dir) {
    std::istringstream lines(read(dir / "velocity_profile.csv"));
    std::string line;
    std::getline(lines, line);  // header: z,vx,weight
    double sum = 0.0;
    while (std::getline(lines, line)) sum += std::stod(line.substr(line.rfind(',') + 1));
    return sum;
  };
  const Config later = small_cell({"run.strain=0.1", "run.transient_strain=0.04"});
  run_into(later, whole, false);
  run_into(small_cell({"run.strain=0.04"}), moved, false);  // transient 0.01
  const double first_window = weight(moved);
  try {
    run_into(small_cell({"run.strain=0.1", "run.transient_strain=0.03"}), moved, true);
    ADD_FAILURE() << "a transient moved into the strain already run was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.transient_strain = 0.03"), std::string::npos)
        << e.what();
  }
  run_into(later, moved, true);
  EXPECT_EQ(read(whole / "timeseries.csv"), read(moved / "timeseries.csv"));
  const nlohmann::json a = physics_of(whole / "summary.json");
  const nlohmann::json b = physics_of(moved / "summary.json");
  for (const char* key : {"eta", "gamma_dot", "frac_bl", "wall_velocity_drift", "steady"})
    EXPECT_EQ(a[key], b[key]) << key;
  const double spheres = a["mobile_spheres"].get<double>();
  const double dt_mean = a["time"].get<double>() / a["steps"].get<double>();
  const double past = weight(whole);
  ASSERT_GT(past, 0.0);
  // One step apart: at most N dt_max; 4 dt_mean bounds dt_max here (the one
  // step measured 1.02 dt_mean).
  EXPECT_NEAR(weight(moved), past, 4.0 * spheres * dt_mean);
  // The bound tells the windows apart: the first run's own window (strain 0.01
  // to 0.04), which a profile not started anew would still hold, weighs more.
  EXPECT_LT(4.0 * spheres * dt_mean, first_window);
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(moved);
}

// The parallel sweep (solver/slab_partition.hpp) fixes the order of the
// Gauss–Seidel updates by geometry alone: two threads give the same bits as
// one. The gap of 11 R holds four slabs, so two threads really share sweeps.
TEST(ShearCellRun, TwoThreadsGiveTheSameBitsAsOne) {
  const std::string size = "cell.size=[6.0, 5.0, 11.0]";
  {
    ShearCellGeometry geometry;
    RoughWalls walls;
    const World world = build_shear_cell(small_cell({size}), geometry, walls);
    std::vector<Contact> contacts, scratch;
    ContactDetector().detect(world, 0.1, contacts);
    ASSERT_GE(partition_into_slabs(contacts, world, scratch).count(), 4);
  }
  const auto one = fresh_dir("threads1");
  const auto two = fresh_dir("threads2");
  run_shear_cell(small_cell({size, "solver.threads=1"}),
                 CellRunOptions{RunOptions{one, true}, false, nullptr});
  run_shear_cell(small_cell({size, "solver.threads=2"}),
                 CellRunOptions{RunOptions{two, true}, false, nullptr});
  for (const char* f : {"timeseries.csv", "contacts.csv", "checkpoint.bin"}) {
    EXPECT_EQ(read(one / f), read(two / f)) << f;
  }
  std::filesystem::remove_all(one);
  std::filesystem::remove_all(two);
}

}  // namespace
}  // namespace dilatant::shear_cell_test
