// Sweeps on MPI ranks (issue 18, sweep/mpi_scheduler.hpp): `mpirun -n 2` on
// tiny sweeps gives the table of the local sweep (same seeds, same numbers),
// with a failing point recorded as locally (and a resumed table that mixes
// versions noted once); killed mid-way and run again it
// completes to the same table; continuation chains, with a ramp that jams,
// give the local ramps. mpirun runs on this machine only (shared memory and
// loopback), oversubscribed, and as root where CI runs as root.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "sweep/child_sweep.hpp"
#include "sweep/tiny_sweep.hpp"

#if DILATANT_WITH_MPI
#include "sweep/mpi_messages.hpp"
#endif

namespace dilatant::mpi_sweep_test {
namespace {

namespace fs = std::filesystem;
using test::table_without_timing;
using test::wait_for;

#define SKIP_WITHOUT_MPI()                                                             \
  if (!DILATANT_WITH_MPI) GTEST_SKIP() << "built without MPI (DILATANT_WITH_MPI=OFF)"; \
  static_assert(true)

// `dilatant sweep FILE --out OUT --no-plots ARGS...`, locally or on `ranks`
// MPI ranks; stderr to `err` when given.
pid_t start_sweep(int ranks, const fs::path& file, const fs::path& out,
                  const std::vector<std::string>& args = {}, const std::string& err = {}) {
  std::vector<std::string> command;
  if (ranks > 0) {
    // Only this machine: shared memory and self, no network interface, no
    // ssh; oversubscribed (2 ranks may exceed the cores CI gives); as root.
    setenv("OMPI_MCA_btl", "self,vader", 1);
    setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);  // no ptrace in containers
    setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    command = {DILATANT_MPIEXEC, "-n", std::to_string(ranks), "--oversubscribe"};
  }
  for (const std::string& a :
       {std::string(DILATANT_EXECUTABLE), std::string("sweep"), file.string(), std::string("--out"),
        out.string(), std::string("--no-plots")})
    command.push_back(a);
  command.insert(command.end(), args.begin(), args.end());
  return test::start_child(command, err);
}

// The tiny grid and a fifth point at a fraction no packing reaches.
std::string grid_with_a_failure() {
  return test::kTinyCell +
         "[fluid]\nlambda = [3.0, 30.0]\n[[points]]\nfriction.mu0 = 0.1\n[[points]]\n"
         "friction.mu0 = 0.4\n[[points]]\nfriction.mu0 = 0.1\ncell.phi = 0.72\n"
         "fluid.lambda = 3.0\n";
}

TEST(MpiSweep, TwoRanksGiveTheTableOfTheLocalSweepAndRecordAFailingPoint) {
  SKIP_WITHOUT_MPI();
  test::TempDir dir;
  const fs::path file = dir.write("grid.toml", grid_with_a_failure());
  ASSERT_EQ(wait_for(start_sweep(0, file, dir.path() / "local", {"--jobs", "2", "-q"})), 1);
  const std::string err = (dir.path() / "mpi.err").string();
  ASSERT_EQ(wait_for(start_sweep(2, file, dir.path() / "mpi", {}, err)), 1) << test::read_text(err);
  const std::string messages = test::read_text(err);
  EXPECT_NE(messages.find("failed: could not pack cell.phi = 0.72"), std::string::npos) << messages;
  EXPECT_NE(messages.find("1 of 5 points failed"), std::string::npos) << messages;
  const std::string local = table_without_timing(dir.path() / "local" / "flowcurves.csv");
  EXPECT_EQ(table_without_timing(dir.path() / "mpi" / "flowcurves.csv"), local);
  const fs::path error = "points/004-lambda=3_mu0=0.1_phi=0.72/error.txt";
  ASSERT_TRUE(fs::is_regular_file(dir.path() / "mpi" / error));
  EXPECT_EQ(test::read_text(dir.path() / "mpi" / error),
            test::read_text(dir.path() / "local" / error));
  // Run again: the failed points again, the others skipped; one rank is the
  // local sweep.
  ASSERT_EQ(wait_for(start_sweep(1, file, dir.path() / "mpi", {"-q"})), 1);
  EXPECT_EQ(table_without_timing(dir.path() / "mpi" / "flowcurves.csv"), local);
  // A point finished by another version: rank 0, and only rank 0, says the
  // table will mix versions (as the local sweep does).
  fs::path older;
  for (const auto& point : fs::directory_iterator(dir.path() / "mpi" / "points"))
    if (point.path().filename().string().rfind("000-", 0) == 0)
      older = point.path() / "summary.json";
  ASSERT_TRUE(fs::is_regular_file(older)) << older;
  auto summary = nlohmann::json::parse(test::read_text(older));
  summary["version"] = "0.1.0";
  std::ofstream(older) << summary.dump(2) << "\n";
  const std::string again = (dir.path() / "mpi-again.err").string();
  ASSERT_EQ(wait_for(start_sweep(2, file, dir.path() / "mpi", {}, again)), 1);
  const std::string notes = test::read_text(again);
  const std::string note = "note: 1 finished point(s) in " + (dir.path() / "mpi").string() +
                           " were run by version 0.1.0";
  const auto first = notes.find(note);
  EXPECT_NE(first, std::string::npos) << notes;
  EXPECT_EQ(notes.find(note, first + 1), std::string::npos) << notes;
}

TEST(MpiSweep, KilledMidwayAndRunAgainCompletesToTheLocalTable) {
  SKIP_WITHOUT_MPI();
  test::TempDir dir;
  // The tiny grid sheared longer, checkpointed often (as the kill test).
  std::string text = test::kTinyGrid;
  const auto run_at = text.find("[run]"), friction_at = text.find("[friction]");
  text = text.substr(0, run_at) +
         "[run]\nstrain = 1.5\ntransient_strain = 0.1\ncheckpoint_interval = 0.05\n"
         "snapshot_interval = 0.0\n\n" +
         text.substr(friction_at);
  const fs::path file = dir.write("kill.toml", text);
  ASSERT_EQ(wait_for(start_sweep(0, file, dir.path() / "local", {"--jobs", "2", "-q"})), 0);

  // Killed, mpirun and both ranks at once (SIGKILL to its session: a node
  // lost, or a time limit without grace), as soon as a point is done.
  const fs::path out = dir.path() / "mpi", table = out / "flowcurves.csv";
  const pid_t pid = start_sweep(2, file, out, {"-q"});
  int code = 0;
  bool ended = false;
  while (test::done_points(table) == 0 && !ended) {
    ended = waitpid(pid, &code, WNOHANG) == pid;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_FALSE(ended) << "the sweep ended before a kill (exit " << code << ")";
  EXPECT_EQ(test::kill_session(pid), -SIGKILL);
  const std::size_t done = test::done_points(table);
  EXPECT_GE(done, 1u);
  EXPECT_LT(done, 4u) << "the kill came after the sweep's end";

  const std::string err = (dir.path() / "resume.err").string();
  ASSERT_EQ(wait_for(start_sweep(2, file, out, {"-q"}, err)), 0) << test::read_text(err);
  EXPECT_EQ(table_without_timing(table),
            table_without_timing(dir.path() / "local" / "flowcurves.csv"));
}

// Two stress ramps: mu0 1 dense and dry jams at lambda 1e4 (as ramp_jam_test),
// confirmed from a cold start, its last point skipped; mu0 0.1 flows.
constexpr const char* kRamps = R"(
[cell]
size = [8.0, 6.0, 9.0]
phi = 0.60
seed = 3  # flows at lambda 0.01, jams at 1e4 (confirmed cold), with the wall inside the pass
[friction]
law = "stribeck"
mu0 = [1.0, 0.1]
[fluid]
lambda = [0.01, 10000.0, 100000.0]
lubrication = "none"
drag = "none"
[solver]
tolerance = 1e-3  # a jam needs it (docs/model.md "Convergence criterion")
[run]
strain = 0.2
transient_strain = 0.1
snapshot_interval = 0.0
[sweep]
continuation = true
)";

TEST(MpiSweep, ContinuationChainsOnTwoRanksGiveTheLocalRamps) {
  SKIP_WITHOUT_MPI();
  test::TempDir dir;
  const fs::path file = dir.write("ramps.toml", kRamps);
  ASSERT_EQ(wait_for(start_sweep(0, file, dir.path() / "local", {"--jobs", "2", "-q"})), 0);
  const std::string err = (dir.path() / "mpi.err").string();
  ASSERT_EQ(wait_for(start_sweep(2, file, dir.path() / "mpi", {"-q"}, err)), 0)
      << test::read_text(err);
  const std::string local = table_without_timing(dir.path() / "local" / "flowcurves.csv");
  EXPECT_NE(local.find("|jammed|"), std::string::npos) << local;  // the jam was confirmed
  EXPECT_NE(local.find("|skipped|"), std::string::npos) << local;
  EXPECT_EQ(table_without_timing(dir.path() / "mpi" / "flowcurves.csv"), local);
}

#if DILATANT_WITH_MPI
TEST(MpiMessages, UnitsAndRecordsReadBackFromTheirText) {
  EXPECT_EQ(sweep::mpi::parse_unit(sweep::mpi::unit_text({3, 4, 12})), (sweep::WorkUnit{3, 4, 12}));
  sweep::PointRecord r;
  r.status = sweep::PointStatus::Done;
  r.summary = nlohmann::json::parse(R"({"eta": 0.1, "gamma_dot": 3.0000000000000004, "n": 7})");
  const auto [i, back] = sweep::mpi::parse_record(sweep::mpi::record_json(5, r));
  EXPECT_EQ(i, 5u);
  EXPECT_EQ(back.status, sweep::PointStatus::Done);
  EXPECT_EQ(back.summary, r.summary);
  EXPECT_EQ(back.summary["gamma_dot"].get<double>(), 3.0000000000000004);
  EXPECT_TRUE(back.cold_start.is_null());
}
#endif

}  // namespace
}  // namespace dilatant::mpi_sweep_test
