#pragma once
// The run folder of one point of a sweep, DIR/points/NNN-label/, as a previous
// invocation left it: this is what makes re-running a sweep resume it.
//
//   Done       config.toml equals the point's configuration and summary.json
//              exists: the point is finished and is skipped;
//   Resumable  config.toml equals it and checkpoint.bin exists: the run was
//              interrupted and continues from the checkpoint (`run --resume`);
//   Fresh      nothing usable (no folder, or no config.toml): the point runs
//              from the start.
//
// A config.toml that differs from the point's configuration means the sweep
// file changed under an existing output folder: that is refused (InputError,
// exit code 2) rather than mixing runs of two sweeps in one table. Comments
// are ignored in the comparison (they name the file the sweep was read from).
// Under sweep.extend_unsteady_to, a folder whose run extended the point
// (sweep/unsteady_extension.hpp) is the point's too, with its count.
#include <cstddef>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sweep/sweep_plan.hpp"

namespace dilatant::sweep {

enum class PointState { Fresh, Resumable, Done };

PointState inspect_point_folder(const SweepPoint& point, const std::filesystem::path& folder);

struct PointFolder {
  PointState state = PointState::Fresh;
  int extensions = 0;  // of the planned run: config.toml is extended_config(planned, extensions)
};
// The same, for a sweep with sweep.extend_unsteady_to = `cap` (none: as above).
PointFolder inspect_point_folder(const SweepPoint& point, const std::filesystem::path& folder,
                                 std::optional<double> cap);

// A finished point's summary.json (`file`); throws InputError when it cannot
// be read and nlohmann::json::parse_error when it is corrupt.
nlohmann::json read_point_summary(const std::filesystem::path& file);

// The versions other than this binary's that ran the finished points of
// `plan` in `out`, each with its count ("unknown" for a summary without one):
// a sweep resumed by another version would mix two versions' results in one
// table. A summary that cannot be read is left to the sweep to report.
std::map<std::string, std::size_t> other_versions_of_done_points(const SweepPlan& plan,
                                                                 const std::filesystem::path& out);

// InputError when a refinement's output folder `out` is the folder it refines:
// its sweep.toml and table would overwrite the ramp's.
void refuse_refining_into_itself(const SweepPlan& plan, const std::filesystem::path& out);

}  // namespace dilatant::sweep
