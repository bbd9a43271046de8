// A blown-up state stops the run instead of yielding a number. The films +
// drag model once did this at phi 0.61 (docs/paper-reproduction.md, "The
// Newtonian branch", item 4): the wall speed went from 0.25 to 1e20 within half
// a strain unit and the summary still reported eta = 16.7. Here a start a
// billion times faster than the drive could make the wall stands in for such a
// state: the automatic step collapses below 1e-6 of the drive's and step()
// throws, naming the step.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "drivers/shear_cell.hpp"
#include "io/config.hpp"

namespace dilatant::shear_cell_blowup_test {
namespace {

TEST(CellBlowUp, ACollapsedTimeStepStopsTheRun) {
  ShearCell cell(default_cell_config(
      {"cell.size=[8.0, 5.0, 9.0]", "cell.initial_shear_rate=1e9", "run.snapshot_interval=0.0"}));
  try {
    cell.step();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("numerical blow-up at step 0"), std::string::npos)
        << e.what();
  }
}

TEST(CellBlowUp, AnOrdinaryStartIsNotOne) {
  ShearCell cell(default_cell_config({"cell.size=[8.0, 5.0, 9.0]", "run.snapshot_interval=0.0"}));
  for (int k = 0; k < 20; ++k) EXPECT_NO_THROW(cell.step());
}

}  // namespace
}  // namespace dilatant::shear_cell_blowup_test
