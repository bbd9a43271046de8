#pragma once
// The input readers under fuzzing (issue 19, docs/reliability.md "Fuzzing"):
// each takes arbitrary bytes, hands them to one reader of user input, and
// returns normally whether the reader accepts them or refuses them as bad
// input. Anything else (a crash, a sanitizer report, an exception of another
// kind, a hang) is a bug the fuzzer reports.
//
// The same functions serve two front ends: the libFuzzer executables
// (fuzz/*_fuzzer.cpp, clang only: scripts/fuzz.sh) and the corpus replay in
// the ordinary test suite (tests/fuzz/corpus_replay_test.cpp), which feeds
// every committed corpus file and every crasher found so far through them
// with g++ under ASan and UBSan.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace dilatant::fuzz {

// A run or sweep configuration (TOML text): parse_config, i.e. TOML syntax,
// known keys, types and ranges. Refusal: InputError.
void config(const std::uint8_t* data, std::size_t size);
// A scene's particles CSV (io/particles_csv.hpp). Refusal: InputError.
void particles_csv(const std::uint8_t* data, std::size_t size);
// A checkpoint.bin: the same bytes to the shear cell's reader
// (drivers/shear_cell_state.hpp), the scene's (drivers/scene_checkpoint.hpp)
// and the sediment's (drivers/sediment_checkpoint.hpp). Refusal: a
// std::runtime_error whose message names the file.
void checkpoint(const std::uint8_t* data, std::size_t size);
// A rheometer export of one or several steps, or a plain flow-curve table
// (analysis/rheometer_file.hpp).
// Refusal: InputError.
void rheometer_file(const std::uint8_t* data, std::size_t size);

// The tables `dilatant predict` reads from a user's files: the sediment's
// phi_max_BL table (--table), the bulk flow states (--bulk-table) and a
// Wyart–Cates fit (--model, every sample in it): the same bytes to each, and
// whatever is accepted is asked for an answer at a few (mu0, phi) and stresses.
// Refusal: InputError.
void predict_tables(const std::uint8_t* data, std::size_t size);

// By name, for the replay test: "config", "particles_csv", "checkpoint",
// "rheometer_file", "predict_tables"; null for another name.
using Target = void (*)(const std::uint8_t*, std::size_t);
Target target_named(std::string_view name);

}  // namespace dilatant::fuzz
