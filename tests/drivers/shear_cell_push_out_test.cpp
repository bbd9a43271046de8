// An overlap deeper than a step may move a body must not run away with the
// automatic time step (docs/model.md "Overlap push-out"). A cold start of a
// 15 x 10 x 18 R cell at phi 0.64 (coulomb mu0 1, tolerance 1e-4) did: the
// overlaps its accepted steps left were pushed out at |g|/dt, the fastest body
// set dt = c r_min / v_max, and in 200 steps dt fell from the drive's 0.148 to
// 7e-8 ("numerical blow-up at step 1114"). That run takes 20 s to get there;
// here a particle of a small jammed cell swells by 0.04 R (2.5 c r_min), which
// its neighbours at fixed volume cannot all make room for within one step.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "drivers/shear_cell.hpp"
#include "io/config.hpp"

namespace dilatant::shear_cell_push_out_test {
namespace {

const std::vector<std::string> kJammedCell = {"cell.size=[8.0, 5.0, 9.0]", "cell.phi=0.64",
                                              "friction.law=coulomb", "friction.mu0=1.0",
                                              "run.snapshot_interval=0.0"};

TEST(CellPushOut, ASwollenParticleDoesNotCollapseTheStep) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("dilatant_push_out_" + std::to_string(::getpid()) + ".bin");
  {
    ShearCell cell(default_cell_config(kJammedCell));
    for (int k = 0; k < 50; ++k) cell.step();
    // The state as it is (the cell's own is not copied: it owns its drive),
    // without the warm-start impulses the checkpoint adds.
    cell.write_checkpoint(file);
    ShearCellState s = load_checkpoint(file);
    s.contact_memory.clear();
    // The middle particle of the cell in height (particles are numbered from
    // bottom to top) swells; its mass stays, only the overlaps matter.
    const std::size_t middle = s.geometry.first_mobile + s.geometry.mobile_count / 2;
    s.world.bodies.radius[middle] += 0.04;
    save_checkpoint(file, s);
  }
  ShearCell cell = ShearCell::resumed(default_cell_config(kJammedCell), file);
  std::filesystem::remove(file);
  double dt_min = 1.0;
  for (int k = 0; k < 300; ++k) {
    ASSERT_NO_THROW(cell.step()) << "step " << k;
    dt_min = std::min(dt_min, cell.state().dt);
  }
  // The push-out alone never asks for a step shorter than the drive's (0.146
  // here); the collisions it sets off do, by a bounded factor (dt stays above
  // 0.012). Uncapped, dt fell to 1.3e-7 and the guard threw 37 steps on.
  EXPECT_GT(dt_min, 1e-3);
}

}  // namespace
}  // namespace dilatant::shear_cell_push_out_test
