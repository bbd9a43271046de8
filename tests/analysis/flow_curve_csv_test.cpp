// Reading one flow curve: plain tables, rheometer exports (metadata, ';' or tab,
// decimal commas, mPa·s, a units row, UTF-16 or Windows-1252 text), and every
// malformed file refused with "file:line: problem".
#include "analysis/flow_curve_csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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
  const auto points = read_flow_curve_file(file);
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
  const auto points = read_flow_curve_file(kAntonPaarExport);
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

TEST(FlowCurveCsv, ReadsTabsUnitsRowsWindowsCodePageAndTwoColumns) {
  test::TempDir dir;
  // Tab-separated, units row with a Windows-1252 middle dot, decimal commas.
  const auto tsv = read_flow_curve_file(dir.write(
      "b.txt",
      "Test:\tB\n\nInterval data:\tShear Rate\tViscosity\n\t[1/s]\t[mPa\xB7s]\n\t2,5\t400\n"
      "\t5\t400\n\t10\t400\n"));
  ASSERT_EQ(tsv.size(), 3u);
  EXPECT_DOUBLE_EQ(tsv[0].shear_stress, 2.5 * 0.4);  // computed: eta * rate
  EXPECT_DOUBLE_EQ(tsv[2].viscosity, 0.4);
  // Stress and rate only, no units (SI); ascending ramp.
  const auto plain = read_flow_curve_file(dir.write("c.tsv", "tau\tgamma_dot\n1\t2\n2\t4\n4\t8\n"));
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_DOUBLE_EQ(plain[1].viscosity, 0.5);
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
      {"UnsortedData", "shear_rate,shear_stress\n1,1\n3,3\n2,2\n", 4, "does not continue"},
      {"RepeatedStress", "shear_rate,shear_stress\n1,1\n2,2\n2.1,2\n", 4, "does not continue"},
      {"NaN", "shear_rate,shear_stress\n1,1\n2,nan\n3,3\n", 3, "not a finite number"},
      {"NegativeRate", "shear_rate,shear_stress\n1,1\n-2,2\n3,3\n", 3, "must be > 0"},
      {"EmptyField", "shear_rate,shear_stress\n1,1\n,2\n3,3\n", 3, "empty field"},
      {"MissingField", "shear_rate,shear_stress\n1,1\n2\n3,3\n", 3, "missing in this row"},
      {"UnknownUnit", "Shear Rate [1/s],Viscosity [Poise]\n1,1\n2,2\n3,3\n", 1,
       "unknown unit 'Poise'"},
      {"UnknownUnitInUnitsRow", "Shear Rate;Shear Stress\n[1/min];[Pa]\n1;1\n2;2\n3;3\n", 2,
       "unknown unit '1/min'"},
      // Viscosity written in mPa·s but labelled Pa·s: eta*rate/tau = 1000.
      {"InconsistentUnits",
       "Shear Rate [1/s],Shear Stress [Pa],Viscosity [Pa s]\n1,1,1000\n2,2,1000\n4,4,1000\n", 1,
       "unit"},
      {"SecondTable", "shear_rate,shear_stress\n1,1\n2,2\n3,3\n\nshear_rate,shear_stress\n1,1\n", 6,
       "second flow-curve table"},
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
