// flowcurves.csv: its columns, done / failed / pending rows, and that
// `dilatant analyze` reads it (failed and pending rows left out, curves by
// phi and sample).
#include "sweep/flow_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analysis/analysis_input.hpp"
#include "analysis/delimited_text.hpp"
#include "io/io_test_files.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep::flow_table_test {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

nlohmann::json summary(double lambda, bool jammed) {
  nlohmann::json j;
  j["shear_stress"] = lambda * lambda;
  j["gamma_dot"] = jammed ? 0.0 : lambda;
  j["gamma_dot_err"] = 0.01 * lambda;
  j["eta"] = jammed ? nlohmann::json(nullptr) : nlohmann::json(lambda);
  j["valid"] = !jammed;
  j["jammed"] = jammed;
  j["phi"] = 0.5791;
  j["steps"] = 120;
  j["friction_law"] = "stribeck";
  j["version"] = "test";
  return j;
}

TEST(FlowTable, OneRowPerPointSweptKeysFirstThenStatusAndSummary) {
  const SweepPlan plan = parse_sweep(test::kTinyGrid, "s.toml", ".", {});
  std::vector<PointRecord> records(4);
  records[0] = {PointStatus::Done, "", summary(3.0, false), {}, {}};
  records[1] = {PointStatus::Failed, "could not pack, \"really\"", {}, {}, {}};
  records[2] = {PointStatus::Running, "", {}, {}, {}};
  records[3] = {PointStatus::Done, "", summary(30.0, true), {}, {}};
  const auto rows = lines(flowcurves_csv(plan, records));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].rfind("friction.mu0,fluid.lambda,point,status,error,phi,mu0,lambda,"
                          "shear_stress,gamma_dot,gamma_dot_err,eta,eta_err,valid,jammed,frac_bl,",
                          0),
            0u)
      << rows[0];
  const auto header = analysis::split_fields(rows[0], ',');
  EXPECT_EQ(header.back(), "jam_cold_start_phi_bulk_start");
  EXPECT_EQ(header[header.size() - 5], "jam_cold_start");
  const auto column = [&](std::size_t row, const std::string& name) {
    const auto fields = analysis::split_fields(rows[row], ',');
    EXPECT_EQ(fields.size(), header.size()) << rows[row];
    const auto at = std::find(header.begin(), header.end(), name) - header.begin();
    return fields.at(static_cast<std::size_t>(at));
  };
  EXPECT_EQ(column(1, "status"), "done");
  EXPECT_EQ(column(1, "friction.mu0"), "0.1");
  EXPECT_EQ(column(1, "fluid.lambda"), "3.0");
  EXPECT_EQ(column(1, "lambda"), "3");
  EXPECT_EQ(column(1, "phi"), "0.58");  // as requested
  EXPECT_EQ(column(1, "phi_realized"), "0.5791");
  EXPECT_EQ(column(1, "shear_stress"), "9");
  EXPECT_EQ(column(1, "valid"), "true");
  EXPECT_EQ(column(1, "steps"), "120");
  EXPECT_EQ(column(1, "sample"), "mu0=0.1");
  EXPECT_EQ(column(1, "start"), "cold");
  EXPECT_EQ(column(1, "dir"), "points/000-mu0=0.1_lambda=3");
  EXPECT_EQ(column(2, "status"), "failed");
  EXPECT_EQ(column(2, "error"), "could not pack, 'really'");  // quoted in the file
  EXPECT_EQ(column(2, "gamma_dot"), "");
  EXPECT_EQ(column(3, "status"), "pending");  // running is pending in the table
  EXPECT_EQ(column(4, "eta"), "");            // jammed
  EXPECT_EQ(column(4, "jammed"), "true");
}

// A point's row is filled from the summary its run returns, in memory; a
// resumed sweep reads finished points' summary.json from disk. Both must give
// the same row, byte for byte: numbers print as the shortest text that reads
// back exactly, and a value summary.json cannot hold (NaN, written as null)
// is empty in either.
TEST(FlowTable, SummaryInMemoryAndReadBackGiveTheSameRow) {
  const SweepPlan plan = parse_sweep(test::kTinyGrid, "s.toml", ".", {});
  nlohmann::json in_memory = summary(3.0, false);
  in_memory["gamma_dot"] = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
  in_memory["eta_err"] = std::nan("");
  in_memory["mobile_spheres"] = std::size_t{470};
  in_memory["steps"] = -1L;  // a signed integer in memory, any sign
  std::vector<PointRecord> memory(4), disk(4);
  memory[0] = {PointStatus::Done, "", in_memory, {}, {}};
  disk[0] = {PointStatus::Done, "", nlohmann::json::parse(in_memory.dump(2)), {}, {}};
  const auto from_memory = lines(flowcurves_csv(plan, memory));
  EXPECT_EQ(from_memory, lines(flowcurves_csv(plan, disk)));
  EXPECT_NE(from_memory[1].find(",0.30000000000000004,"), std::string::npos) << from_memory[1];
}

// A rate sweep (cell.control = "rate") places its points along the curve by
// cell.shear_rate, as a stress ramp does by lambda: the rate names no curve.
TEST(FlowTable, ASweptShearRateIsACurvesAxisNotItsSample) {
  const SweepPlan plan = parse_sweep(
      "[cell]\nsize = [6.0, 5.0, 7.0]\nphi = 0.55\nboundary = \"lees-edwards\"\n"
      "control = \"rate\"\nshear_rate = [0.01, 0.1]\n[friction]\nmu0 = [0.1, 0.4]\n",
      "s.toml", ".", {});
  ASSERT_EQ(plan.points.size(), 4u);
  // The key written first varies slowest: rate 0.01 with mu0 0.1, 0.4, then 0.1.
  EXPECT_EQ(sample_label(plan, plan.points[0]), "mu0=0.1");
  EXPECT_EQ(sample_label(plan, plan.points[1]), "mu0=0.4");
  EXPECT_EQ(sample_label(plan, plan.points[2]), "mu0=0.1");
}

// A sweep of the pressure-imposed cell (cell.control = "pressure") moves J =
// eta_f gamma_dot / P by cell.normal_stress or cell.shear_rate: neither names
// a curve, and each row carries what mu(J) and phi(J) need (Boyer, Guazzelli
// & Pouliquen, PRL 107, 188301 (2011)): the imposed and measured normal
// stress, phi_bulk, mu_eff, J and I, and the lid's height.
TEST(FlowTable, APressureSweepsRowsCarryTheImposedStressAndTheMeasuredPhiAndMu) {
  const SweepPlan plan = parse_sweep(
      "[cell]\nsize = [6.0, 5.0, 7.0]\nphi = 0.55\nboundary = \"lees-edwards\"\n"
      "control = \"pressure\"\nshear_rate = [0.01, 0.1]\nnormal_stress = [1.0, 4.0]\n"
      "[friction]\nmu0 = 0.4\n",
      "s.toml", ".", {});
  ASSERT_EQ(plan.points.size(), 4u);
  for (const auto& p : plan.points) EXPECT_EQ(sample_label(plan, p), "mu0=0.4");
  nlohmann::json done = summary(1.0, false);
  done["control"] = "pressure";
  done["normal_stress_imposed"] = 4.0;
  done["normal_stress"] = 3.9;
  done["phi_bulk"] = 0.571;
  done["mu_eff"] = 0.42;
  done["viscous_number"] = 0.025;
  done["inertial_number"] = 0.05;
  done["box_height_mean"] = 7.2;
  done["box_height_fluctuation"] = 0.01;
  std::vector<PointRecord> records(4);
  records[1] = {PointStatus::Done, "", done, {}, {}};
  const auto rows = lines(flowcurves_csv(plan, records));
  const auto header = analysis::split_fields(rows[0], ',');
  EXPECT_EQ(header[0], "cell.shear_rate");
  EXPECT_EQ(header[1], "cell.normal_stress");
  const auto fields = analysis::split_fields(rows[2], ',');
  ASSERT_EQ(fields.size(), header.size());
  const auto column = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    EXPECT_NE(at, header.end()) << name;
    return at == header.end() ? std::string("?")
                              : fields[static_cast<std::size_t>(at - header.begin())];
  };
  EXPECT_EQ(column("cell.normal_stress"), "4.0");
  EXPECT_EQ(column("control"), "pressure");
  EXPECT_EQ(column("normal_stress_imposed"), "4");
  EXPECT_EQ(column("normal_stress"), "3.9");
  EXPECT_EQ(column("phi_bulk"), "0.571");
  EXPECT_EQ(column("mu_eff"), "0.42");
  EXPECT_EQ(column("viscous_number"), "0.025");
  EXPECT_EQ(column("inertial_number"), "0.05");
  EXPECT_EQ(column("box_height_mean"), "7.2");
  EXPECT_EQ(column("box_height_fluctuation"), "0.01");
  EXPECT_EQ(column("sample"), "mu0=0.4");
}

TEST(FlowTable, AnalyzeReadsDoneRowsOnlyAndGroupsCurvesByPhiAndSample) {
  test::TempDir dir;
  const SweepPlan plan =
      parse_sweep(test::kTinyCell +
                      "[fluid]\nlambda = [3.0, 30.0]\n[friction]\nlaw = [\"stribeck\", "
                      "\"coulomb\"]\n",
                  "s.toml", ".", {});
  ASSERT_EQ(plan.points.size(), 4u);
  EXPECT_EQ(sample_label(plan, plan.points[1]), "mu0=0.1 law=coulomb");
  std::vector<PointRecord> records(4);
  records[0] = {PointStatus::Done, "", summary(3.0, false), {}, {}};
  records[1] = {PointStatus::Done, "", summary(3.0, false), {}, {}};
  records[2] = {PointStatus::Done, "", summary(30.0, false), {}, {}};
  records[3] = {PointStatus::Failed, "boom", {}, {}, {}};
  const auto file = dir.write("flowcurves.csv", flowcurves_csv(plan, records));
  const analysis::AnalysisInput in = analysis::read_sweep_table(file);
  // Two curves at phi 0.58: Stribeck with 2 points, Coulomb with the 1 done.
  ASSERT_EQ(in.curves.size(), 2u);
  EXPECT_EQ(in.curves[0].sample, "mu0=0.1 law=stribeck");
  EXPECT_EQ(in.curves[0].points.size(), 2u);
  EXPECT_EQ(in.curves[1].sample, "mu0=0.1 law=coulomb");
  EXPECT_EQ(in.curves[1].points.size(), 1u);
  // Nothing finished: a table without results, said so.
  std::vector<PointRecord> none(4);
  const auto empty = dir.write("none.csv", flowcurves_csv(plan, none));
  const std::string message = test::input_error_message([&] { analysis::read_sweep_table(empty); });
  EXPECT_NE(message.find("no finished point"), std::string::npos) << message;
}

}  // namespace
}  // namespace dilatant::sweep::flow_table_test
