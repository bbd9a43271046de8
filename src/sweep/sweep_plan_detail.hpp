#pragma once
// Internals of the sweep reader, shared by sweep_plan*.cpp; not part of the API.
#include <string>
#include <string_view>
#include <vector>

#include "sweep/sweep_plan.hpp"

namespace dilatant::sweep::detail {

std::string join(const std::vector<std::string>& parts, std::string_view separator);

// Each point's values, label, folder and config.source. Only once all points
// are expanded: the folder numbers are as wide as the largest index.
void name_points(SweepPlan& plan);

// Continuation: chains of points equal in all swept keys but lambda, by lambda.
// Throws InputError when lambda is not swept or a continued point's strains
// leave no measured part.
void link_continuations(SweepPlan& plan);

// Refinement (sweep.refines): each point's start in the refined sweep's ramps
// and its continued strains (sweep_refinement.cpp). Throws InputError when
// the refined folder is no ramp sweep, a point matches none of its ramps, or
// has no lower lambda in its ramp to start from.
void link_refinement(SweepPlan& plan);

// A continued point's run.strain and run.transient_strain from the [sweep]
// settings (its cold configuration kept as cold_start, for a jam's confirmation).
void continue_point(const SweepPlan& plan, SweepPoint& p);

// InputError when sweep.extend_unsteady_to lies below a point's run.strain.
void check_extension_cap(const SweepPlan& plan);

}  // namespace dilatant::sweep::detail
