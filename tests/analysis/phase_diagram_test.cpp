// The phase diagram over (mu0, phi) (analysis/phase_diagram.hpp): every node,
// no accumulated rounding at the grid's ends, and each node's regime the one
// predict_regime gives there; with a bulk table, its nodes are marked `bulk`.
#include "analysis/phase_diagram.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace dilatant::analysis::phase_diagram_test {
namespace {

TEST(PhaseDiagram, EveryNodeWithTheRegimeOfPredict) {
  const auto table = JammingTable::parse(NumericCsv::from_text(
      "mu0,phi_max,phi_max_err\n0,0.64,0.002\n0.5,0.58,0.004\n1,0.56,0.002\n", "t.csv"));
  const PhaseGrid grid{1.0, 0.1, 0.50, 0.66, 0.02};
  std::istringstream csv(phase_diagram_csv(table, nullptr, grid));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "mu0,phi,regime,phi_max_bl,phi_rcp,margin_sigma,uncertain,source");
  int rows = 0, cst = 0, dst = 0, no_flow = 0;
  while (std::getline(csv, line)) {
    ++rows;
    std::istringstream f(line);
    std::string mu, phi, regime;
    std::getline(f, mu, ',');
    std::getline(f, phi, ',');
    std::getline(f, regime, ',');
    const auto p = predict_regime(table, std::stod(mu), std::stod(phi));
    EXPECT_EQ(regime, flow_regime_name(p.regime)) << line;
    cst += regime == "cst";
    dst += regime == "dst";
    no_flow += regime == "no_flow";
  }
  EXPECT_EQ(rows, 11 * 9);  // mu0 0..1 by 0.1, phi 0.50..0.66 by 0.02 (ends included)
  EXPECT_GT(cst, 0);
  EXPECT_GT(dst, 0);
  EXPECT_EQ(no_flow, 11);  // phi 0.66 > 0.64 at every mu0
}

// mu0 1 is CST up to phi 0.58 in the bulk table: those nodes change from the
// sediment's dst (phi_max 0.56) to cst, and say so.
TEST(PhaseDiagram, BulkNodesOverrideTheSedimentAndAreMarked) {
  const auto table = JammingTable::parse(
      NumericCsv::from_text("mu0,phi_max,phi_max_err\n0,0.64,0.002\n1,0.56,0.002\n", "t.csv"));
  const auto bulk = BulkFlowTable::parse(
      NumericCsv::from_text("mu0,phi_bulk,regime,max_lambda,jam_lambda,cell,source,sample\n"
                            "1,0.58,cst,30000,,25x10x27,d.csv,x\n",
                            "b.csv"));
  const PhaseGrid grid{1.0, 0.5, 0.56, 0.60, 0.02};
  const std::string csv = phase_diagram_csv(table, &bulk, grid);
  EXPECT_NE(csv.find("\n1,0.58,cst,0.56000,0.64000,,false,bulk\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n1,0.6,dst,0.56000,0.64000,20,false,sediment\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n0.5,0.58,cst,0.60000,0.64000,10,false,sediment\n"), std::string::npos)
      << csv;
}

}  // namespace
}  // namespace dilatant::analysis::phase_diagram_test
