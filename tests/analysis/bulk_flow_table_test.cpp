// The bulk flow states and when they decide a query (analysis/bulk_flow_table.hpp):
// a cst ramp decides below it (+ the tolerance), a jammed one above it, a dst
// one only near it; other mu0, the bracket between them and phi beyond a dst
// ramp are left to the sediment table. The built-in table reads and answers
// the point of issue 34 (mu0 1, phi 0.58: CST in the Lees–Edwards box).
#include "analysis/bulk_flow_table.hpp"

#include <gtest/gtest.h>

#include "io/input_error.hpp"

namespace dilatant::analysis::bulk_flow_table_test {
namespace {

constexpr const char* kHeader = "mu0,phi_bulk,regime,max_lambda,jam_lambda,cell,source,sample\n";

// The table of `rows` under `header` (default: without the evidence columns),
// read from "b.csv".
BulkFlowTable table_of(const std::string& rows, const std::string& header = kHeader) {
  return BulkFlowTable::parse(NumericCsv::from_text(header + rows, "b.csv"));
}

std::string error_of(const std::string& rows, const std::string& header = kHeader) {
  try {
    table_of(rows, header);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BulkFlowTable, CstDecidesBelowJammedAboveDstNearAndTheRestIsLeft) {
  const auto t = table_of(
      "0.4,0.580,cst,30000,,25x10x27,a.csv,A\n"
      "0.4,0.600,dst,100,1000,25x10x27,a.csv,B\n"
      "0.4,0.620,jammed,,1,25x10x27,a.csv,C\n");
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.50).regime, FlowRegime::Cst);
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.5805).regime, FlowRegime::Cst);  // within 0.0005
  EXPECT_FALSE(decide_from_bulk(t, 0.4, 0.5806).regime);                // the bracket
  EXPECT_FALSE(decide_from_bulk(t, 0.4, 0.59).regime);
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.6004).regime, FlowRegime::Dst);
  EXPECT_FALSE(decide_from_bulk(t, 0.4, 0.61).regime);  // beyond the dst ramp
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.6196).regime, FlowRegime::NoFlow);
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.70).regime, FlowRegime::NoFlow);
  const auto other = decide_from_bulk(t, 0.35, 0.50);
  EXPECT_FALSE(other.regime);
  EXPECT_NE(other.reason.find("no bulk flow curve at mu0 0.35"), std::string::npos) << other.reason;
  const auto above = decide_from_bulk(t, 0.4, 0.59);
  EXPECT_NE(above.reason.find("flow up to phi_bulk 0.5800"), std::string::npos) << above.reason;
}

// Of two cst ramps covering phi, the one that went further in stress decides,
// then the one nearer phi; the answer names its line, file and curve.
TEST(BulkFlowTable, TheStrongestNearestCstRampDecidesAndIsNamed) {
  const auto t = table_of(
      "1,0.5797,cst,200,,25x10x27,f.csv,short\n"
      "1,0.5790,cst,30000,,12x8x14,d.csv,small\n"
      "1,0.5797,cst,30000,,25x10x27,d.csv,big\n");
  const auto at_58 = decide_from_bulk(t, 1.0, 0.58);
  ASSERT_EQ(at_58.regime, FlowRegime::Cst);
  EXPECT_EQ(at_58.row.sample, "big");
  EXPECT_EQ(at_58.row.line, 4u);
  EXPECT_EQ(at_58.reason,
            "mu0 1, phi_bulk 0.5797, 25x10x27 Lees-Edwards box: CST to lambda 30000 (d.csv, "
            "curve big)");
  EXPECT_EQ(decide_from_bulk(t, 1.0, 0.57).row.sample, "small");
}

TEST(BulkFlowTable, BadRowsNameTheirLine) {
  EXPECT_NE(error_of("1,0.58,flows,100,,c,s.csv,x\n").find("b.csv:2: regime \"flows\""),
            std::string::npos);
  EXPECT_NE(error_of("1,0.58,cst,100,\n").find("b.csv:2: 5 fields, the header has 8"),
            std::string::npos);
  EXPECT_NE(error_of("1,0.58,cst,,,c,s.csv,x\n").find("b.csv:2: regime cst with max_lambda"),
            std::string::npos);
  EXPECT_NE(error_of("1,0.58,dst,100,50,c,s.csv,x\n").find("b.csv:2: dst ramp jammed"),
            std::string::npos);
  EXPECT_NE(error_of("1,0.58,cst,100,,c,,x\n").find("b.csv:2: no source"), std::string::npos);
  EXPECT_NE(error_of("1,x,cst,100,,c,s.csv,x\n").find("b.csv:2: phi_bulk = \"x\""),
            std::string::npos);
  EXPECT_NE(error_of("1,0.8,cst,100,,c,s.csv,x\n").find("b.csv:2: mu0 1, phi_bulk 0.8"),
            std::string::npos);
  // A ramp that flows above one that jams at the same mu0: the later line is
  // blamed, the earlier named.
  EXPECT_NE(error_of("1,0.57,jammed,,1,c,s.csv,x\n1,0.58,cst,100,,c,s.csv,y\n")
                .find("b.csv:3: mu0 1: this cst ramp at phi_bulk 0.58 contradicts the jammed "
                      "ramp at phi_bulk 0.57 on line 2"),
            std::string::npos);
  EXPECT_NE(error_of("1,0.58,cst,100,,c,s.csv,x\n1,0.58,dst,100,1000,c,s.csv,y\n")
                .find("b.csv:3: mu0 1: this dst ramp at phi_bulk 0.58 contradicts the cst ramp"),
            std::string::npos);
  EXPECT_NE(error_of("").find("no rows"), std::string::npos);
}

// A ramp whose rate fell without a jam (dst_evidence rate_falls) is DST near
// its phi like a jammed one, and says where the rate fell; a table without the
// evidence column reads its dst rows as jams.
constexpr const char* kEvidenceHeader =
    "mu0,phi_bulk,regime,max_lambda,jam_lambda,cell,source,sample,dst_evidence,fall_lambda\n";

BulkFlowTable evidence_table_of(const std::string& rows) { return table_of(rows, kEvidenceHeader); }

std::string evidence_error_of(const std::string& rows) { return error_of(rows, kEvidenceHeader); }

TEST(BulkFlowTable, ARampWhoseRateFellIsDstWithoutAJam) {
  const auto t = evidence_table_of(
      "0.4,0.6097,dst,10000,,25x10x27,le.csv,mu0=0.4,rate_falls,316\n"
      "0.1,0.6097,cst,10000,,25x10x27,le.csv,mu0=0.1,,\n");
  const auto d = decide_from_bulk(t, 0.4, 0.61);
  ASSERT_EQ(d.regime, FlowRegime::Dst) << d.reason;
  EXPECT_EQ(d.row.dst_evidence, DstEvidence::RateFalls);
  EXPECT_EQ(d.row.fall_lambda, 316.0);
  EXPECT_EQ(d.reason,
            "mu0 0.4, phi_bulk 0.6097, 25x10x27 Lees-Edwards box: flowed to lambda 10000 without "
            "a jam, DST by rate_falls (its rate fell at lambda 316 as the stress rose) (le.csv, "
            "curve mu0=0.4)");
  EXPECT_FALSE(decide_from_bulk(t, 0.4, 0.605).regime);  // below it: not located
  EXPECT_EQ(decide_from_bulk(t, 0.1, 0.61).row.dst_evidence, DstEvidence::None);
  // The window's power law turned over (rule 6's rate_not_increasing) after
  // the rate fell: DST too, the fall where it was.
  const auto turned = evidence_table_of("0.4,0.61,dst,1e6,,c,le.csv,y,rate_not_increasing,316\n");
  EXPECT_EQ(decide_from_bulk(turned, 0.4, 0.61).regime, FlowRegime::Dst);
  EXPECT_NE(decide_from_bulk(turned, 0.4, 0.61)
                .reason.find("DST by rate_not_increasing (its rate "
                             "fell at lambda 316"),
            std::string::npos);
  const auto old = table_of("0.4,0.60,dst,100,1000,c,s.csv,x\n");
  EXPECT_EQ(old.rows()[0].dst_evidence, DstEvidence::Jammed);
  EXPECT_EQ(dst_evidence_name(old.rows()[0].dst_evidence), "jammed");
}

TEST(BulkFlowTable, BadEvidenceNamesItsLine) {
  EXPECT_NE(evidence_error_of("1,0.58,dst,100,,c,s.csv,x,falls,10\n")
                .find("b.csv:2: dst_evidence \"falls\": must be jammed, rate_falls"),
            std::string::npos);
  EXPECT_NE(evidence_error_of("1,0.58,cst,100,,c,s.csv,x,rate_falls,10\n")
                .find("b.csv:2: dst_evidence \"rate_falls\" on a cst row"),
            std::string::npos);
  EXPECT_NE(evidence_error_of("1,0.58,cst,100,,c,s.csv,x,,10\n")
                .find("b.csv:2: fall_lambda 10 on a cst row"),
            std::string::npos);
  EXPECT_NE(evidence_error_of("1,0.58,dst,100,,c,s.csv,x,rate_falls,\n")
                .find("b.csv:2: dst by rate_falls with max_lambda 100, jam_lambda 0 and "
                      "fall_lambda 0: needs"),
            std::string::npos);
  EXPECT_NE(evidence_error_of("1,0.58,dst,100,,c,s.csv,x,rate_falls,1000\n")
                .find("b.csv:2: fall_lambda 1000: the rate falls at a stress the ramp flowed at"),
            std::string::npos);
  EXPECT_NE(evidence_error_of("1,0.58,dst,100,1000,c,s.csv,x,rate_falls,10\n")
                .find("needs max_lambda > 0, no jam_lambda"),
            std::string::npos);
  EXPECT_NE(evidence_error_of("1,0.58,dst,100,,c,s.csv,x,jammed,\n").find("b.csv:2: regime dst"),
            std::string::npos);  // a jam without its lambda
}

// Each dst row decides near its own phi, not only the loosest; of two within
// reach the nearest answers, then the one with fewer steps at the iteration
// cap (a rerun of the same ramp at a higher cap); the share is checked.
TEST(BulkFlowTable, TheNearestBestConvergedDstRowAnswers) {
  const std::string header =
      "mu0,phi_bulk,regime,max_lambda,jam_lambda,cell,source,sample,dst_evidence,fall_lambda,"
      "max_frac_unconverged\n";
  const auto t = table_of(
      "0.4,0.6097,dst,316,,c,first.csv,capped,rate_falls,316,0.29\n"
      "0.4,0.6097,dst,316,,c,rerun.csv,converged,rate_falls,316,0.00024\n"
      "0.4,0.6099,dst,316,,c,rerun.csv,seed2,n_above_cap,316,0.00028\n"
      "0.4,0.6200,dst,316,,c,dense.csv,dense,rate_falls,316,0\n",
      header);
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.6097).row.sample, "converged");
  EXPECT_EQ(decide_from_bulk(t, 0.4, 0.6100).row.sample, "seed2");
  const auto dense = decide_from_bulk(t, 0.4, 0.62);
  ASSERT_EQ(dense.regime, FlowRegime::Dst) << dense.reason;
  EXPECT_EQ(dense.row.sample, "dense");
  EXPECT_FALSE(decide_from_bulk(t, 0.4, 0.615).regime);  // between the two: not located
  EXPECT_EQ(t.rows()[0].max_frac_unconverged, 0.29);
  EXPECT_NE(error_of("1,0.58,cst,100,,c,s.csv,x,,,1.5\n", header)
                .find("b.csv:2: max_frac_unconverged 1.5: a share of steps, in [0, 1]"),
            std::string::npos);
}

TEST(BulkFlowTable, TheBuiltInTableDecidesMu0OneAtPhi058) {
  const auto t = BulkFlowTable::builtin();
  const auto d = decide_from_bulk(t, 1.0, 0.58);
  ASSERT_EQ(d.regime, FlowRegime::Cst) << d.reason;
  EXPECT_EQ(d.row.max_lambda, 30000.0);
  EXPECT_NE(d.row.source.find("lees-edwards-dst/flowcurves.csv"), std::string::npos);
  EXPECT_FALSE(decide_from_bulk(t, 0.35, 0.58).regime);
}

}  // namespace
}  // namespace dilatant::analysis::bulk_flow_table_test
