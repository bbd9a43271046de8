// End-to-end tests of `dilatant sweep` and `dilatant plot` (docs/sweeps.md), the
// CI check of issue 5: a reduced sweep (a 6 x 5 x 7 R cell sheared to strain 0.3,
// the 2 x 2 grid mu0 x lambda, two jobs) run by the real executable; its table,
// resuming it (a second run skips every point and changes nothing; a deleted
// summary.json redoes that point only), a point that fails without stopping the
// others, a changed sweep refused, bad sweep files, and the plots.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/delimited_text.hpp"
#include "app/cli_runner.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep_command_test {
namespace {

namespace fs = std::filesystem;
using test::read_text;

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  const std::string& at(std::size_t row, const std::string& column) const {
    const auto it = std::find(header.begin(), header.end(), column);
    EXPECT_NE(it, header.end()) << column;
    return rows.at(row).at(static_cast<std::size_t>(it - header.begin()));
  }
};

Table read_table(const fs::path& file) {
  Table t;
  std::istringstream in(read_text(file));
  for (std::string line; std::getline(in, line);) {
    auto fields = analysis::split_fields(line, ',');
    if (t.header.empty()) {
      t.header = fields;
    } else {
      EXPECT_EQ(fields.size(), t.header.size()) << line;
      t.rows.push_back(fields);
    }
  }
  return t;
}

// The table with the columns that time the runs blanked.
Table without_timing(Table t) {
  for (auto& row : t.rows)
    for (std::size_t k = 0; k < t.header.size(); ++k)
      if (t.header[k] == "wall_time_s") row[k] = "";
  return t;
}

std::map<std::string, fs::file_time_type> summary_times(const fs::path& out) {
  std::map<std::string, fs::file_time_type> times;
  for (const auto& e : fs::directory_iterator(out / "points"))
    if (fs::exists(e.path() / "summary.json"))
      times[e.path().filename().string()] = fs::last_write_time(e.path() / "summary.json");
  return times;
}

const std::vector<std::string> kPointFolders = {"000-mu0=0.1_lambda=3", "001-mu0=0.1_lambda=30",
                                                "002-mu0=0.4_lambda=3", "003-mu0=0.4_lambda=30"};

TEST(SweepCommand, RunsTheGridThenResumesSkippingFinishedPointsAndRedoingAMissingOne) {
  test::CliDir dir;
  const fs::path config = dir.write("grid.toml", test::kTinyGrid);
  const fs::path out = dir.path() / "grid";
  const std::vector<std::string> command = {
      "sweep", config.string(), "--out", out.string(), "--jobs", "2", "--no-plots"};
  const auto first = dir.run(command);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  // No progress line without a terminal; its points' unconverged steps (a few
  // per cent at the tiny cell's tolerance) are the one thing it warns of.
  EXPECT_EQ(first.err.find('\r'), std::string::npos) << first.err;
  EXPECT_EQ(first.err.rfind("dilatant: warning: ", 0), 0u) << first.err;
  EXPECT_EQ(std::count(first.err.begin(), first.err.end(), '\n'), 1) << first.err;
  EXPECT_NE(first.out.find("sweep of 4 points: 4 done, 0 failed"), std::string::npos) << first.out;

  // The table: one row per point in point order, the swept keys first, then
  // point, status, error and the summary fields `dilatant analyze` needs.
  const Table table = read_table(out / "flowcurves.csv");
  ASSERT_EQ(table.rows.size(), 4u);
  const std::vector<std::string> head(table.header.begin(), table.header.begin() + 8);
  EXPECT_EQ(head, (std::vector<std::string>{"friction.mu0", "fluid.lambda", "point", "status",
                                            "error", "phi", "mu0", "lambda"}));
  for (const char* column :
       {"shear_stress", "gamma_dot", "gamma_dot_err", "eta", "eta_err", "valid", "jammed",
        "frac_bl", "frac_over_slim", "phi_bulk", "normal_stress", "inertial_number", "steps",
        "wall_time_s", "version", "sample", "dir"})
    EXPECT_NE(std::find(table.header.begin(), table.header.end(), column), table.header.end())
        << column;
  const double mu0[] = {0.1, 0.1, 0.4, 0.4}, lambda[] = {3, 30, 3, 30};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(table.at(k, "point"), std::to_string(k));
    EXPECT_EQ(table.at(k, "status"), "done");
    EXPECT_EQ(table.at(k, "error"), "");
    EXPECT_EQ(std::stod(table.at(k, "friction.mu0")), mu0[k]);
    EXPECT_EQ(std::stod(table.at(k, "mu0")), mu0[k]);
    EXPECT_EQ(std::stod(table.at(k, "lambda")), lambda[k]);
    EXPECT_EQ(table.at(k, "phi"), "0.58");
    // Paper units: tau = lambda^2; the cell flows, eta = tau / gamma_dot.
    EXPECT_NEAR(std::stod(table.at(k, "shear_stress")), lambda[k] * lambda[k], 1e-9);
    EXPECT_EQ(table.at(k, "jammed"), "false");
    const double rate = std::stod(table.at(k, "gamma_dot"));
    EXPECT_GT(rate, 0.0);
    EXPECT_NEAR(std::stod(table.at(k, "eta")) * rate, lambda[k] * lambda[k],
                1e-9 * lambda[k] * lambda[k]);
    EXPECT_TRUE(table.at(k, "valid") == "true" || table.at(k, "valid") == "false");
    EXPECT_EQ(table.at(k, "dir"), "points/" + kPointFolders[k]);
    EXPECT_TRUE(fs::is_regular_file(out / "points" / kPointFolders[k] / "summary.json"));
    EXPECT_TRUE(fs::is_regular_file(out / "points" / kPointFolders[k] / "config.toml"));
  }
  // A hundred times the stress: the cell shears faster.
  EXPECT_GT(std::stod(table.at(1, "gamma_dot")), std::stod(table.at(0, "gamma_dot")));
  EXPECT_TRUE(fs::is_regular_file(out / "sweep.toml"));
  // The flow-curve analysis: one curve per mu0.
  const Table curves = read_table(out / "analysis" / "curves.csv");
  ASSERT_EQ(curves.rows.size(), 2u);
  EXPECT_EQ(curves.at(0, "sample"), "mu0=0.1");
  EXPECT_EQ(curves.at(1, "sample"), "mu0=0.4");
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_NE(e.path().extension(), ".part") << e.path();

  // Again: every point is skipped, nothing changes.
  const std::string text = read_text(out / "flowcurves.csv");
  const auto times = summary_times(out);
  ASSERT_EQ(times.size(), 4u);
  const auto second = dir.run(command);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(second.out.find("4 done (4 of them before this run)"), std::string::npos) << second.out;
  EXPECT_EQ(read_text(out / "flowcurves.csv"), text);
  EXPECT_EQ(summary_times(out), times);

  // A deleted summary.json: that point runs again (from the start, the same
  // result), the others are left as they are.
  const fs::path redo = out / "points" / kPointFolders[2] / "summary.json";
  const std::string before = read_text(redo);
  fs::remove(redo);
  const auto third = dir.run(command);
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_NE(third.out.find("4 done (3 of them before this run)"), std::string::npos) << third.out;
  const auto after_times = summary_times(out);
  auto others = after_times;
  EXPECT_NE(others[kPointFolders[2]], times.at(kPointFolders[2]));
  others[kPointFolders[2]] = times.at(kPointFolders[2]);
  EXPECT_EQ(others, times);
  const Table redone = without_timing(read_table(out / "flowcurves.csv"));
  EXPECT_EQ(redone.rows, without_timing(table).rows);
  // Everything but what the run cost (time, memory) is the same.
  const auto physics = [](const std::string& summary) {
    auto j = nlohmann::json::parse(summary);
    for (auto it = j.begin(); it != j.end();) {
      const std::string& key = it.key();
      const bool cost = key.rfind("time_", 0) == 0 || key.rfind("wall_time", 0) == 0 ||
                        key == "ns_per_contact_update" || key == "peak_memory_mib";
      it = cost ? j.erase(it) : std::next(it);
    }
    return j;
  };
  EXPECT_EQ(physics(read_text(redo)), physics(before));

  // A changed sweep over the same folder is refused, naming the point and key.
  const auto changed =
      dir.run({"sweep", config.string(), "--out", out.string(), "--set", "run.strain=0.4"});
  EXPECT_EQ(changed.exit_code, 2);
  EXPECT_EQ(std::count(changed.err.begin(), changed.err.end(), '\n'), 1) << changed.err;
  EXPECT_NE(changed.err.find(kPointFolders[0] + ": holds a run of another configuration "
                                                "(run.strain = 0.3 there, 0.4 in this sweep)"),
            std::string::npos)
      << changed.err;
  EXPECT_EQ(summary_times(out), after_times);

  // A point finished by another version: resuming says the table will mix
  // versions (and still runs); --quiet keeps quiet.
  const fs::path older = out / "points" / kPointFolders[0] / "summary.json";
  auto summary = nlohmann::json::parse(read_text(older));
  summary["version"] = "0.1.0";
  dir.write(older.lexically_relative(dir.path()), summary.dump(2) + "\n");
  const auto mixed = dir.run(command);
  ASSERT_EQ(mixed.exit_code, 0) << mixed.err;
  EXPECT_NE(mixed.err.find("note: 1 finished point(s) in " + out.string() +
                           " were run by version 0.1.0, this is "),
            std::string::npos)
      << mixed.err;
  std::vector<std::string> quiet = command;
  quiet.push_back("--quiet");
  EXPECT_EQ(dir.run(quiet).err, "");

  // `dilatant analyze` reads the sweep's table as it is.
  const auto analyze = dir.run({"analyze", (out / "flowcurves.csv").string(), "--out",
                                (dir.path() / "analysis").string(), "--no-plots", "-q"});
  EXPECT_EQ(analyze.exit_code, 0) << analyze.err;
}

// Writes NAME.toml, the tiny cell and `extra`, and sweeps it into DIR/NAME
// on `jobs` workers, without plots.
test::RunResult sweep_tiny(test::CliDir& dir, const std::string& name, const std::string& extra,
                           const std::string& jobs) {
  const fs::path config = dir.write(name + ".toml", test::kTinyCell + extra);
  return dir.run({"sweep", config.string(), "--out", (dir.path() / name).string(), "--jobs", jobs,
                  "--no-plots"});
}

TEST(SweepCommand, AFailingPointIsRecordedWithItsErrorAndTheOthersFinish) {
  test::CliDir dir;
  // Three points, the second at a fraction no packing reaches.
  const auto r = sweep_tiny(dir, "fail",
                            "[fluid]\nlambda = 3.0\n[[points]]\ncell.phi = 0.58\n[[points]]\n"
                            "cell.phi = 0.72\n[[points]]\ncell.phi = 0.55\n",
                            "2");
  const fs::path out = dir.path() / "fail";
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("point points/001-phi=0.72 failed: could not pack cell.phi = 0.72"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1 of 3 points failed"), std::string::npos) << r.err;
  const Table table = read_table(out / "flowcurves.csv");
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.at(0, "status"), "done");
  EXPECT_EQ(table.at(1, "status"), "failed");
  EXPECT_NE(table.at(1, "error").find("could not pack"), std::string::npos);
  EXPECT_EQ(table.at(1, "gamma_dot"), "");
  EXPECT_EQ(table.at(2, "status"), "done");
  EXPECT_EQ(read_text(out / "points/001-phi=0.72/error.txt"), table.at(1, "error") + "\n");
  // The analysis leaves the failed point out: two curves of one point each.
  EXPECT_EQ(read_table(out / "analysis" / "curves.csv").rows.size(), 2u);
}

// The wall-free cell sweeps like the wall cell: two lambdas of a
// Lees–Edwards cell (docs/shear-cell.md "The Lees–Edwards cell"), each a done
// point of the table with its shear rate; the wall-only columns are empty.
TEST(SweepCommand, SweepsTheLeesEdwardsCell) {
  test::CliDir dir;
  std::string sweep = test::kTinyCell;
  sweep.replace(sweep.find("[cell]\n"), 7, "[cell]\nboundary = \"lees-edwards\"\n");
  const fs::path config = dir.write("le.toml", sweep + "[fluid]\nlambda = [3.0, 30.0]\n");
  const fs::path out = dir.path() / "le";
  const auto r =
      dir.run({"sweep", config.string(), "--out", out.string(), "--jobs", "1", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table table = read_table(out / "flowcurves.csv");
  ASSERT_EQ(table.rows.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(table.at(k, "status"), "done");
    EXPECT_GT(std::stod(table.at(k, "gamma_dot")), 0.0);
  }
  const auto summary =
      nlohmann::json::parse(read_text(out / "points" / "000-lambda=3" / "summary.json"));
  EXPECT_EQ(summary["boundary"], "lees-edwards");
  EXPECT_TRUE(summary["bottom_wall_force_x"].is_null());
}

// A sweep whose points' solver stopped at solver.max_iterations says so on
// stderr, once, naming the worst point, as `dilatant run` warns about its
// own; a point whose steps all converged is not counted.
TEST(SweepCommand, APointWithUnconvergedStepsIsWarnedAbout) {
  test::CliDir dir;
  const auto r = sweep_tiny(dir, "cap",
                            "[fluid]\nlambda = 3.0\n[[points]]\nsolver.max_iterations = 2\n"
                            "[[points]]\nsolver.max_iterations = 1000\n",
                            "1");
  const fs::path out = dir.path() / "cap";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table table = read_table(out / "flowcurves.csv");
  ASSERT_GT(std::stod(table.at(0, "frac_steps_unconverged")), 0.0);
  ASSERT_EQ(std::stod(table.at(1, "frac_steps_unconverged")), 0.0);
  const std::string share =
      fmt::format("{:.2g}", 100.0 * std::stod(table.at(0, "frac_steps_unconverged")));
  EXPECT_EQ(r.err,
            "dilatant: warning: 1 of 2 points have steps that did not converge within "
            "solver.max_iterations, up to " +
                share +
                "% of a point's (points/000-max_iterations=2; frac_steps_unconverged in "
                "flowcurves.csv)\n");
}

TEST(SweepCommand, BadSweepFilesExitWith2AndOneLineNamingFileKeyAndPoint) {
  test::CliDir dir;
  const fs::path config =
      dir.write("bad.toml", test::kTinyCell + "[friction]\nmu0 = [0.1, -0.3]\n");
  const auto r = dir.run({"sweep", config.string(), "--out", (dir.path() / "o").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "dilatant: error: " + config.string() +
                       ":14: friction.mu0 = -0.3: must be >= 0 (point 1: friction.mu0 = -0.3)\n");
  EXPECT_FALSE(fs::exists(dir.path() / "o")) << "nothing runs";
  const auto jobs = dir.run({"sweep", config.string(), "--jobs", "-1"});
  EXPECT_EQ(jobs.exit_code, 2);
  const auto missing = dir.run({"sweep", (dir.path() / "nope.toml").string()});
  EXPECT_EQ(missing.exit_code, 2);
  const auto plot = dir.run({"plot", dir.path().string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_NE(plot.err.find("no flowcurves.csv here"), std::string::npos) << plot.err;
}

TEST(SweepCommand, PlotDrawsTheFiguresOrSaysInOneLineWhyNot) {
  test::CliDir dir;
  const fs::path config = dir.write("grid.toml", test::kTinyGrid);
  const fs::path out = dir.path() / "grid";
  const auto r = dir.run({"sweep", config.string(), "--out", out.string(), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const std::vector<std::string> figures = {"flow_curves", "fig1b_viscosity", "fig1c_sommerfeld",
                                            "fig1d_contacts"};
  if (test::matplotlib_available()) {
    EXPECT_EQ(r.err, "");
    for (const auto& f : figures)
      for (const char* ext : {".png", ".svg"})
        EXPECT_GT(fs::file_size(out / "plots" / (f + ext)), 1000u) << f << ext;
    fs::remove_all(out / "plots");
    const auto again = dir.run({"plot", out.string()});
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_TRUE(fs::is_regular_file(out / "plots" / "flow_curves.svg"));
  }
  const auto without = dir.run({"plot", out.string(), "--python", "/nonexistent/python3"});
  EXPECT_EQ(without.exit_code, 0);
  EXPECT_EQ(std::count(without.err.begin(), without.err.end(), '\n'), 1) << without.err;
  EXPECT_NE(without.err.find("plots skipped"), std::string::npos) << without.err;
  EXPECT_TRUE(fs::is_regular_file(out / "analysis" / "curves.csv"));
}

TEST(SweepCommand, HelpDescribesTheSweepFileAndItsOutputs) {
  test::CliDir dir;
  const auto r = dir.run({"sweep", "--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"[[points]]", "--jobs", "flowcurves.csv", "continuation", "--set",
                           "sweep.toml", "docs/sweeps.md"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  const auto plot = dir.run({"plot", "--help"});
  EXPECT_EQ(plot.exit_code, 0);
  EXPECT_NE(plot.out.find("Fig. 1c"), std::string::npos);
}

}  // namespace
}  // namespace dilatant::sweep_command_test
