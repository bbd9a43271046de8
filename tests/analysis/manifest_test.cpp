// The analysis manifest: what it labels, and every mistake located by line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "analysis/analysis_input.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::analysis::manifest_test {
namespace {

constexpr const char* kCurveCsv =
    "shear_rate,shear_stress\n1,1\n2,2\n3,3.5\n";  // 3 points, stress ascending

constexpr const char* kManifest = R"(# two curves of sample A, one of B
[[curve]]
file = "data/a1.csv"
sample = "A"
phi = 0.53

[[curve]]
file = "data/a2.csv"
sample = "A"
phi = 0.55
window_stress = [1.5, 4.0]

[[curve]]
file = "data/b1.csv"
sample = "B"
phi = 0.50

[samples.A]
phi_max = 0.578
)";

// `text` with the first `from` replaced by `to` ("" if absent: the test fails).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) return "";
  return text.replace(at, from.size(), to);
}

void write_curves(const test::TempDir& dir) {
  for (const char* name : {"data/a1.csv", "data/a2.csv", "data/b1.csv"}) dir.write(name, kCurveCsv);
}

TEST(Manifest, LabelsEachFileWithSamplePhiAndWindow) {
  test::TempDir dir;
  write_curves(dir);
  const auto manifest = dir.write("m.toml", kManifest);
  const AnalysisInput in = load_analysis_input(manifest);
  EXPECT_EQ(in.kind, InputKind::Manifest);
  EXPECT_EQ(in.units, UnitSystem::SI);
  ASSERT_EQ(in.curves.size(), 3u);
  EXPECT_EQ(in.samples, (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(in.curves[1].sample, "A");
  EXPECT_EQ(in.curves[1].phi, 0.55);
  EXPECT_EQ(in.curves[1].source, (dir.path() / "data/a2.csv").string());  // relative to m.toml
  EXPECT_EQ(in.curves[1].points.size(), 3u);
  ASSERT_TRUE(in.curves[1].window);
  EXPECT_EQ(in.curves[1].window->low, 1.5);
  EXPECT_EQ(in.curves[1].window->origin, manifest.string() + ":11: curve[1].window_stress");
  EXPECT_FALSE(in.curves[0].window);
  ASSERT_EQ(in.phi_max.size(), 1u);
  EXPECT_EQ(in.phi_max.at("A"), 0.578);
}

struct BadManifest {
  std::string name;
  std::string text;
  std::string where;    // expected after "m.toml" in the message, e.g. ":5: "
  std::string problem;  // expected in the message
};

std::vector<BadManifest> bad_manifests() {
  const std::string m = kManifest;
  return {
      {"UnknownTopLevelKey", "units = \"SI\"\n" + m, ":1: ", "unknown key 'units'"},
      {"UnknownCurveKey", replaced(m, "phi = 0.53\n", "phi = 0.53\nphii = 0.5\n"),
       ":6: ", "curve[0].phii: unknown key"},
      {"MissingPhi", replaced(m, "phi = 0.50\n", ""), ":13: ", "curve[2].phi is missing"},
      {"PhiOutOfRange", replaced(m, "phi = 0.50", "phi = 0.80"),
       ":16: ", "curve[2].phi = 0.8: must be in (0, 0.74)"},
      {"PhiNotANumber", replaced(m, "phi = 0.50", "phi = \"half\""),
       ":16: ", "curve[2].phi: expected a number"},
      {"MissingDataFile", replaced(m, "data/b1.csv", "data/none.csv"), ":14: ", "no such file"},
      {"SampleWithAComma", replaced(m, "sample = \"B\"", "sample = \"B,1\""),
       ":15: ", "must not contain ','"},
      {"SampleWithoutCurves", m + "[samples.C]\nphi_max = 0.55\n",
       ":20: ", "samples.C: no [[curve]] has sample = \"C\""},
      {"UnknownSampleKey", replaced(m, "phi_max = 0.578", "mu0 = 0.3"),
       ":19: ", "samples.A.mu0: unknown key"},
      {"PhiMaxOutOfRange", replaced(m, "phi_max = 0.578", "phi_max = 0.0"),
       ":19: ", "samples.A.phi_max = 0: must be in (0, 0.74)"},
      {"WindowReversed", replaced(m, "[1.5, 4.0]", "[4.0, 1.5]"), ":11: ", "needs 0 < low < high"},
      {"WindowNotAPair", replaced(m, "[1.5, 4.0]", "[1.5]"), ":11: ", "expected [low, high]"},
      {"NoCurves", "[samples.A]\nphi_max = 0.5\n", ": ", "no [[curve]] entries"},
      {"InvalidToml", replaced(m, "[[curve]]\nfile = \"data/b1.csv\"", "[[curve]\nfile = 1"),
       ":13:", "invalid TOML"},
      {"StepZero", replaced(m, "phi = 0.50\n", "phi = 0.50\nstep = 0\n"),
       ":17: ", "curve[2].step = 0: steps are numbered from 1"},
      {"StepNotANumberOrName", replaced(m, "phi = 0.50\n", "phi = 0.50\nstep = 1.5\n"),
       ":17: ", "curve[2].step: expected a step number (2) or name"},
      {"StepNotInTheFile", replaced(m, "phi = 0.50\n", "phi = 0.50\nstep = \"Up\"\n"),
       ":17: ", "curve[2].step: step \"Up\": no step of"},
      {"StepBeyondTheFile", replaced(m, "phi = 0.50\n", "phi = 0.50\nstep = 2\n"),
       ":17: ", "curve[2].step: step 2: "},
  };
}

class ManifestBad : public ::testing::TestWithParam<BadManifest> {};

TEST_P(ManifestBad, IsRefusedWithTheManifestLineAndTheProblem) {
  const BadManifest& c = GetParam();
  ASSERT_FALSE(c.text.empty()) << "test set-up: a replaced() pattern was not found";
  test::TempDir dir;
  write_curves(dir);
  const auto manifest = dir.write("m.toml", c.text);
  const std::string message = test::input_error_message([&] { load_analysis_input(manifest); });
  EXPECT_EQ(message.rfind(manifest.string() + c.where, 0), 0u) << message;
  EXPECT_NE(message.find(c.problem), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Manifest, ManifestBad, ::testing::ValuesIn(bad_manifests()),
                         [](const auto& p) { return p.param.name; });

// A file of two steps (Malvern's layout): each flow step is a curve of its
// own, or the manifest chooses one by name or number.
TEST(Manifest, AFileOfSeveralStepsGivesACurvePerStepOrTheChosenOne) {
  test::TempDir dir;
  dir.write("ramps.csv",
            "Action Name;Shear rate(1/s);Shear stress(Pa)\nUp;1;1\nUp;2;2\nUp;3;3,5\n"
            "Down;3;3,4\nDown;2;2\nDown;1;1\n");
  const std::string entry = "[[curve]]\nfile = \"ramps.csv\"\nsample = \"A\"\nphi = 0.5\n";
  const AnalysisInput all = load_analysis_input(dir.write("all.toml", entry));
  ASSERT_EQ(all.curves.size(), 2u);
  EXPECT_EQ(all.curves[0].step, "1 'Up'");
  EXPECT_EQ(all.curves[1].step, "2 'Down'");
  EXPECT_DOUBLE_EQ(all.curves[1].points.back().shear_stress, 3.4);
  for (const auto& step : {std::string("step = \"down\"\n"), std::string("step = 2\n")}) {
    const AnalysisInput one = load_analysis_input(dir.write("one.toml", entry + step));
    ASSERT_EQ(one.curves.size(), 1u) << step;
    EXPECT_EQ(one.curves[0].step, "2 'Down'") << step;
  }
}

TEST(Manifest, AMalformedDataFileIsNamedWithItsOwnLine) {
  test::TempDir dir;
  write_curves(dir);
  dir.write("data/b1.csv", "shear_rate,shear_stress\n1,1\n2,x\n3,3\n");
  const auto manifest = dir.write("m.toml", kManifest);
  const std::string message = test::input_error_message([&] { load_analysis_input(manifest); });
  EXPECT_EQ(message.rfind((dir.path() / "data/b1.csv").string() + ":3: ", 0), 0u) << message;
}

TEST(Manifest, AFileThatIsNeitherManifestNorSweepTableIsRefused) {
  test::TempDir dir;
  const auto other = dir.write("rheo.csv", kCurveCsv);
  const std::string message = test::input_error_message([&] { load_analysis_input(other); });
  EXPECT_EQ(message.rfind(other.string() + ":1: ", 0), 0u) << message;
  EXPECT_NE(message.find("manifest"), std::string::npos) << message;
}

}  // namespace
}  // namespace dilatant::analysis::manifest_test
