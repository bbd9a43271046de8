#include "sweep/refined_start.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "sweep/point_folder.hpp"

namespace dilatant::sweep {

// In order of lambda, so that a jam below the starting point is met before an
// unfinished point above it, which its ramp never runs (stop_at_jam) and would
// leave this one waiting for ever.
RefinedStart refined_start(const RampStart& start, bool stop_at_jam) {
  using Verdict = RefinedStart::Verdict;
  std::filesystem::path jam;  // a jammed point of the ramp below the start
  for (const auto& folder : start.ramp) {
    if (std::filesystem::is_regular_file(folder / "error.txt"))
      return {Verdict::Fail,
              fmt::format("not run: the refined ramp's point {} failed", folder.string()),
              {}};
    if (!std::filesystem::is_regular_file(folder / "summary.json")) {
      if (!jam.empty())
        return {Verdict::Skip,
                fmt::format("not run: the refined ramp stopped at its jam at {}", jam.string()),
                {}};
      return {Verdict::Wait,
              fmt::format("waits for {}, which has not finished: run this sweep again when it has",
                          folder.string()),
              {}};
    }
    nlohmann::json summary;
    try {
      summary = read_point_summary(folder / "summary.json");
    } catch (const std::exception& e) {
      return {Verdict::Fail,
              fmt::format("not run: the refined ramp's point {}: {}", folder.string(), e.what()),
              {}};
    }
    const auto jammed = summary.find("jammed");
    if (jammed != summary.end() && jammed->is_boolean() && jammed->get<bool>()) {
      if (stop_at_jam)
        return {Verdict::Skip,
                fmt::format("not run: the refined ramp jammed at {}", folder.string()),
                {}};
      if (jam.empty()) jam = folder;  // runs from the jammed state (stop_at_jam = false)
    }
  }
  return {Verdict::Run, "", start.ramp.back() / "checkpoint.bin"};
}

}  // namespace dilatant::sweep
