#pragma once
// Whether a run folder's config.toml is the run of a given configuration: the
// test that keeps a resume (`dilatant run --resume`, a sweep's point) from
// continuing a state under other settings. Comment lines are ignored (they
// name the file the configuration was read from).
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "io/config.hpp"

namespace dilatant {

// The value of dotted `key` ("friction.mu0") in a resolved configuration.
const toml::node* find_dotted_key(const toml::table& resolved, std::string_view key);

// nullopt when `file_text` (a config.toml as written by a run) is `config`'s
// resolved configuration, keys in `ignored` ("run.strain") aside, and keys the
// file lacks (a run of an older version) that `config` holds at their
// defaults; else the
// first difference, "friction.mu0 = 0.1 there, 0.3 here" with `here` naming
// the configuration (or why the text cannot be compared).
std::optional<std::string> config_difference(const std::string& file_text, const Config& config,
                                             std::string_view here = "here",
                                             std::span<const std::string_view> ignored = {});

// The configuration a run in `folder` ran with (its config.toml; nullopt if
// there is none), when it is `config`'s but for the keys in `extensible`;
// else InputError naming the file and the first difference, and telling how
// to resume: "resume it with the same configuration and --set options
// (`may_change`), or choose another --out".
std::optional<toml::table> resumable_run_config(const std::filesystem::path& folder,
                                                const Config& config,
                                                std::span<const std::string_view> extensible,
                                                std::string_view may_change);

}  // namespace dilatant
