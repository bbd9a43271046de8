// Reading one flow curve: plain tables, rheometer exports (metadata, ';' or tab,
// decimal commas, mPa·s, a units row, UTF-16 or Windows-1252 text), and every
// malformed file refused with "file:line: problem".
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "analysis/rheometer_file.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::analysis::flow_curve_csv_test {
namespace {

const std::filesystem::path kAntonPaarExport =
    std::filesystem::path(DILATANT_SOURCE_DIR) / "tests/analysis/data/anton_paar_export.csv";

TEST(FlowCurveCsv, ReadsAPlainTableAndReturnsAscendingStressInSI) {
  test::TempDir dir;
  // A descending ramp, viscosity in mPa·s, stress in Pa.
  const auto file = dir.write("a.csv",
                              "Shear Rate (1/s),Shear Stress (Pa),Viscosity (mPa.s)\n"
                              "100,50,500\n"
                              "40,20,500\n"
                              "10,5,500\n");
  const auto points = read_flow_curve_file(file).points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].shear_stress, 5.0);
  EXPECT_EQ(points[0].shear_rate, 10.0);
  EXPECT_DOUBLE_EQ(points[0].viscosity, 0.5);  // 500 mPa·s
  EXPECT_EQ(points[0].line, 4u);
  EXPECT_EQ(points[2].shear_stress, 50.0);
  EXPECT_EQ(points[2].line, 2u);
}

TEST(FlowCurveCsv, ReadsTheShippedAntonPaarExport) {
  // tests/analysis/data/anton_paar_export.csv: metadata lines, "Interval data:"
  // header, a units row, ';' separators, decimal commas, viscosity in mPa·s.
  const auto points = read_flow_curve_file(kAntonPaarExport).points;
  ASSERT_EQ(points.size(), 49u);
  EXPECT_DOUBLE_EQ(points.front().shear_stress, 0.01);
  EXPECT_DOUBLE_EQ(points.back().shear_stress, 700.0);
  // First data row (line 10): ;1;2,041;30,401;700;23025;Dy_auto
  EXPECT_EQ(points.back().line, 10u);
  EXPECT_DOUBLE_EQ(points.back().shear_rate, 30.401);
  EXPECT_DOUBLE_EQ(points.back().viscosity, 23.025);
  // Every value is written with 5 significant digits (relative rounding <= 5e-5
  // each): eta * rate / stress is 1 within 2e-4 only if mPa·s was converted.
  for (const auto& p : points)
    EXPECT_NEAR(p.viscosity * p.shear_rate / p.shear_stress, 1.0, 2e-4) << "line " << p.line;
}

TEST(FlowCurveCsv, ReadsAFrenchRheoCompassExportInUtf16) {
  // The layout of issue 32: metadata lines, the "Interval données:" header in
  // French, a units row, tabs, decimal commas, viscosity in mPa·s, an empty
  // frequency column.
  test::TempDir dir;
  const std::string text =
      "Projet:\tsuspension\n"
      "Test:\tcourbe\n"
      "R\xC3\xA9sultat:\tFlow Curve 1\n"
      "Intervalle et points de donn\xC3\xA9\x65s:\t1\t4\n"
      "Interval donn\xC3\xA9\x65s:\tPoint No.\tTemps\tIntervalle Temps\tContrainte de "
      "Cisaillement\tGradient de Cisaillement\tFr\xC3\xA9quence\tViscosit\xC3\xA9\n"
      "\t\t[s]\t[s]\t[Pa]\t[1/s]\t[Hz]\t[mPa\xC2\xB7s]\n"
      "\t1\t1\t1\t73,196\t300\t\t243,99\n"
      "\t2\t2\t1\t20,5\t100\t\t205\n"
      "\t3\t3\t1\t5,4\t30\t\t180\n"
      "\t4\t4\t1\t1,6\t10\t\t160\n";
  const auto points = read_flow_curve_file(dir.write("fr.csv", test::utf16le(text))).points;
  ASSERT_EQ(points.size(), 4u);
  EXPECT_DOUBLE_EQ(points.front().shear_stress, 1.6);
  EXPECT_DOUBLE_EQ(points.front().shear_rate, 10.0);
  EXPECT_DOUBLE_EQ(points.front().viscosity, 0.16);  // 160 mPa·s
  EXPECT_EQ(points.front().line, 10u);
  EXPECT_DOUBLE_EQ(points.back().shear_stress, 73.196);
  EXPECT_DOUBLE_EQ(points.back().viscosity, 0.24399);
}

TEST(FlowCurveCsv, ReadsAOneStepMalvernExportWithSuperscriptUnits) {
  // Malvern rSpace: ';', decimal commas, units in parentheses with a Unicode
  // superscript ("s-¹"), a text column naming the step. (Files of several
  // steps are issue 32's next item.)
  test::TempDir dir;
  const auto points =
      read_flow_curve_file(
          dir.write("m.csv",
                    "Action Name;Time (sequence)(s);Shear stress(Pa);Shear rate(s-\xC2\xB9);"
                    "Normal force(N)\n"
                    "Flow Curve Up;112,3;1,5;3,0;0,2044\n"
                    "Flow Curve Up;113,3;3,0;6,1;0,2044\n"
                    "Flow Curve Up;114,3;6,0;12,5;0,2044\n"))
          .points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points[1].shear_stress, 3.0);
  EXPECT_DOUBLE_EQ(points[1].shear_rate, 6.1);
}

TEST(FlowCurveCsv, ReadsTabsUnitsRowsWindowsCodePageAndTwoColumns) {
  test::TempDir dir;
  // Tab-separated, units row with a Windows-1252 middle dot, decimal commas.
  const auto tsv =
      read_flow_curve_file(
          dir.write(
              "b.txt",
              "Test:\tB\n\nInterval data:\tShear Rate\tViscosity\n\t[1/s]\t[mPa\xB7s]\n\t2,5\t400\n"
              "\t5\t400\n\t10\t400\n"))
          .points;
  ASSERT_EQ(tsv.size(), 3u);
  EXPECT_DOUBLE_EQ(tsv[0].shear_stress, 2.5 * 0.4);  // computed: eta * rate
  EXPECT_DOUBLE_EQ(tsv[2].viscosity, 0.4);
  // Stress and rate only, no units (SI); ascending ramp.
  const auto plain =
      read_flow_curve_file(dir.write("c.tsv", "tau\tgamma_dot\n1\t2\n2\t4\n4\t8\n")).points;
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_DOUBLE_EQ(plain[1].viscosity, 0.5);
}

// Rows with a missing, zero or negative value are dropped and counted, as an
// instrument writes them at a step's start (zero stress) or where a reading
// failed; the rest of the curve is read.
TEST(FlowCurveCsv, DropsRowsWithAMissingZeroOrNegativeValueAndCountsThem) {
  test::TempDir dir;
  const auto file = dir.write("steps.csv",
                              "shear_rate;shear_stress\n0;0\n1;1\n-2;2\n2;2\n;3\n3;nan\n"
                              "4;4\n5;0\n");
  const FlowCurveFile read = read_flow_curve_file(file);
  ASSERT_EQ(read.points.size(), 3u);
  EXPECT_EQ(read.points[2].line, 8u);
  EXPECT_EQ(read.dropped_rows, 5u);
  EXPECT_EQ(read.dropped,
            "5 rows dropped (missing value: lines 6, 7; zero or negative value: lines 2, 4, 9)");
}

// Every row's viscosity agrees with stress / rate within its written digits:
// the shipped examples and exports (5 significant digits, rounded) pass.
TEST(FlowCurveCsv, ViscosityWithinItsWrittenDigitsIsAccepted) {
  test::TempDir dir;
  // 0.333 is 0.1% from 1/3: within the 0.3% + 0.3% + 1% its digits allow.
  const auto points = read_flow_curve_file(dir.write("r.csv",
                                                     "Shear Rate,Shear Stress,Viscosity\n"
                                                     "3.00,1.00,0.333\n6.00,2.00,0.333\n"
                                                     "9.00,3.00,0.333\n"))
                          .points;
  EXPECT_EQ(points.size(), 3u);
}

struct BadFile {
  std::string name;
  std::string text;
  int line;             // expected in "file:line:"
  std::string problem;  // expected in the message
};

std::vector<BadFile> bad_files() {
  return {
      {"MissingColumn", "Shear Stress [Pa],Time [s]\n1,1\n2,2\n3,3\n", 1, "missing column"},
      {"TextInANumber", "Shear Rate [1/s],Shear Stress [Pa]\n1,1\n2,abc\n3,3\n", 3,
       "'abc' is not a number"},
      {"EmptyFile", "", 1, "empty file"},
      {"BlankFile", "\n  \n", 1, "empty file"},
      {"SinglePoint", "shear_rate,shear_stress\n1,1\n", 2, "only 1 data point"},
      {"HeaderOnly", "shear_rate,shear_stress\n", 1, "only 0 data points"},
      {"UnsortedData", "shear_rate,shear_stress\n1,1\n3,3\n2,2\n", 4, "breaks the ascending"},
      // A repeated ramp value is dropped and counted (TRIOS writes set points
      // with too few digits); what is left must still be a curve.
      {"RepeatedStress", "shear_rate,shear_stress\n1,1\n2,2\n2.1,2\n", 3,
       "only 2 data points after the header; a flow curve needs at least 3 (1 row dropped "
       "(repeated ramp value: line 4))"},
      // A spike is named on its own line, not on the next one (issue 31).
      {"Spike", "shear_rate,shear_stress\n1,1\n2,2\n9,9\n4,4\n5,5\n", 4,
       "shear stress 9 breaks the ascending ramp (after 2 on line 3, before 4 on line 5)"},
      {"StrayFirstPoint", "shear_rate,shear_stress\n9,9\n2,2\n3,3\n4,4\n", 2,
       "shear stress 9 breaks the ascending ramp"},
      {"DropOut", "shear_rate,shear_stress\n5,5\n4,4\n0.5,0.5\n3,3\n2,2\n", 4,
       "shear stress 0.5 breaks the descending ramp"},
      {"Infinite", "shear_rate,shear_stress\n1,1\n2,inf\n3,3\n", 3, "not a finite number"},
      // A field too few or too many: the file is malformed, not the value (issue 31).
      {"MissingField", "shear_rate,shear_stress\n1,1\n2\n3,3\n", 3, "1 field, the header has 2"},
      {"ExtraField", "shear_rate,shear_stress\n1,1\n2,2,7\n3,3\n4,4\n", 3,
       "3 fields, the header has 2"},
      {"ExtraFieldInUnitsRow", "shear_rate;shear_stress\n[1/s];[Pa];[s]\n1;1\n2;2\n3;3\n", 2,
       "3 fields, the header has 2"},
      // Viscosity off by 10% in one row, where 5 digits allow 0.012%.
      {"ViscosityDisagrees",
       "Shear Rate [1/s],Shear Stress [Pa],Viscosity [Pa s]\n1.0000,1.0000,1.0000\n"
       "2.0000,4.0000,2.2000\n3.0000,9.0000,3.0000\n4.0000,16.000,4.0000\n",
       3, "viscosity 2.2 disagrees with shear stress / shear rate = 2 by 10%"},
      {"AllRowsDropped", "shear_rate,shear_stress\n0,1\n2,0\n,3\n", 1,
       "only 0 data points after the header; a flow curve needs at least 3 (3 rows dropped "
       "(missing value: line 4; zero or negative value: lines 2, 3))"},
      {"UnknownUnit", "Shear Rate [1/s],Viscosity [Poise]\n1,1\n2,2\n3,3\n", 1,
       "unknown unit 'Poise'"},
      {"UnknownUnitInUnitsRow", "Shear Rate;Shear Stress\n[1/min];[Pa]\n1;1\n2;2\n3;3\n", 2,
       "unknown unit '1/min'"},
      // Viscosity written in mPa·s but labelled Pa·s: eta*rate/tau = 1000.
      {"InconsistentUnits",
       "Shear Rate [1/s],Shear Stress [Pa],Viscosity [Pa s]\n1,1,1000\n2,2,1000\n4,4,1000\n", 1,
       "unit"},
      {"NoHeader", "1,2\n3,4\n", 1, "data before any header"},
      {"TwoStressColumns", "shear_rate,stress,tau\n1,1,1\n2,2,2\n3,3,3\n", 1,
       "two shear stress columns"},
  };
}

class FlowCurveCsvBad : public ::testing::TestWithParam<BadFile> {};

TEST_P(FlowCurveCsvBad, IsRefusedWithFileLineAndProblem) {
  const BadFile& c = GetParam();
  test::TempDir dir;
  const auto file = dir.write("bad.csv", c.text);
  const std::string message = test::input_error_message([&] { read_flow_curve_file(file); });
  EXPECT_EQ(message.rfind(file.string() + ":" + std::to_string(c.line) + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(c.problem), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
}

INSTANTIATE_TEST_SUITE_P(FlowCurveCsv, FlowCurveCsvBad, ::testing::ValuesIn(bad_files()),
                         [](const auto& p) { return p.param.name; });

TEST(FlowCurveCsv, AMissingFileIsAnInputError) {
  const std::string message =
      test::input_error_message([] { read_flow_curve_file("/nonexistent/flow.csv"); });
  EXPECT_NE(message.find("/nonexistent/flow.csv"), std::string::npos) << message;
}

}  // namespace
}  // namespace dilatant::analysis::flow_curve_csv_test
