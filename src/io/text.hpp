// Text helpers shared by the readers of user input (configs, overrides, CSV
// files, rheometer exports, sweep plans, manifests).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace dilatant {

// The view without its leading and trailing blanks: spaces, tabs, and the CR
// and LF that files written on another system leave at a line's end.
inline std::string_view trim(std::string_view s) {
  constexpr std::string_view blanks = " \t\r\n";
  const auto first = s.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(blanks) - first + 1);
}

// The candidate a mistyped word most likely meant: the closest by edit
// distance (Levenshtein: insertions, deletions, substitutions; a swap of two
// neighbours counts 1, as in Damerau's typing errors), if within a third of
// the word's length (at least 1, at most 3); empty when none is that close.
// For "did you mean" in messages: `rnu` -> `run`, `frcition` -> `friction`.
std::string_view closest_word(std::string_view word, std::span<const std::string_view> candidates);
// " (did you mean 'X'?)" for closest_word(), or "" when there is none.
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

// The whole of a file the user named, byte for byte. A file that is missing,
// a folder or unreadable is bad input (InputError, exit 2), in one line:
//     <file>: cannot read the <what> (no such file | not a readable file)
std::string read_input_file(const std::filesystem::path& file, std::string_view what);

}  // namespace dilatant
