#include "sweep/refined_start.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "io/text.hpp"

namespace dilatant::sweep {

// In order of lambda, so that a jam below the starting point skips the point
// before an unfinished point above the jam (never run: stop_at_jam) could make
// it wait for ever.
RefinedStart refined_start(const RampStart& start, bool stop_at_jam) {
  using Verdict = RefinedStart::Verdict;
  for (const auto& folder : start.ramp) {
    if (std::filesystem::is_regular_file(folder / "error.txt"))
      return {Verdict::Fail,
              fmt::format("not run: the refined ramp's point {} failed", folder.string()),
              {}};
    if (!std::filesystem::is_regular_file(folder / "summary.json"))
      return {Verdict::Wait,
              fmt::format("waits for {}, which has not finished: run this sweep again when it has",
                          folder.string()),
              {}};
    nlohmann::json summary;
    try {
      summary = nlohmann::json::parse(read_input_file(folder / "summary.json", "point's summary"));
    } catch (const std::exception& e) {
      return {Verdict::Fail,
              fmt::format("not run: the refined ramp's point {}: {}", folder.string(), e.what()),
              {}};
    }
    const auto jammed = summary.find("jammed");
    if (stop_at_jam && jammed != summary.end() && jammed->is_boolean() && jammed->get<bool>())
      return {Verdict::Skip,
              fmt::format("not run: the refined ramp jammed at {}", folder.string()),
              {}};
  }
  return {Verdict::Run, "", start.ramp.back() / "checkpoint.bin"};
}

}  // namespace dilatant::sweep
