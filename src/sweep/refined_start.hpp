#pragma once
// Where a refinement's point starts, when it is to run (sweep.refines,
// sweep_plan.hpp "Refinement"): the refined ramp's final state at the nearest
// lower lambda, read from that sweep's folders, which may still be running.
#include <filesystem>
#include <string>

#include "sweep/sweep_plan.hpp"

namespace dilatant::sweep {

struct RefinedStart {
  // Run from `checkpoint`; Wait: the ramp's point has not finished (the point
  // stays pending); Skip: the ramp jammed at or below it (stop_at_jam); Fail:
  // the ramp's point failed or its summary cannot be read.
  enum class Verdict { Run, Wait, Skip, Fail };
  Verdict verdict = Verdict::Run;
  std::string why;  // for Wait, Skip and Fail: one line
  std::filesystem::path checkpoint;
};

// Reads the ramp's points below the refinement's point, in order of lambda.
RefinedStart refined_start(const RampStart& start, bool stop_at_jam);

}  // namespace dilatant::sweep
