// A light top wall against stiff squeeze films (docs/model.md "The wall
// inside the solve"; the blow-up traced in docs/paper-reproduction.md): when
// the wall's speed was solved once per pass, each of its contacts pushed as if
// the wall were fixed and V then jumped by their sum, a Jacobi block that
// oscillates when the wall is light. This cell (8 x 5 x 9 R, phi 0.58,
// stribeck mu0 0.1, films and Stokes drag at lambda 1, the wall at 1.5
// rho_p R^3, 3% of its spheres' mass) went non-finite in its first step that
// way (0.7.0: "numerical fault at t = 0.00892: body 31 has a non-finite
// position"). With the wall a Gauss–Seidel block inside the pass it runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "drivers/shear_cell.hpp"
#include "io/config.hpp"

namespace dilatant::shear_cell_light_wall_test {
namespace {

const std::vector<std::string> kLightWall = {
    "cell.size=[8.0, 5.0, 9.0]", "cell.phi=0.58",
    "cell.wall_mass=1.5",        "friction.law=stribeck",
    "friction.mu0=0.1",          "fluid.lambda=1.0",
    "fluid.lubrication=normal",  "fluid.drag=stokes",
    "solver.threads=1",          "run.strain=0.3",
    "run.transient_strain=0.1",  "run.snapshot_interval=0.0"};

TEST(CellLightWall, TheWallSolvedInsideThePassNeitherOscillatesNorBlowsUp) {
  const Config config = default_cell_config(kLightWall);
  ShearCell cell(config);
  const double r_min = config.cell()->radius_min;
  double speed_max = 0.0, overlap_max = 0.0;
  int unconverged = 0, steps = 0;
  while (cell.state().strain < 0.3) {
    const StepReport* r = nullptr;
    ASSERT_NO_THROW(r = &cell.step()) << "step " << steps;
    unconverged += r->solve.converged ? 0 : 1;
    overlap_max = std::max(overlap_max, r->max_overlap);
    speed_max = std::max(speed_max, std::abs(cell.state().drive_speed()));
    ++steps;
  }
  // Every step meets the tolerance within solver.max_iterations: the wall's
  // block converges, it does not alternate between two speeds.
  EXPECT_EQ(unconverged, 0) << "of " << steps << " steps";
  // Overlaps stay at what linearising the gap over a step leaves (4e-4 r at
  // the step rule's 2%), within the cell's 1% tolerance.
  EXPECT_LT(overlap_max, ShearCell::kOverlapTolerance * r_min);
  // The wall moves at the speed the stress drives, never runs away: bounded by
  // the speed at which the fluid alone (eta_f gamma_dot = tau, the whole gap
  // sheared) would let it move, tau Lz / eta_f, a generous bound on a
  // suspension whose viscosity is several times eta_f.
  const double tau = config.cell()->shear_stress;
  const double eta_f = cell.units().eta_f;
  EXPECT_LT(speed_max, tau * config.cell()->size[2] / eta_f);
}

}  // namespace
}  // namespace dilatant::shear_cell_light_wall_test
