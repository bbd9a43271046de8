// Rheometer exports of several steps, in the layouts the vendors write
// (issue 32): each is split into its steps, each step's kind is recognised,
// and the flow-curve steps become curves with the right points.
#include "analysis/rheometer_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/io_test_files.hpp"

namespace dilatant::analysis::rheometer_file_test {
namespace {

// Malvern Kinexus rSpace: ';', decimal commas, the step in "Action Name",
// superscript units, every step in one table; a zero row where the up-ramp
// starts; the oscillation step leaves the flow columns empty.
const std::string kMalvern =
    "Action Name;Time (sequence)(s);Shear stress(Pa);Shear rate(s-\xC2\xB9);Viscosity(Pa s);"
    "Complex modulus(Pa)\n"
    "Pre Shear Initial;1,0;30,5;50,0;0,61;\n"
    "Pre Shear Initial;2,0;30,6;50,0;0,612;\n"
    "Pre Shear Initial;3,0;30,4;50,0;0,608;\n"
    "Flow Curve Up;4,0;0,0;0,0;0,0;\n"
    "Flow Curve Up;5,0;0,5;1,0;0,5;\n"
    "Flow Curve Up;6,0;1,0;2,0;0,5;\n"
    "Flow Curve Up;7,0;2,0;4,0;0,5;\n"
    "Flow Curve Up;8,0;4,0;8,0;0,5;\n"
    "Flow Curve Up;9,0;8,0;16,0;0,5;\n"
    "Flow Curve Up;10,0;16,0;32,0;0,5;\n"
    "Flow Curve Down;11,0;17,0;32,0;0,53125;\n"
    "Flow Curve Down;12,0;8,5;16,0;0,53125;\n"
    "Flow Curve Down;13,0;4,2;8,0;0,525;\n"
    "Flow Curve Down;14,0;2,1;4,0;0,525;\n"
    "Flow Curve Down;15,0;1,05;2,0;0,525;\n"
    "Oscillation Amplitude Table;16,0;;;;12,3\n"
    "Oscillation Amplitude Table;17,0;;;;12,1\n"
    "Oscillation Amplitude Table;18,0;;;;11,8\n";

// TA TRIOS "Export to LIMS" text: tabs, metadata, "[step]" sections with a
// title, a header and a units row; a zero row at each step's start.
const std::string kTriosTxt =
    "Filename\tsample 3\n"
    "Instrument serial number\t5332-0120\n"
    "Procedure name\tflow curves\n"
    "[step]\n"
    "Flow sweep - 1\n"
    "Stress\tShear rate\tViscosity\tStep time\tTemperature\n"
    "Pa\t1/s\tPa.s\ts\t\xC2\xB0"
    "C\n"
    "0.00000\t0.00000\t0.00000\t0.00000\t25.0\n"
    "0.100000\t0.500000\t0.200000\t10.0\t25.0\n"
    "0.200000\t1.00000\t0.200000\t20.0\t25.0\n"
    "0.400000\t2.00000\t0.200000\t30.0\t25.0\n"
    "0.800000\t4.00000\t0.200000\t40.0\t25.0\n"
    "1.60000\t8.00000\t0.200000\t50.0\t25.0\n"
    "\n"
    "[step]\n"
    "Flow sweep - 2\n"
    "Stress\tShear rate\tViscosity\tStep time\tTemperature\n"
    "Pa\t1/s\tPa.s\ts\t\xC2\xB0"
    "C\n"
    "0.00000\t0.00000\t0.00000\t0.00000\t25.0\n"
    "1.60000\t8.00000\t0.200000\t10.0\t25.0\n"
    "0.800000\t4.00000\t0.200000\t20.0\t25.0\n"
    "0.400000\t2.00000\t0.200000\t30.0\t25.0\n"
    "0.200000\t1.00000\t0.200000\t40.0\t25.0\n";

// TA TRIOS .csv: the procedure's steps listed, "[File Parameters]"-like
// sections, then one "[step]" table per step: peak hold, two flow sweeps, an
// amplitude sweep.
const std::string kTriosCsv =
    "Filename,sample 7\n"
    "Instrument name,5332-0120\n"
    "Procedure name,Peak hold\n"
    ",Peak hold\n"
    ",Flow sweep\n"
    ",Flow sweep\n"
    ",Amplitude sweep\n"
    "[File Parameters]\n"
    "Geometry name,40 mm 2\xC2\xB0 cone\n"
    "[Geometry Parameters]\n"
    "Diameter,40 mm\n"
    "[step]\n"
    "Peak hold - 1\n"
    "Step time,Shear rate,Stress,Viscosity\n"
    "s,1/s,Pa,Pa.s\n"
    "1.0,10.0,5.02,0.502\n"
    "2.0,10.0,5.01,0.501\n"
    "3.0,10.0,5.00,0.500\n"
    "4.0,10.0,4.99,0.499\n"
    "\n"
    "[step]\n"
    "Flow sweep - 2\n"
    "Step time,Shear rate,Stress,Viscosity\n"
    "s,1/s,Pa,Pa.s\n"
    "10.0,1.00,2.00,2.00\n"
    "20.0,2.00,3.00,1.50\n"
    "30.0,4.00,4.00,1.00\n"
    "40.0,8.00,6.00,0.750\n"
    "50.0,16.0,8.00,0.500\n"
    "\n"
    "[step]\n"
    "Flow sweep - 3\n"
    "Step time,Shear rate,Stress,Viscosity\n"
    "s,1/s,Pa,Pa.s\n"
    "10.0,16.0,8.00,0.500\n"
    "20.0,8.00,6.00,0.750\n"
    "30.0,4.00,4.00,1.00\n"
    "40.0,2.00,3.00,1.50\n"
    "50.0,1.00,2.00,2.00\n"
    "\n"
    "[step]\n"
    "Amplitude sweep - 4\n"
    "Oscillation strain,Storage modulus,Loss modulus,Oscillation stress\n"
    "%,Pa,Pa,Pa\n"
    "0.100,120,30.0,0.124\n"
    "1.00,118,31.0,1.22\n"
    "10.0,90.0,40.0,9.85\n";

// Anton Paar RheoCompass, UTF-16 LE with its byte-order mark: a result of
// three intervals (pre-shear at one rate, ramp up, ramp down), each with its
// own header, an empty row and a units row; decimal points, and a status
// column whose text has a comma.
const std::string kRheoCompassInterval =
    "Interval data:\tPoint No.\tTime\tShear Rate\tShear Stress\tViscosity\tStatus\n"
    "\t\t\t\t\t\t\n"
    "\t\t[s]\t[1/s]\t[Pa]\t[Pa\xC2\xB7s]\t\n";
const std::string kRheoCompass =
    "Project:\tslurry\n"
    "Test:\tflow\n"
    "Result:\tFlow Curve 1\n"
    "Interval and data points:\t1\t3\n" +
    kRheoCompassInterval +
    "\t1\t1\t100\t52.1\t0.521\tDy_auto,TruRate\xE2\x84\xA2\n"
    "\t2\t2\t100\t52.3\t0.523\tDy_auto\n"
    "\t3\t3\t100\t52.2\t0.522\tDy_auto\n"
    "Interval and data points:\t2\t5\n" +
    kRheoCompassInterval +
    "\t1\t4\t1\t0.8\t0.8\tDy_auto\n"
    "\t2\t5\t3\t2.1\t0.7\tDy_auto\n"
    "\t3\t6\t10\t6\t0.6\tDy_auto\n"
    "\t4\t7\t30\t18\t0.6\tDy_auto\n"
    "\t5\t8\t100\t70\t0.7\tDy_auto\n"
    "Interval and data points:\t3\t4\n" +
    kRheoCompassInterval +
    "\t1\t9\t100\t70\t0.7\tDy_auto\n"
    "\t2\t10\t30\t18\t0.6\tDy_auto\n"
    "\t3\t11\t10\t6\t0.6\tDy_auto\n"
    "\t4\t12\t1\t0.8\t0.8\tDy_auto\n";

// RheoCompass in French as a real export writes it: a second header line
// ("Sinusoïdes") over the oscillation columns, columns qualified "(pour
// déformation sinusoïdale)" beside the flow curve's own, an interval of
// invalid points ("1  (invalide)"), decimal commas.
const std::string kRheoCompassHeader =
    "Interval donn\xC3\xA9\x65s:\tPoint No.\tTemps\tContrainte de Cisaillement\tGradient de "
    "Cisaillement\tContrainte de Cisaillement (pour d\xC3\xA9\x66ormation "
    "sinuso\xC3\xAF\x64\x61le)\n"
    "\t\t\t\t\tSinuso\xC3\xAF\x64\x65s\n"
    "\t\t[s]\t[Pa]\t[1/s]\t[Pa]\n";
const std::string kRheoCompassFrench =
    "Projet:\tcarbopol\n"
    "R\xC3\xA9sultat:\tFlow Curve 1\n"
    "Intervalle et points de donn\xC3\xA9\x65s:\t1\t3\n" +
    kRheoCompassHeader +
    "\t1\t1\t73,196\t300\t\n"
    "\t2\t2\t72,859\t300\t\n"
    "\t3\t3\t72,901\t300\t\n"
    "Intervalle et points de donn\xC3\xA9\x65s:\t2\t3\n" +
    kRheoCompassHeader +
    "\t1  (invalide)\t\t\t\t\n"
    "\t2  (invalide)\t\t\t\t\n"
    "\t3  (invalide)\t\t\t\t\n"
    "Intervalle et points de donn\xC3\xA9\x65s:\t3\t4\n" +
    kRheoCompassHeader +
    "\t1\t4\t15,343\t0,00609\t\n"
    "\t2\t8\t15,398\t0,00649\t\n"
    "\t3\t12\t18,2\t1,21\t\n"
    "\t4\t16\t25,973\t9,49\t\n";

// TA TRIOS's "Export to LIMS" text: "[Step]", "Step name", "Number of
// points", the "Variables" and "Units" lines, rows labelled "Data point";
// "Stress (step)" is another column than the stress; set points written with
// too few digits repeat ("0.18" twice).
const std::string kTriosLims =
    "[Header]\n"
    "Instrument serial number\t5332-0120\n"
    "[Step]\n"
    "Step name\tFlow sweep (25.0 \xC2\xB0\x43)\n"
    "Number of points\t5\n"
    "Variables\tStress\tShear rate\tViscosity\tStress (step)\tStep time\n"
    "Units\tPa\t1/s\tPa.s\tPa\ts\n"
    "Data point\t0.22\t0.0251707\t8.740\t0.22\t10.0\n"
    "Data point\t0.20\t0.0198663\t10.07\t0.20\t20.0\n"
    "Data point\t0.18\t0.0126287\t14.25\t0.18\t30.0\n"
    "Data point\t0.18\t0.0101777\t17.69\t0.18\t40.0\n"
    "Data point\t0.16\t5.80024e-3\t27.59\t0.16\t50.0\n";

struct Expected {
  StepKind kind;
  std::size_t rows;
  std::size_t points;  // of a flow curve
  std::string name;
};

void expect_steps(const RheometerFile& f, const std::vector<Expected>& expected) {
  ASSERT_EQ(f.steps.size(), expected.size()) << step_listing(f);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const auto& s = f.steps[k];
    SCOPED_TRACE("step " + s.label());
    EXPECT_EQ(s.number, k + 1);
    EXPECT_EQ(s.name, expected[k].name);
    EXPECT_EQ(step_kind_name(s.kind), step_kind_name(expected[k].kind));
    EXPECT_EQ(s.rows, expected[k].rows);
    EXPECT_EQ(s.problem, RheometerStep::Problem::None) << s.why;
    if (s.kind == StepKind::FlowCurve) {
      EXPECT_EQ(s.curve.points.size(), expected[k].points);
    }
  }
}

TEST(RheometerFile, SplitsAMalvernExportByItsActionNameColumn) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("malvern.csv", kMalvern));
  expect_steps(f, {{StepKind::Hold, 3, 0, "Pre Shear Initial"},
                   {StepKind::FlowCurve, 7, 6, "Flow Curve Up"},
                   {StepKind::FlowCurve, 5, 5, "Flow Curve Down"},
                   {StepKind::Oscillation, 3, 0, "Oscillation Amplitude Table"}});
  EXPECT_EQ(f.steps[1].first_line, 5u);
  EXPECT_EQ(f.steps[1].last_line, 11u);
  EXPECT_EQ(f.steps[1].curve.dropped_rows, 1u);  // the zero row at the ramp's start

  const ChosenCurves all = choose_flow_curves(f, {});
  ASSERT_EQ(all.curves.size(), 2u);
  EXPECT_EQ(all.curves[0].step, "2 'Flow Curve Up'");
  EXPECT_EQ(all.curves[1].step, "3 'Flow Curve Down'");
  EXPECT_EQ(all.skipped,
            "step 1 'Pre Shear Initial' (hold), step 4 'Oscillation Amplitude Table' "
            "(oscillation)");
  // The down-ramp, read with its decimal commas, in ascending stress.
  const auto& down = all.curves[1].curve.points;
  EXPECT_DOUBLE_EQ(down.front().shear_stress, 1.05);
  EXPECT_DOUBLE_EQ(down.front().shear_rate, 2.0);
  EXPECT_EQ(down.front().line, 16u);
  EXPECT_DOUBLE_EQ(down.back().viscosity, 0.53125);
}

TEST(RheometerFile, SplitsATriosTextExportIntoItsStepSections) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("trios.txt", kTriosTxt));
  expect_steps(f, {{StepKind::FlowCurve, 6, 5, "Flow sweep - 1"},
                   {StepKind::FlowCurve, 5, 4, "Flow sweep - 2"}});
  EXPECT_EQ(f.steps[0].first_line, 4u);  // the "[step]" line
  EXPECT_EQ(f.steps[0].curve.dropped, "1 row dropped (zero or negative value: line 8)");
  EXPECT_DOUBLE_EQ(f.steps[1].curve.points.back().shear_stress, 1.6);
}

TEST(RheometerFile, ReadsATriosCsvExportPastItsSectionsAndSkipsHoldAndOscillation) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("trios.csv", kTriosCsv));
  expect_steps(f, {{StepKind::Hold, 4, 0, "Peak hold - 1"},
                   {StepKind::FlowCurve, 5, 5, "Flow sweep - 2"},
                   {StepKind::FlowCurve, 5, 5, "Flow sweep - 3"},
                   {StepKind::Oscillation, 3, 0, "Amplitude sweep - 4"}});
  const ChosenCurves chosen = choose_flow_curves(f, {std::nullopt, "flow sweep - 3", ""});
  ASSERT_EQ(chosen.curves.size(), 1u);
  EXPECT_EQ(chosen.curves[0].step, "3 'Flow sweep - 3'");
  EXPECT_DOUBLE_EQ(chosen.curves[0].curve.points.front().shear_stress, 2.0);
}

TEST(RheometerFile, SplitsARheoCompassResultIntoItsIntervalsInUtf16) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("ap.csv", test::utf16le(kRheoCompass)));
  expect_steps(f, {{StepKind::Hold, 3, 0, "Flow Curve 1, interval 1"},
                   {StepKind::FlowCurve, 5, 5, "Flow Curve 1, interval 2"},
                   {StepKind::FlowCurve, 4, 4, "Flow Curve 1, interval 3"}});
  // Decimal points decided for the file, though the status column has a comma.
  EXPECT_DOUBLE_EQ(f.steps[1].curve.points[1].shear_stress, 2.1);
  EXPECT_DOUBLE_EQ(f.steps[1].curve.points[1].viscosity, 0.7);
}

// The shipped RheoCompass export has metadata ("Profile:", a blank line)
// between its interval marker and the interval's header: one step.
TEST(RheometerFile, MetadataBetweenAnIntervalMarkerAndItsHeaderIsSkipped) {
  const auto f = read_rheometer_file(std::filesystem::path(DILATANT_SOURCE_DIR) /
                                     "tests/analysis/data/anton_paar_export.csv");
  expect_steps(f, {{StepKind::FlowCurve, 49, 49, "interval 1"}});
  EXPECT_EQ(f.steps[0].first_line, 4u);
}

TEST(RheometerFile, ReadsARealRheoCompassLayoutWithSubHeadersAndInvalidPoints) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("fr.csv", test::utf16le(kRheoCompassFrench)));
  ASSERT_EQ(f.steps.size(), 3u) << step_listing(f);
  EXPECT_EQ(step_kind_name(f.steps[0].kind), "hold");  // pre-shear at 300 1/s
  // The invalid points are rows with no value: dropped, counted, too few left.
  EXPECT_EQ(f.steps[1].rows, 3u);
  EXPECT_EQ(f.steps[1].problem, RheometerStep::Problem::TooFewPoints);
  EXPECT_NE(f.steps[1].why.find("3 rows dropped (missing value: lines 14, 15, 16)"),
            std::string::npos)
      << f.steps[1].why;
  // The qualified column is not a second stress: the ramp is read.
  EXPECT_EQ(f.steps[2].problem, RheometerStep::Problem::None) << f.steps[2].why;
  ASSERT_EQ(f.steps[2].curve.points.size(), 4u);
  EXPECT_DOUBLE_EQ(f.steps[2].curve.points[1].shear_rate, 0.00649);
  const ChosenCurves chosen = choose_flow_curves(f, {});
  ASSERT_EQ(chosen.curves.size(), 1u);
  EXPECT_EQ(chosen.skipped,
            "step 1 'Flow Curve 1, interval 1' (hold), step 2 'Flow Curve 1, interval 2' (too few "
            "points)");
}

TEST(RheometerFile, ReadsATriosLimsExportAndDropsRepeatedSetPoints) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("lims.txt", kTriosLims));
  ASSERT_EQ(f.steps.size(), 1u) << step_listing(f);
  const auto& s = f.steps[0];
  EXPECT_EQ(s.name, "Flow sweep (25.0 \xC2\xB0\x43)");
  EXPECT_EQ(s.first_line, 3u);
  EXPECT_EQ(s.problem, RheometerStep::Problem::None) << s.why;
  ASSERT_EQ(s.curve.points.size(), 4u);  // the second 0.18 Pa dropped
  EXPECT_EQ(s.curve.dropped, "1 row dropped (repeated ramp value: line 11)");
  EXPECT_DOUBLE_EQ(s.curve.points.front().shear_stress, 0.16);
}

TEST(RheometerFile, AChosenStepMustExistAndBeAFlowCurve) {
  test::TempDir dir;
  const auto f = read_rheometer_file(dir.write("malvern.csv", kMalvern));
  const auto message = [&](StepChoice c) {
    return test::input_error_message([&] { choose_flow_curves(f, c); });
  };
  EXPECT_NE(message({1, std::nullopt, "m.toml:3: curve[0].step"})
                .find("m.toml:3: curve[0].step: step 1 'Pre Shear Initial' of "),
            std::string::npos);
  EXPECT_NE(message({1, std::nullopt, ""}).find("is a hold step, not a flow curve"),
            std::string::npos);
  EXPECT_NE(message({9, std::nullopt, ""}).find("has steps 1 to 4"), std::string::npos);
  EXPECT_NE(message({std::nullopt, "Flow Curve", ""}).find("no step of"), std::string::npos);
  const auto chosen = choose_flow_curves(f, {3, std::nullopt, ""});
  ASSERT_EQ(chosen.curves.size(), 1u);
  EXPECT_EQ(chosen.curves[0].curve.points.size(), 5u);
}

TEST(RheometerFile, AFileWithoutAFlowCurveSaysWhatItFound) {
  test::TempDir dir;
  const std::string oscillation = kTriosCsv.substr(kTriosCsv.find("[step]\nAmplitude"));
  const auto file = dir.write("amplitude.csv", oscillation);
  const std::string message = test::input_error_message([&] { read_flow_curve_file(file); });
  EXPECT_EQ(message, file.string() +
                         ": no flow curve in the file (found: step 1 'Amplitude sweep - 4' "
                         "(oscillation, 3 rows))");
}

TEST(RheometerFile, TheDecimalMarkIsTheFilesNotGuessedPerRow) {
  test::TempDir dir;
  // ';' and decimal commas: a row written with a decimal point is not a number.
  const auto file = dir.write("mixed.csv", "Shear rate;Shear stress\n1,5;3\n2,5;5\n3.5;7\n4,5;9\n");
  const std::string message = test::input_error_message([&] { read_flow_curve_file(file); });
  EXPECT_EQ(message.rfind(file.string() + ":4: ", 0), 0u) << message;
  EXPECT_NE(message.find("'3.5'"), std::string::npos) << message;
}

TEST(RheometerFile, PlainTablesAfterABlankLineAreStepsOfTheirOwn) {
  test::TempDir dir;
  const auto file = dir.write(
      "two.csv", "shear_rate,shear_stress\n1,1\n2,2\n3,3\n\nshear_rate,shear_stress\n4,1\n");
  const auto f = read_rheometer_file(file);
  ASSERT_EQ(f.steps.size(), 2u);
  EXPECT_EQ(f.steps[1].problem, RheometerStep::Problem::TooFewPoints);
  const ChosenCurves chosen = choose_flow_curves(f, {});
  ASSERT_EQ(chosen.curves.size(), 1u);
  EXPECT_EQ(chosen.skipped, "step 2 (too few points)");
  EXPECT_NE(step_listing(f).find("only 1 data point in step 2"), std::string::npos)
      << step_listing(f);
}

}  // namespace
}  // namespace dilatant::analysis::rheometer_file_test
