#pragma once
// A sweep point that is not steady, run on (sweep.extend_unsteady_to; docs/sweeps.md
// "Points that are not steady").
//
// A point's averaging window is its last W = run.strain - run.transient_strain
// of strain. When the steadiness test (measure/steadiness.hpp) finds the wall
// speed still drifting there, the transient was longer than the run allowed
// for. The sweep then resumes the point's run for one more window: extension k
// runs to
//
//     run.strain_k = run.strain + k W,   run.transient_strain_k = run.strain + (k - 1) W,
//
// so every strain run before is transient and the new window, of the planned
// length, follows it without overlap (the profile and histogram start anew
// there: drivers/shear_cell_run.cpp). Each extension tests a fresh window, not
// one that still holds the drift; it stops when the point is steady, or when
// one more window would run past the cap (the point then stays invalid, "not
// steady"). A ramp's next point starts from the extended run's final state,
// so a point is extended only before its successor has started.
//
// The extended configuration is the point's run folder's config.toml: a sweep
// resumed later recognises it by k (point_folder.cpp) and refuses any other
// change.
#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "io/config.hpp"

namespace dilatant::sweep {

// The planned configuration extended k times (k = 0: itself).
Config extended_config(const Config& planned, int k);

// How many times the run whose config.toml is `config_text` extended the
// planned configuration: k >= 1 when its run.strain and run.transient_strain
// are those of extension k, up to `cap`; else 0 (the planned configuration,
// or another one, which the caller's comparison then reports).
int extensions_in(const std::string& config_text, const Config& planned, double cap);

// Whether a finished point whose run had configuration `current` and wrote
// `summary` runs on: it is not steady (the test ran and failed; a jammed run
// or a window too short to test is not extended) and one more window ends at
// or below `cap`.
bool needs_extension(const nlohmann::json& summary, const Config& current, double cap);

// The line a sweep prints when it extends a point.
std::string extension_note(const std::string& folder, const nlohmann::json& summary,
                           const Config& next, double cap);

// A finished point's run in `folder`, planned as `planned`, extended
// `extensions` times so far and ending with `summary`, run on while it needs
// it: summary.json is removed first (a run stopped during an extension is
// resumable, not done), then the run is resumed under the next extended
// configuration. `extensions` and `summary` follow each extension; `note`
// receives the line of each. Returns false when `halt` stopped an extension
// (its checkpoint written); halted before one starts, the point is left done
// as it stands (a later sweep runs it on). Throws what the run throws.
struct ExtensionRun {
  std::filesystem::path folder;
  std::string name;  // the point's folder as the sweep names it (points/NNN-label)
  const Config& planned;
  double cap = 0.0;
  const std::atomic<bool>* halt = nullptr;
  std::atomic<double>* progress = nullptr;
  std::function<void(std::string)> note;
};
bool run_on_while_unsteady(const ExtensionRun& run, int& extensions, nlohmann::json& summary);

}  // namespace dilatant::sweep
