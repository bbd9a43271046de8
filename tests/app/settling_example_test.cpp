// examples/settling: a bead settling through a viscous fluid onto a floor, run
// by the CLI from its shipped config ([fluid] drag and lubrication in a scene).
// Against closed forms: the Stokes terminal speed in the bulk, and below the
// film's cut-off h0 the quasi-static approach (inertia negligible: tau v_t / r
// = 0.3%),
//     (h0 - h) + r ln((h0 + delta)/(h + delta)) = v_t (t - t0),
// t0 when the gap reaches h0. Tolerance: the film taken at the step's start
// gap is first order, (t/T)(dt/T)/2 with T = r / v_t = 0.18 s and dt = 1 ms,
// under 1% over the 0.6 s checked; plus tau/T; 2% in all.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_runner.hpp"

namespace dilatant::settling_example_test {
namespace {

namespace fs = std::filesystem;

struct Sample {
  double t, z, vz;
};

std::vector<Sample> trajectory(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // t,id,x,y,z,vx,vy,vz,...
  std::vector<Sample> out;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    out.push_back({v[0], v[4], v[7]});
  }
  return out;
}

TEST(SettlingExample, BeadFallsAtStokesSpeedThenSlowsThroughTheFilm) {
  test::CliDir dir;
  const fs::path config = fs::path(DILATANT_SOURCE_DIR) / "examples/settling/settling.toml";
  const auto r = dir.run({"run", config.string(), "--out", (dir.path() / "out").string(), "-q",
                          "--set", "run.time=1.2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<Sample> s = trajectory(dir.path() / "out/trajectory.csv");
  ASSERT_GE(s.size(), 100u);
  const double r_bead = 1e-3, rho = 2500.0, g = 9.81, eta = 1.0, h0 = 0.5e-3, delta = 1e-6;
  const double v_t = 2.0 * r_bead * r_bead * rho * g / (9.0 * eta);
  // The bulk: the terminal speed (exact for the implicit drag), until the film.
  const double t0 = (2.0e-3 - h0) / v_t;  // 0.275 s, from gap 2 mm
  int bulk = 0, film = 0;
  for (const Sample& p : s) {
    const double gap = p.z - r_bead;
    if (p.t > 0.02 && gap > h0 + 1e-5) {
      EXPECT_NEAR(p.vz, -v_t, 1e-9 * v_t) << "t = " << p.t;
      ++bulk;
    }
    if (p.t < t0 + 0.05 || p.t > t0 + 0.6) continue;
    // Solve the quasi-static approach for h by bisection (its left side grows as h falls).
    const double travelled = v_t * (p.t - t0);
    double lo = 0.0, hi = h0;
    for (int it = 0; it < 200; ++it) {
      const double h = 0.5 * (lo + hi);
      const double f = (h0 - h) + r_bead * std::log((h0 + delta) / (h + delta));
      (f > travelled ? lo : hi) = h;
    }
    EXPECT_NEAR(gap / lo, 1.0, 0.02) << "t = " << p.t;
    ++film;
  }
  EXPECT_GE(bulk, 20);
  EXPECT_GE(film, 50);
  EXPECT_GT(s.back().z - r_bead, 0.0);  // still approaching at t = 1.2 s, never through
}

}  // namespace
}  // namespace dilatant::settling_example_test
