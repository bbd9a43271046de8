#include "drivers/sediment_checkpoint.hpp"

#include <cstring>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/binary_archive.hpp"
#include "io/checksum.hpp"

namespace dilatant {

namespace {

// "DILSEDM1"
constexpr std::uint64_t kSedimentMagic = 0x314d4445534c4944ULL;
// Each sample holds at least its fixed fields.
constexpr std::size_t kSedimentSampleBytes = 8 * 10 + 1;

template <class Archive, class Sample>
void visit_sample(Archive& a, Sample& s) {
  a.value(s.seed);
  a.value(s.spheres);
  a.value(s.settled);
  a.value(s.time);
  a.value(s.steps);
  a.value(s.unconverged);
  a.value(s.max_overlap);
  a.value(s.fraction.surface);
  a.value(s.fraction.phi);
  a.value(s.fraction.top);
  a.vector(s.phi_at);
}

}  // namespace

std::string sediment_checkpoint_bytes(const std::vector<SedimentSample>& samples) {
  BinaryWriter w;
  w.value(kSedimentMagic);
  w.value(static_cast<std::uint64_t>(samples.size()));
  for (const SedimentSample& s : samples) visit_sample(w, s);
  std::string bytes = w.release();
  append_crc_trailer(bytes);
  return bytes;
}

void save_sediment_checkpoint(const std::filesystem::path& file,
                              const std::vector<SedimentSample>& samples) {
  write_file_atomically(file, sediment_checkpoint_bytes(samples));
}

std::vector<SedimentSample> load_sediment_checkpoint(const std::filesystem::path& file) {
  return parse_checkpoint_file(
      file, [&](std::string bytes) { return read_sediment_checkpoint(std::move(bytes), file); });
}

std::vector<SedimentSample> read_sediment_checkpoint(std::string bytes,
                                                     const std::filesystem::path& file) {
  std::uint64_t magic = 0;
  if (bytes.size() < sizeof(magic)) throw std::runtime_error("checkpoint is truncated");
  std::memcpy(&magic, bytes.data(), sizeof(magic));
  if (magic != kSedimentMagic)
    throw std::runtime_error(file.string() + ": not a sediment's checkpoint (dilatant jam)");
  check_crc_trailer(bytes, sizeof(magic), file);
  BinaryReader r(std::move(bytes));
  r.end_before(kCrcTrailerBytes);
  r.value(magic);
  std::uint64_t n = 0;
  r.count(n, kSedimentSampleBytes);
  std::vector<SedimentSample> samples(n);
  for (SedimentSample& s : samples) visit_sample(r, s);
  if (!r.at_end()) throw std::runtime_error(file.string() + ": checkpoint has trailing data");
  return samples;
}

}  // namespace dilatant
