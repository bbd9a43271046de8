// libFuzzer entry point for fuzz::particles_csv (fuzz/fuzz_targets.hpp; scripts/fuzz.sh).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dilatant::fuzz::particles_csv(data, size);
  return 0;
}
