#include "fuzz_targets.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "analysis/bulk_flow_table.hpp"
#include "analysis/jamming_table.hpp"
#include "analysis/prediction_report.hpp"
#include "analysis/rheometer_file.hpp"
#include "analysis/wyart_cates_prediction.hpp"
#include "drivers/scene_checkpoint.hpp"
#include "drivers/sediment_checkpoint.hpp"
#include "drivers/shear_cell_state.hpp"
#include "io/config.hpp"
#include "io/input_error.hpp"
#include "io/particles_csv.hpp"

namespace dilatant::fuzz {

namespace {

std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The file readers take a path: the bytes go to a file of this process's own
// (libFuzzer runs one input at a time per process), removed afterwards.
struct InputFile {
  std::filesystem::path path;
  InputFile(const std::uint8_t* data, std::size_t size, const char* name)
      : path(std::filesystem::temp_directory_path() /
             ("dilatant-fuzz-" + std::to_string(::getpid()) + "-" + name)) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::logic_error("fuzz harness: cannot write " + path.string());
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

}  // namespace

void config(const std::uint8_t* data, std::size_t size) {
  try {
    (void)parse_config(text_of(data, size), "fuzz.toml", std::filesystem::path("."), {});
  } catch (const InputError&) {
  }
}

void particles_csv(const std::uint8_t* data, std::size_t size) {
  const InputFile file(data, size, "particles.csv");
  try {
    (void)read_particles_csv(file.path);
  } catch (const InputError&) {
  }
}

namespace {

// One checkpoint reader on the bytes: accepted, or refused with a
// runtime_error that names the file or is one of the archive's own messages
// ("checkpoint is truncated", ...; the load_* functions put the file's name in
// front of those).
template <typename Read>
void read_or_refuse(Read read, std::string bytes, const std::string& name) {
  try {
    (void)read(std::move(bytes), name);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.rfind(name, 0) != 0 && what.rfind("checkpoint is", 0) != 0) throw;
  }
}

}  // namespace

void checkpoint(const std::uint8_t* data, std::size_t size) {
  const std::string name = "fuzz-checkpoint.bin";
  // The mutated bytes with their checksum made to match again: otherwise
  // nearly every input would stop at the checksum, before the reader's checks.
  // (All three formats end in the same CRC-32 trailer, io/checksum.hpp.)
  std::string bytes(text_of(data, size));
  seal_checkpoint(bytes);
  // The same bytes to each kind of checkpoint: a shear cell's, a scene's and a
  // sediment's; each refuses the others' by their magic, and the seeds of
  // each (fuzz/corpus/checkpoint/) carry the mutations into its own.
  read_or_refuse(
      [](std::string b, const std::string& n) { return read_checkpoint(std::move(b), n); }, bytes,
      name);
  read_or_refuse(
      [](std::string b, const std::string& n) { return read_scene_checkpoint(std::move(b), n); },
      bytes, name);
  read_or_refuse(
      [](std::string b, const std::string& n) { return read_sediment_checkpoint(std::move(b), n); },
      bytes, name);
}

void rheometer_file(const std::uint8_t* data, std::size_t size) {
  const InputFile file(data, size, "flow-curve.csv");
  try {
    // Every step found (tables, TRIOS [step] sections, RheoCompass intervals,
    // Malvern's Action Name column), listed as --list does, then the curves
    // chosen without a choice and by the first step's number and name.
    const analysis::RheometerFile read = analysis::read_rheometer_file(file.path);
    (void)analysis::step_listing(read);
    try {
      (void)analysis::choose_flow_curves(read, {});
    } catch (const InputError&) {
    }
    (void)analysis::choose_flow_curves(read, {1, read.steps.front().name, "fuzz"});
  } catch (const InputError&) {
  }
}

namespace {

// Where predict is asked: no friction, the paper's boundary, beyond the last
// measured mu0; a dilute, a dense and a near-random-close-packed fraction.
constexpr double kMu0s[] = {0.0, 0.35, 10.0};
constexpr double kPhis[] = {0.3, 0.58, 0.64};

}  // namespace

void predict_tables(const std::uint8_t* data, std::size_t size) {
  const InputFile file(data, size, "predict-table");
  try {
    const auto table = analysis::JammingTable::read(file.path);
    for (double mu0 : kMu0s)
      for (double phi : kPhis) (void)analysis::predict(table, nullptr, mu0, phi, 5e-5);
  } catch (const InputError&) {
  }
  try {
    const auto bulk = analysis::BulkFlowTable::read(file.path);
    const auto sediment = analysis::JammingTable::builtin();
    for (double mu0 : kMu0s)
      for (double phi : kPhis) {
        const auto report = analysis::predict(sediment, &bulk, mu0, phi, 5e-5);
        (void)analysis::source_detail(report, bulk.name());
      }
  } catch (const InputError&) {
  }
  try {
    for (const auto& sample : analysis::fitted_wyart_cates_samples(file.path)) {
      const auto fit = analysis::read_fitted_wyart_cates(file.path, sample);
      for (double phi : kPhis) {
        (void)analysis::wyart_cates_prediction(fit, phi, std::nullopt);
        (void)analysis::wyart_cates_prediction(fit, phi, 1.0);
      }
    }
  } catch (const InputError&) {
  }
}

Target target_named(std::string_view name) {
  if (name == "config") return &config;
  if (name == "particles_csv") return &particles_csv;
  if (name == "checkpoint") return &checkpoint;
  if (name == "rheometer_file") return &rheometer_file;
  if (name == "predict_tables") return &predict_tables;
  return nullptr;
}

}  // namespace dilatant::fuzz
