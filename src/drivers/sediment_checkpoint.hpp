#pragma once
// A sediment's checkpoint, OUT/checkpoint.bin of `dilatant jam`
// (drivers/sediment_run.hpp): the samples finished so far, each as measured,
// so that a resumed run goes on with the next sample and averages the same
// numbers an uninterrupted run would. A sample stopped half-way is run again
// from its start (a sample of the built-in sediment takes minutes; its state
// is not kept). The file ends with the CRC-32 of every byte before it, as a
// shear cell's does (io/checksum.hpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "measure/sediment_fraction.hpp"

namespace dilatant {

// One packing: how it settled and its fraction.
struct SedimentSample {
  std::int64_t seed = 0;
  std::uint64_t spheres = 0;
  bool settled = false;
  double time = 0.0;
  long steps = 0, unconverged = 0;
  double max_overlap = 0.0;
  SedimentFraction fraction;
  std::vector<double> phi_at;  // at the reported exclusions (sediment_run.cpp)
};

// Written atomically (io/atomic_file.hpp).
void save_sediment_checkpoint(const std::filesystem::path& file,
                              const std::vector<SedimentSample>& samples);
std::string sediment_checkpoint_bytes(const std::vector<SedimentSample>& samples);
// Throw InputError naming `file` for a missing, damaged or foreign file.
std::vector<SedimentSample> load_sediment_checkpoint(const std::filesystem::path& file);
std::vector<SedimentSample> read_sediment_checkpoint(std::string bytes,
                                                     const std::filesystem::path& file);

}  // namespace dilatant
