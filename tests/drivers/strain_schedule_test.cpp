// The run loop's schedules in strain (drivers/strain_schedule.hpp).
#include "drivers/strain_schedule.hpp"

#include <gtest/gtest.h>

namespace dilatant::drivers::strain_schedule_test {
namespace {

// A row or snapshot keeps its grid: one interval on after each.
TEST(StrainSchedule, AdvanceKeepsTheGrid) {
  StrainSchedule s{.interval = 0.25, .next = 0.25};
  EXPECT_FALSE(s.due(0.2));
  EXPECT_TRUE(s.due(0.26));
  s.advance();
  EXPECT_EQ(s.next, 0.5);
}

// A checkpoint written early (a stop request at strain 1.3) moves to the
// first grid point past it, not into a burst of due ones.
TEST(StrainSchedule, AdvancePastSkipsToTheFirstPointBeyond) {
  StrainSchedule s{.interval = 0.5, .next = 0.5};
  s.advance_past(1.3);
  EXPECT_EQ(s.next, 1.5);
  s.advance_past(1.5);  // on a grid point: the next one
  EXPECT_EQ(s.next, 2.0);
}

// Interval 0 (run.snapshot_interval = 0) never comes due, nor loops.
TEST(StrainSchedule, ZeroIntervalIsNever) {
  StrainSchedule s{.interval = 0.0, .next = 0.0};
  EXPECT_FALSE(s.due(10.0));
  s.advance_past(10.0);
  EXPECT_EQ(s.next, 0.0);
}

}  // namespace
}  // namespace dilatant::drivers::strain_schedule_test
