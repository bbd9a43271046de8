#pragma once
// The configuration of a jam's cold start (sweep.confirm_jams): the jammed
// point's own configuration run from a new packing, at the nominal phi that
// sweep.cold_start_phi chooses (docs/sweeps.md "Ramps to the jam"):
//
//   nominal  the ramp's phi;
//   matched  the ramp's phi shifted by its change of the time-averaged bulk
//            fraction before the jam (cold_start_choice.cpp);
//   bulk     the phi whose new packing begins at the bulk fraction the jammed
//            point began from (the final state of the point before it),
//            within kBulkTolerance: the confirmation then asks whether the
//            same stress jams a packing of the same fraction without the
//            ramp's history. How it was chosen is kept beside the cold start
//            (cold-start/phi_choice.json) and is read back, not redone, when a
//            sweep resumes.
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "sweep/flow_table.hpp"
#include "sweep/sweep_plan.hpp"

namespace dilatant::sweep {

// A third of the 0.003 within which a cold start must match the ramp's bulk
// (issue 34), so that the packings' own scatter of 0.001 leaves room.
inline constexpr double kBulkTolerance = 0.001;
inline constexpr int kBulkMaxPackings = 12;
inline constexpr const char* kPhiChoiceFile = "phi_choice.json";

struct ColdStartChoice {
  Config config;
  nlohmann::json record;  // "bulk": what phi_choice.json holds; else null
  bool fresh = false;     // "bulk": chosen now (to be written), not read back
  bool unchosen = false;  // "bulk" without a choice on disk and search not allowed
};

// The cold start of continued point `jammed`, whose folder is under `out`;
// `records` are the sweep's (the matched rule reads the ramp's summaries).
// Under "bulk" reads `out/<folder>/cold-start/phi_choice.json` when present,
// else, if `search`, builds packings (seconds each, no shearing; the
// checkpoint of the point before the jam gives the target), else returns
// `unchosen`. Throws std::runtime_error when no packing can be built; `stop`
// (the sweep's halt flag) ends the search early, and the caller, which checks
// it, then runs nothing.
ColdStartChoice choose_cold_start(const SweepPlan& plan, std::size_t jammed,
                                  const std::vector<PointRecord>& records,
                                  const std::filesystem::path& out, bool search,
                                  const std::atomic<bool>* stop = nullptr);

}  // namespace dilatant::sweep
