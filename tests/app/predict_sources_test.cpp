// `dilatant predict`'s order of sources end to end (docs/jamming.md "The
// predictor's sources"): a Wyart–Cates fit if given, then the flow states
// measured in bulk, then the sediment table; every answer names its source,
// and a bad bulk table is exit 2 with one line naming its file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::predict_sources_test {
namespace {

namespace fs = std::filesystem;

nlohmann::json answer(test::CliDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), "predict");
  args.emplace_back("--json");
  const auto r = dir.run(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// Issue 34: at phi_bulk 0.58 the Lees–Edwards ramps of mu0 1 flow to lambda
// 3e4, where the sediment's phi_max_BL(1) = 0.559 says dst.
TEST(PredictSources, TheBulkFlowCurvesAnswerMu0OneAtPhi058AndSaySo) {
  test::CliDir dir;
  const auto j = answer(dir, {"--mu0", "1", "--phi", "0.58"});
  EXPECT_EQ(j["regime"], "cst");
  EXPECT_EQ(j["source"], "bulk flow curves");
  EXPECT_EQ(j["sediment"]["regime"], "dst");
  EXPECT_EQ(j["bulk"]["max_lambda"], 30000.0);
  EXPECT_EQ(j["bulk"]["cell"], "25x10x27");
  EXPECT_TRUE(j["uncertain"] == false && j["margin_sigma"].is_null());
  const std::string detail = j["source_detail"];
  EXPECT_EQ(
      detail.rfind("bulk flow curves (data/jamming/bulk_flow_states.csv (built in), line ", 0), 0u)
      << detail;
  EXPECT_NE(detail.find("CST to lambda 30000"), std::string::npos) << detail;
  EXPECT_NE(detail.find("lees-edwards-dst/flowcurves.csv"), std::string::npos) << detail;
  const auto text = dir.run({"predict", "--mu0", "1", "--phi", "0.58"});
  EXPECT_EQ(text.out.rfind("cst (measured in bulk; the sediment table alone would say dst", 0), 0u)
      << text.out;
  EXPECT_NE(text.out.find("\nsource: bulk flow curves (data/jamming/bulk_flow_states.csv"),
            std::string::npos)
      << text.out;
}

// Issue 34: the decisive study's mu0 0.4 ramps at phi_bulk 0.61 fell (their
// rate 3.97 times lower at tau 1e5 than at 1e4) and run on above: their rows
// are the bulk table's first dst, and answer there, naming the fall.
TEST(PredictSources, TheDecisiveRampsFallIsABulkDstAtMu0Point4) {
  test::CliDir dir;
  const auto j = answer(dir, {"--mu0", "0.4", "--phi", "0.61"});
  EXPECT_EQ(j["regime"], "dst");
  EXPECT_EQ(j["source"], "bulk flow curves");
  EXPECT_EQ(j["bulk"]["fall_lambda"], 316.0);
  // Flowed at every stress: the evidence is the analysis's, never a jam
  // (which rule fires first depends on the window of points run so far).
  const std::string evidence = j["bulk"]["dst_evidence"];
  EXPECT_TRUE(evidence == "rate_falls" || evidence == "rate_not_increasing" ||
              evidence == "n_above_cap")
      << evidence;
  EXPECT_NE(j["source_detail"].get<std::string>().find("decisive-le"), std::string::npos)
      << j["source_detail"];
  // Between the densest CST ramp (0.5797) and the falls (0.6097) the boundary
  // is not located: the sediment answers.
  const auto between = answer(dir, {"--mu0", "0.4", "--phi", "0.60"});
  EXPECT_EQ(between["source"], "sediment table");
}

TEST(PredictSources, OutsideTheBulkTableTheSedimentAnswersAndSaysWhy) {
  test::CliDir dir;
  // mu0 0.6: a sediment row, no bulk ramp (the decisive study runs 0.01-1 without it).
  const auto other_mu0 = answer(dir, {"--mu0", "0.6", "--phi", "0.58"});
  EXPECT_EQ(other_mu0["source"], "sediment table");
  EXPECT_TRUE(other_mu0["bulk"].is_null());
  EXPECT_NE(other_mu0["bulk_reason"].get<std::string>().find("no bulk flow curve at mu0 0.6"),
            std::string::npos);
  const auto denser = answer(dir, {"--mu0", "1", "--phi", "0.60"});
  EXPECT_EQ(denser["source"], "sediment table");
  EXPECT_EQ(denser["regime"], "dst");
  EXPECT_NE(denser["source_detail"].get<std::string>().find("flow up to phi_bulk 0.5797"),
            std::string::npos)
      << denser["source_detail"];
  const auto none = answer(dir, {"--mu0", "1", "--phi", "0.58", "--bulk-table", "none"});
  EXPECT_EQ(none["regime"], "dst");
  EXPECT_EQ(none["source_detail"],
            "sediment table (data/jamming/phi_max_bl.csv (built in)); no bulk table used");
  const auto text = dir.run({"predict", "--mu0", "0.6", "--phi", "0.58"});
  EXPECT_NE(text.out.find("\nsource: sediment table (data/jamming/phi_max_bl.csv (built in)); bulk "
                          "flow curves: no bulk flow curve at mu0 0.6"),
            std::string::npos)
      << text.out;
}

// A user's fit comes first: with --model the tables are not asked (and
// --bulk-table beside --model is refused).
TEST(PredictSources, AFittedModelWinsOverBothTables) {
  test::CliDir dir;
  const fs::path model = fs::path(DILATANT_SOURCE_DIR) / "docs/laws/viscous/wyart_cates.json";
  const auto j = answer(dir, {"--model", model.string(), "--phi", "0.58"});
  EXPECT_EQ(j["source"], "wyart-cates fit");
  const auto both =
      dir.run({"predict", "--model", model.string(), "--phi", "0.58", "--bulk-table", "none"});
  EXPECT_EQ(both.exit_code, 2) << both.err;
}

TEST(PredictSources, AUserBulkTableIsReadAndBadOnesAreExit2NamingTheLine) {
  test::CliDir dir;
  const std::string header = "mu0,phi_bulk,regime,max_lambda,jam_lambda,cell,source,sample\n";
  std::ofstream(dir.path() / "b.csv") << header << "0.35,0.57,jammed,,10,10x10x10,mine.csv,A\n";
  const auto mine = answer(
      dir, {"--mu0", "0.35", "--phi", "0.58", "--bulk-table", (dir.path() / "b.csv").string()});
  EXPECT_EQ(mine["regime"], "no_flow");
  EXPECT_EQ(mine["bulk_table"], (dir.path() / "b.csv").string());
  const std::vector<std::pair<std::string, std::string>> bad = {
      {header + "1,0.58,cst,100,,c,s.csv,x\n1,0.58,maybe,100,,c,s.csv,x\n", ":3: regime"},
      {header + "1,0.58,cst,100\n", ":2: 4 fields, the header has 8"},
      {"mu0,phi_bulk,regime\n1,0.58,cst\n", ":1: no column max_lambda"},
      {header + "1,0.57,dst,10,100,c,s.csv,x\n1,0.58,cst,100,,c,s.csv,y\n", ":3: mu0 1"},
  };
  for (const auto& [text, says] : bad) {
    std::ofstream(dir.path() / "bad.csv") << text;
    const auto r = dir.run({"predict", "--mu0", "1", "--phi", "0.58", "--bulk-table",
                            (dir.path() / "bad.csv").string()});
    EXPECT_EQ(r.exit_code, 2) << says;
    EXPECT_NE(r.err.find("bad.csv" + says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto missing = dir.run({"predict", "--mu0", "1", "--phi", "0.58", "--bulk-table",
                                (dir.path() / "missing.csv").string()});
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_NE(missing.err.find("missing.csv"), std::string::npos) << missing.err;
}

// --grid marks the nodes the bulk decided.
TEST(PredictSources, TheGridNamesEachNodesSource) {
  test::CliDir dir;
  const auto r = dir.run({"predict", "--grid", "--no-plots", "--out", dir.path().string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = test::read_text(dir.path() / "phase_diagram.csv");
  EXPECT_EQ(csv.rfind("mu0,phi,regime,phi_max_bl,phi_rcp,margin_sigma,uncertain,source\n", 0), 0u);
  EXPECT_NE(csv.find("\n1,0.58,cst,0.55931,0.63555,,false,bulk\n"), std::string::npos);
  EXPECT_NE(csv.find("\n1,0.6,dst,0.55931,0.63555,"), std::string::npos);
}

}  // namespace
}  // namespace dilatant::predict_sources_test
