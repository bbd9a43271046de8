// The catalogue of bad inputs (issue 19, item 4; docs/reliability.md): every
// file and flag a user hands dilatant, malformed in the ways seen in practice.
// Each case must exit with code 2 and print exactly one line on stderr that
// names the file, key, line or flag at fault (the expected substring).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::bad_input_catalogue_test {
namespace {

namespace fs = std::filesystem;

struct BadInput {
  std::string name;
  std::vector<std::pair<std::string, std::string>> files;  // written before the run
  std::vector<std::string> args;
  std::string names;  // what the one line must contain
};

constexpr const char* kCell =
    "[cell]\nsize = [6.0, 5.0, 7.0]\nphi = 0.58\n"
    "[run]\nstrain = 0.05\ntransient_strain = 0.0\nsnapshot_interval = 0.0\n";
constexpr const char* kSweep = "[friction]\nmu0 = [0.1, 0.4]\n";
constexpr const char* kRheometer =
    "Shear Stress;Shear Rate;Viscosity\nPa;1/s;Pa.s\n1,0;0,5;2,0\n2,0;abc;2,0\n";

std::vector<BadInput> catalogue() {
  const std::string cell = kCell;
  return {
      // Run configurations.
      {"value of the wrong type",
       {{"c.toml", "[cell]\nphi = \"x\"\n"}},
       {"run", "c.toml"},
       "c.toml:2: cell.phi"},
      {"table defined twice",
       {{"c.toml", "[cell]\nphi = 0.5\n[cell]\n"}},
       {"run", "c.toml"},
       "c.toml:3"},
      {"unclosed table header", {{"c.toml", "[cell\n"}}, {"run", "c.toml"}, "c.toml:1"},
      {"unknown section", {{"c.toml", "[cel]\nphi = 0.5\n"}}, {"run", "c.toml"}, "c.toml:1: cel"},
      {"unknown key",
       {{"c.toml", cell + "[solver]\ntolerence = 1e-4\n"}},
       {"run", "c.toml"},
       "solver.tolerence"},
      {"phi above packing",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "cell.phi=0.9"},
       "cell.phi"},
      {"critical-load law without its load",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "friction.law=critical_load"},
       "friction.law"},
      {"critical load under another law",
       {{"c.toml", cell + "[friction]\ncritical_load = 5.0\n"}},
       {"run", "c.toml"},
       "c.toml:9: friction.critical_load"},
      {"rate control of the wall cell",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "cell.control=rate", "--set", "cell.shear_rate=0.1"},
       "cell.control"},
      {"wall friction without walls",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "cell.boundary=lees-edwards", "--set", "cell.wall_friction=0.5"},
       "cell.wall_friction"},
      {"negative friction",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "friction.mu0=-0.1"},
       "friction.mu0"},
      {"tolerance out of range",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "solver.tolerance=2"},
       "solver.tolerance"},
      {"transient not below strain",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "run.strain=0"},
       "run.transient_strain"},
      {"cell narrower than a sphere",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "cell.size=[1.0, 1.0, 1.0]"},
       "cell.size"},
      {"--set without =",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "friction.mu0"},
       "friction.mu0"},
      {"--set of a non-number",
       {{"c.toml", cell}},
       {"run", "c.toml", "--set", "friction.mu0=abc"},
       "friction.mu0"},
      {"missing config file", {}, {"run", "missing.toml"}, "missing.toml"},
      {"unknown flag", {{"c.toml", cell}}, {"run", "c.toml", "--bogus"}, "--bogus"},
      {"resume without a checkpoint",
       {{"c.toml", cell}},
       {"run", "c.toml", "--resume", "--out", "empty"},
       "empty"},
      // Issue 31, item 7: once a raw library message and exit 1.
      {"--out names a file",
       {{"c.toml", cell}, {"f", "a file\n"}},
       {"run", "c.toml", "--out", "f"},
       "f: cannot use as the output folder: a file is there"},
      {"analyze --out names a file",
       {{"r.csv", "shear_rate,shear_stress\n1,1\n2,2\n3,3\n"},
        {"f", "a file\n"},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml", "--out", "f"},
       "f: cannot use as the output folder"},
      {"sediment config given to run",
       {{"s.toml", "[sediment]\nsize = [12.0, 12.0, 40.0]\n"}},
       {"run", "s.toml"},
       "dilatant jam"},
      // Sweep files.
      {"empty list",
       {{"w.toml", cell + "[friction]\nmu0 = []\n"}},
       {"sweep", "w.toml"},
       "friction.mu0 = []"},
      {"unknown [sweep] key",
       {{"w.toml", cell + kSweep + "[sweep]\njobz = 1\n"}},
       {"sweep", "w.toml"},
       "sweep.jobz"},
      {"two equal points",
       {{"w.toml", cell + "[[points]]\nfriction.mu0 = 0.1\n[[points]]\nfriction.mu0 = 0.1\n"}},
       {"sweep", "w.toml"},
       "points 0 and 1"},
      {"continuation without lambda",
       {{"w.toml", cell + kSweep + "[sweep]\ncontinuation = true\n"}},
       {"sweep", "w.toml"},
       "fluid.lambda"},
      {"jam rule without continuation",
       {{"w.toml", cell + kSweep + "[sweep]\nstop_at_jam = true\n"}},
       {"sweep", "w.toml"},
       "sweep.stop_at_jam"},
      {"negative jobs", {{"w.toml", cell + kSweep}}, {"sweep", "w.toml", "--jobs", "-1"}, "--jobs"},
      // Analysis inputs: rheometer exports and manifests.
      {"CSV that is neither", {{"r.csv", "not,a,curve\n1,2\n"}}, {"analyze", "r.csv"}, "r.csv:1"},
      {"manifest naming a missing file",
       {{"m.toml", "[[curve]]\nfile = \"nope.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml"},
       "curve[0].file"},
      {"manifest without file",
       {{"m.toml", "[[curve]]\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml"},
       "curve[0].file"},
      {"manifest phi out of range",
       {{"r.csv", kRheometer},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 1.5\n"}},
       {"analyze", "m.toml"},
       "curve[0].phi"},
      {"rheometer cell not a number",
       {{"r.csv", kRheometer},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml"},
       "r.csv:4"},
      // Issue 31: a row with a field too many was read as a point; a spike
      // was blamed on the next line.
      {"rheometer row with a field too many",
       {{"r.csv", "shear_rate,shear_stress\n1,1\n2,2,7\n3,3\n4,4\n"},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml"},
       "r.csv:3: 3 fields, the header has 2"},
      {"rheometer point breaking the ramp",
       {{"r.csv", "shear_rate,shear_stress\n1,1\n2,2\n9,9\n4,4\n5,5\n"},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml"},
       "r.csv:4: shear stress 9 breaks"},
      {"rheometer viscosity not stress / rate",
       {{"r.csv", "rate,stress,eta\n1.00,1.00,1.00\n2.00,4.00,2.50\n3.00,9.00,3.00\n"},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml"},
       "r.csv:3: viscosity 2.5 disagrees"},
      {"jamming table row with a field too few",
       {{"t.csv", "mu0,phi_max,phi_max_err\n0,0.6,0\n0.2,0.58\n"}},
       {"predict", "--mu0", "0.1", "--phi", "0.5", "--table", "t.csv"},
       "t.csv:3: 2 fields, the header has 3"},
      {"onset factor below 1",
       {{"r.csv", kRheometer},
        {"m.toml", "[[curve]]\nfile = \"r.csv\"\nsample = \"A\"\nphi = 0.5\n"}},
       {"analyze", "m.toml", "--onset-factor", "0.5"},
       "--onset-factor"},
      // The jamming commands.
      {"sediment phi too dense",
       {{"s.toml", "[sediment]\nsize = [12.0, 12.0, 40.0]\nphi = 0.9\n"}},
       {"jam", "s.toml"},
       "sediment.phi"},
      {"sediment with Stribeck friction",
       {{"s.toml", "[sediment]\nsize = [12.0, 12.0, 40.0]\n[friction]\nlaw = \"stribeck\"\n"}},
       {"jam", "s.toml"},
       "friction.law"},
      {"cell config given to jam", {{"c.toml", cell}}, {"jam", "c.toml"}, "[sediment]"},
      {"predict: mu0 not a number", {}, {"predict", "--mu0", "nan", "--phi", "0.5"}, "--mu0"},
      {"predict: table not starting at 0",
       {{"t.csv", "mu0,phi_max,phi_max_err\n0.2,0.6,0\n"}},
       {"predict", "--mu0", "0.1", "--phi", "0.5", "--table", "t.csv"},
       "t.csv:2"},
      {"predict: grid and a point", {}, {"predict", "--grid", "--phi", "0.5"}, "--grid"},
      {"predict: bulk table with an unknown regime",
       {{"b.csv",
         "mu0,phi_bulk,regime,max_lambda,jam_lambda,cell,source,sample\n1,0.58,flows,100,,c,s,"
         "x\n"}},
       {"predict", "--mu0", "1", "--phi", "0.58", "--bulk-table", "b.csv"},
       "b.csv:2: regime \"flows\""},
  };
}

TEST(BadInputCatalogue, EveryCaseExitsTwoWithOneLineNamingTheCulprit) {
  const auto cases = catalogue();
  ASSERT_GE(cases.size(), 30u);
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    test::CliDir dir;
    for (const auto& [name, text] : c.files) std::ofstream(dir.path() / name) << text;
    fs::create_directories(dir.path() / "empty");
    std::vector<std::string> args;
    for (const auto& a : c.args) {
      // File arguments are relative to the case's folder.
      const bool file = fs::exists(dir.path() / a) || a == "missing.toml" || a == "empty";
      args.push_back(file ? (dir.path() / a).string() : a);
    }
    const auto r = dir.run(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
  }
}

// Checkpoints (issue 19, item 4): truncated, from another version, or of
// another configuration: refused on --resume with exit 2 and the file named.
// And any byte changed (issue 31, item 4): 4 bytes in the middle once resumed
// without a word and put 1.08e-222 into the time series; the CRC-32 at the
// end (format 8) refuses them, and a changed checksum as well.
TEST(BadInputCatalogue, DamagedOrForeignCheckpointsAreRefused) {
  test::CliDir dir;
  std::ofstream(dir.path() / "c.toml") << kCell;
  const auto config = (dir.path() / "c.toml").string();
  const auto good = dir.path() / "good";
  ASSERT_EQ(dir.run({"run", config, "--out", good.string(), "-q"}).exit_code, 0);
  const std::string bytes = test::read_text(good / "checkpoint.bin");
  const auto damaged = [&](const std::string& name, const std::string& content) {
    fs::copy(good, dir.path() / name, fs::copy_options::recursive);
    std::ofstream(dir.path() / name / "checkpoint.bin", std::ios::binary) << content;
    return (dir.path() / name).string();
  };
  std::string older = bytes;
  older[7] = '5';  // the format digit of the magic "DILATNT6"
  std::string middle = bytes, last = bytes;
  for (std::size_t k = 0; k < 4; ++k) middle[bytes.size() / 2 + k] ^= 0x5a;
  last.back() ^= 0x01;  // a bit of the checksum itself
  for (const auto& [folder, names] : std::vector<std::pair<std::string, std::string>>{
           {damaged("truncated", bytes.substr(0, 100)), "truncated"},
           {damaged("older", older), "older dilatant"},
           {damaged("garbage", "not a checkpoint at all"), "not a dilatant checkpoint"},
           {damaged("middle", middle), "checkpoint is damaged"},
           {damaged("last", last), "checkpoint is damaged"}}) {
    const auto r = dir.run({"run", config, "--out", folder, "--resume"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("checkpoint.bin"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
  }
  const auto other =
      dir.run({"run", config, "--out", good.string(), "--resume", "--set", "friction.mu0=0.3"});
  EXPECT_EQ(other.exit_code, 2) << other.err;
  EXPECT_NE(other.err.find("friction.mu0 = 0.1 there, 0.3 here"), std::string::npos) << other.err;
}

}  // namespace
}  // namespace dilatant::bad_input_catalogue_test
