#include "sweep/point_folder.hpp"

#include <fmt/format.h>

#include <limits>

#include "dilatant/version.hpp"
#include "io/config_compare.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"
#include "sweep/unsteady_extension.hpp"

namespace dilatant::sweep {

PointState inspect_point_folder(const SweepPoint& point, const std::filesystem::path& folder) {
  return inspect_point_folder(point, folder, std::nullopt).state;
}

PointFolder inspect_point_folder(const SweepPoint& point, const std::filesystem::path& folder,
                                 std::optional<double> cap) {
  const auto config = folder / "config.toml";
  if (!std::filesystem::is_regular_file(config)) return {};
  const std::string text = read_input_file(config, "run's configuration");
  PointFolder found;
  if (cap) found.extensions = extensions_in(text, point.config, *cap);
  const auto difference =
      config_difference(text, extended_config(point.config, found.extensions), "in this sweep");
  // A point run on by a sweep that set sweep.extend_unsteady_to, read by one
  // that does not (or sets it lower): say so, rather than "another configuration".
  if (const int k = extensions_in(text, point.config, std::numeric_limits<double>::infinity());
      difference && k > 0) {
    const double strain = extended_config(point.config, k).run.strain;
    throw InputError(fmt::format(
        "{}: holds this point run on to strain {} because it was not steady "
        "(sweep.extend_unsteady_to), which this sweep {}: set sweep.extend_unsteady_to to at "
        "least {} to take it up, or delete that folder to run the point anew",
        folder.string(), strain, cap ? fmt::format("caps at {}", *cap) : "does not set", strain));
  }
  if (difference)
    throw InputError(fmt::format(
        "{}: holds a run of another configuration ({}): the sweep changed since it ran; use "
        "another --out, or delete that folder to run the point anew",
        folder.string(), *difference));
  if (std::filesystem::is_regular_file(folder / "summary.json"))
    found.state = PointState::Done;
  else if (std::filesystem::is_regular_file(folder / "checkpoint.bin"))
    found.state = PointState::Resumable;
  return found;
}

nlohmann::json read_point_summary(const std::filesystem::path& file) {
  return nlohmann::json::parse(read_input_file(file, "point's summary"));  // throws if corrupt
}

std::map<std::string, std::size_t> other_versions_of_done_points(const SweepPlan& plan,
                                                                 const std::filesystem::path& out) {
  std::map<std::string, std::size_t> versions;
  for (const SweepPoint& point : plan.points) {
    const auto folder = out / point.folder;
    if (inspect_point_folder(point, folder, plan.settings.extend_unsteady_to).state !=
        PointState::Done)
      continue;
    try {
      const nlohmann::json summary = read_point_summary(folder / "summary.json");
      const std::string version = summary.value("version", std::string("unknown"));
      if (version != kVersion) ++versions[version];
    } catch (const std::exception&) {
      // Unreadable: the sweep's own reading of the summary says so.
    }
  }
  return versions;
}

void refuse_refining_into_itself(const SweepPlan& plan, const std::filesystem::path& out) {
  std::error_code ec;  // a folder that does not exist yet is not the refined one
  if (!plan.settings.refines.empty() && std::filesystem::equivalent(out, plan.settings.refines, ec))
    throw InputError(fmt::format(
        "{}: --out {} is the folder this sweep refines (sweep.refines); give the refinement a "
        "folder of its own",
        plan.source, out.string()));
}

}  // namespace dilatant::sweep
